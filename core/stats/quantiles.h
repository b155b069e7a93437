#pragma once
// Quantiles (inverse CDFs) of the distributions the agreement statistics need, taken from
// Boost.Math (header-only) rather than written here: approximations of our own would be the least
// trustworthy part of every confidence interval.
//
// p is the lower-tail probability, e.g. t_quantile(0.975, 9) = 2.262. Each returns NaN (it does
// not throw) when p is outside (0, 1) or a degree of freedom is not a finite number > 0, so a
// degenerate data set yields NaN intervals instead of aborting a whole report.

namespace lmc {

double normal_quantile(double p);                       // standard normal
double t_quantile(double p, double df);                 // Student's t
double f_quantile(double p, double df1, double df2);    // Fisher's F(df1, df2)
double chi_squared_quantile(double p, double df);       // χ²(df)
double f_upper_tail(double f, double df1, double df2);  // P(F(df1, df2) > f), for F-test p values

}  // namespace lmc
