#include "core/stats/icc.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/stats/paired_values.h"
#include "core/stats/quantiles.h"

namespace lmc {
namespace {

std::string average_of(std::size_t k) {
  return "average of " + std::to_string(k) + " measurements";
}

IccEstimate named(const std::string& form, const std::string& model_and_type, const std::string& unit) {
  IccEstimate e;
  e.form = form;
  e.description = form + ": " + model_and_type + ", " + unit;
  return e;
}

// Spearman–Brown: the reliability of the mean of k measurements from that of one.
double spearman_brown(double single, double k) {
  return k * single / (1.0 + (k - 1.0) * single);
}

// Single- and average-measure estimates whose intervals follow from an exact F ratio F0 = BMS/X
// with (df1, df2) degrees of freedom (S&F's ICC(1,·) with X = WMS, ICC(3,·) with X = EMS).
void exact_f_interval(double f0, double df1, double df2, double k, IccEstimate& single, IccEstimate& average) {
  const double fl = f0 / f_quantile(0.975, df1, df2);
  const double fu = f0 * f_quantile(0.975, df2, df1);
  // F0 is +inf when the error mean square is 0 (perfect consistency): the bound's limit is then 1.
  const auto single_bound = [k](double f) { return std::isinf(f) ? 1.0 : (f - 1.0) / (f + k - 1.0); };
  single.ci = {single_bound(fl), single_bound(fu)};
  average.ci = {1.0 - 1.0 / fl, 1.0 - 1.0 / fu};
  for (IccEstimate* e : {&single, &average}) {
    e->f_value = f0;
    e->f_df1 = df1;
    e->f_df2 = df2;
    e->p_value = f_upper_tail(f0, df1, df2);
  }
}

// The rows with a usable value in every column.
std::vector<Eigen::Index> complete_rating_rows(const Eigen::MatrixXd& ratings) {
  std::vector<Eigen::Index> rows;
  for (Eigen::Index i = 0; i < ratings.rows(); ++i) {
    bool complete = true;
    for (Eigen::Index j = 0; j < ratings.cols(); ++j) complete = complete && is_usable(ratings(i, j));
    if (complete) rows.push_back(i);
  }
  return rows;
}

// ICC(2,·): S&F's approximate interval, Satterthwaite's df v built from the single-measure
// estimate (already in r.icc2_1), for n targets and k raters.
void approximate_icc2_interval(double n, double k, double df_rows, double df_cols, double df_error, IccResult& r) {
  const double bms = r.bms, jms = r.jms, ems = r.ems;
  const double rho = r.icc2_1.value;
  // McGraw & Wong's form of Satterthwaite's df (the same v as S&F's): it stays finite when
  // EMS = 0, where v becomes JMS's own df.
  const double a = k * rho / (n * (1.0 - rho));
  const double b = 1.0 + k * rho * (n - 1.0) / (n * (1.0 - rho));
  const double v =
      (a * jms + b * ems) * (a * jms + b * ems) / ((a * jms) * (a * jms) / df_cols + (b * ems) * (b * ems) / df_error);
  const double f_star = f_quantile(0.975, df_rows, v);
  const double f_star2 = f_quantile(0.975, v, df_rows);
  const double low = n * (bms - f_star * ems) / (f_star * (k * jms + (k * n - k - n) * ems) + n * bms);
  const double high = n * (f_star2 * bms - ems) / (k * jms + (k * n - k - n) * ems + n * f_star2 * bms);
  // Perfect agreement (ρ = 1: EMS = JMS = 0) leaves v undefined; the interval's limit is [1, 1].
  r.icc2_1.ci = rho == 1.0 ? Interval{1.0, 1.0} : Interval{low, high};
  r.icc2_k.ci = {spearman_brown(r.icc2_1.ci.low, k), spearman_brown(r.icc2_1.ci.high, k)};
  for (IccEstimate* e : {&r.icc2_1, &r.icc2_k}) {
    e->f_value = bms / ems;
    e->f_df1 = df_rows;
    e->f_df2 = df_error;
    e->p_value = f_upper_tail(e->f_value, df_rows, df_error);
  }
}

}  // namespace

IccResult icc(const Eigen::MatrixXd& ratings) {
  IccResult r;
  r.k = static_cast<std::size_t>(ratings.cols());
  const std::string k_text = std::to_string(r.k);
  r.icc1_1 = named("ICC(1,1)", "one-way random effects, absolute agreement", "single measurement");
  r.icc2_1 = named("ICC(2,1)", "two-way random effects, absolute agreement", "single measurement");
  r.icc3_1 = named("ICC(3,1)", "two-way mixed effects, consistency", "single measurement");
  r.icc1_k = named("ICC(1," + k_text + ")", "one-way random effects, absolute agreement", average_of(r.k));
  r.icc2_k = named("ICC(2," + k_text + ")", "two-way random effects, absolute agreement", average_of(r.k));
  r.icc3_k = named("ICC(3," + k_text + ")", "two-way mixed effects, consistency", average_of(r.k));

  const std::vector<Eigen::Index> rows = complete_rating_rows(ratings);
  r.n_targets = rows.size();
  r.n_dropped = static_cast<std::size_t>(ratings.rows()) - rows.size();
  if (r.k < 2 || rows.size() < 2) {
    r.reason = "needs at least 2 complete rows and 2 columns (" + std::to_string(rows.size()) + " complete rows, " +
               k_text + " columns)";
    return r;
  }

  Eigen::MatrixXd x(static_cast<Eigen::Index>(rows.size()), ratings.cols());
  for (Eigen::Index i = 0; i < x.rows(); ++i) x.row(i) = ratings.row(rows[static_cast<std::size_t>(i)]);
  const auto n = static_cast<double>(x.rows());
  const auto k = static_cast<double>(x.cols());
  const double grand = x.mean();
  const Eigen::VectorXd row_means = x.rowwise().mean();
  const Eigen::RowVectorXd col_means = x.colwise().mean();
  const double ss_total = (x.array() - grand).square().sum();
  const double ss_rows = k * (row_means.array() - grand).square().sum();
  const double ss_cols = n * (col_means.array() - grand).square().sum();
  const double ss_error = ss_total - ss_rows - ss_cols;
  const double ss_within = ss_total - ss_rows;
  const double df_rows = n - 1.0, df_cols = k - 1.0, df_error = (n - 1.0) * (k - 1.0), df_within = n * (k - 1.0);
  r.bms = ss_rows / df_rows;
  r.jms = ss_cols / df_cols;
  r.ems = ss_error / df_error;
  r.wms = ss_within / df_within;
  if (ss_total == 0.0) {
    r.reason = "every value is equal: the ICC is undefined (0/0)";
    return r;
  }
  const double bms = r.bms, wms = r.wms, jms = r.jms, ems = r.ems;

  r.icc1_1.value = (bms - wms) / (bms + (k - 1.0) * wms);
  r.icc2_1.value = (bms - ems) / (bms + (k - 1.0) * ems + k * (jms - ems) / n);
  r.icc3_1.value = (bms - ems) / (bms + (k - 1.0) * ems);
  r.icc1_k.value = (bms - wms) / bms;
  r.icc2_k.value = (bms - ems) / (bms + (jms - ems) / n);
  r.icc3_k.value = (bms - ems) / bms;

  exact_f_interval(bms / wms, df_rows, df_within, k, r.icc1_1, r.icc1_k);
  exact_f_interval(bms / ems, df_rows, df_error, k, r.icc3_1, r.icc3_k);

  approximate_icc2_interval(n, k, df_rows, df_cols, df_error, r);
  return r;
}

void to_json(nlohmann::json& j, const IccEstimate& e) {
  j = nlohmann::json{{"form", e.form},   {"description", e.description},
                     {"value", e.value}, {"ci", e.ci},
                     {"f", e.f_value},   {"f_df1", e.f_df1},
                     {"f_df2", e.f_df2}, {"p", e.p_value}};
}

void to_json(nlohmann::json& j, const IccResult& r) {
  j = nlohmann::json{{"n_targets", r.n_targets},
                     {"n_dropped", r.n_dropped},
                     {"k", r.k},
                     {"mean_squares", {{"bms", r.bms}, {"wms", r.wms}, {"jms", r.jms}, {"ems", r.ems}}},
                     {"estimates", {r.icc1_1, r.icc2_1, r.icc3_1, r.icc1_k, r.icc2_k, r.icc3_k}},
                     {"level", 0.95},
                     {"reason", r.reason}};
}

}  // namespace lmc
