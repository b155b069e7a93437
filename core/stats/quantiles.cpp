#include "core/stats/quantiles.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>

#include "core/stats/interval.h"

namespace lmc {
namespace {

// Checked here so Boost's domain errors (which throw) are never reached.
bool valid_p(double p) {
  return std::isfinite(p) && p > 0.0 && p < 1.0;
}
bool valid_df(double df) {
  return std::isfinite(df) && df > 0.0;
}

}  // namespace

double normal_quantile(double p) {
  if (!valid_p(p)) return kNaN;
  return boost::math::quantile(boost::math::normal_distribution<double>(0.0, 1.0), p);
}

double t_quantile(double p, double df) {
  if (!valid_p(p) || !valid_df(df)) return kNaN;
  return boost::math::quantile(boost::math::students_t_distribution<double>(df), p);
}

double f_quantile(double p, double df1, double df2) {
  if (!valid_p(p) || !valid_df(df1) || !valid_df(df2)) return kNaN;
  return boost::math::quantile(boost::math::fisher_f_distribution<double>(df1, df2), p);
}

double chi_squared_quantile(double p, double df) {
  if (!valid_p(p) || !valid_df(df)) return kNaN;
  return boost::math::quantile(boost::math::chi_squared_distribution<double>(df), p);
}

double f_upper_tail(double f, double df1, double df2) {
  if (std::isnan(f) || !valid_df(df1) || !valid_df(df2)) return kNaN;
  if (f <= 0.0) return 1.0;
  if (std::isinf(f)) return 0.0;
  return boost::math::cdf(boost::math::complement(boost::math::fisher_f_distribution<double>(df1, df2), f));
}

}  // namespace lmc
