#include "core/metric/robust_terms_report.h"

#include <cstdio>

namespace lmc {

std::string format_robust_terms(const RobustTerms& t, const RobustWeights& w) {
  std::string out = "robust metric R = " + std::to_string(t.total) + " (lower is better):\n";
  char line[160];
  auto row = [&](const char* name, double value, double weight, const char* meaning) {
    std::snprintf(line, sizeof line, "  %-14s %9.6f  x %5.3f  %s\n", name, value, weight, meaning);
    out += line;
  };
  row("M", t.metric_m, 1.0, "the study's metric");
  row("redundancy", t.redundancy, w.redundancy, "share of frames with a finger seen by fewer than 2 controllers");
  row("participation", t.participation, w.participation, "controllers' shortfall below seeing a finger in 20 % of frames");
  row("axis cut", t.axis_cut, w.axis_cut, "share of seeing controller-frames with a seen marker beyond 250 mm");
  row("centring", t.centring, w.centring, "mean off-centre of the palm in the seeing pyramids (0 axis, 1 edge)");
  row("footprint", t.footprint, w.footprint, "share of controller pairs whose footprints overlap");
  return out;
}

std::string format_robust_terms_split(const std::vector<std::string>& names, const std::vector<RobustTerms>& splits,
                                      const RobustWeights& w) {
  std::string out = "robust metric terms (lower is better):\n";
  char cell[64];
  std::snprintf(cell, sizeof cell, "  %-14s %7s", "term", "weight");
  out += cell;
  for (const auto& n : names) {
    std::snprintf(cell, sizeof cell, " %11s", n.c_str());
    out += cell;
  }
  out += "\n";
  struct Row {
    const char* name;
    double weight;
    double RobustTerms::*field;
  };
  const Row rows[] = {{"M", 1.0, &RobustTerms::metric_m},
                      {"redundancy", w.redundancy, &RobustTerms::redundancy},
                      {"participation", w.participation, &RobustTerms::participation},
                      {"axis cut", w.axis_cut, &RobustTerms::axis_cut},
                      {"centring", w.centring, &RobustTerms::centring},
                      {"footprint", w.footprint, &RobustTerms::footprint},
                      {"R", 0.0, &RobustTerms::total}};
  for (const Row& r : rows) {
    if (r.field == &RobustTerms::total) {
      std::snprintf(cell, sizeof cell, "  %-14s %7s", r.name, "");
    } else {
      std::snprintf(cell, sizeof cell, "  %-14s %7.3f", r.name, r.weight);
    }
    out += cell;
    for (const auto& t : splits) {
      std::snprintf(cell, sizeof cell, " %11.6f", t.*(r.field));
      out += cell;
    }
    out += "\n";
  }
  return out;
}

nlohmann::json robust_terms_to_json(const RobustTerms& t, const RobustWeights& w) {
  return {{"M", t.metric_m},
          {"redundancy", t.redundancy},
          {"participation", t.participation},
          {"axis_cut", t.axis_cut},
          {"centring", t.centring},
          {"footprint", t.footprint},
          {"R", t.total},
          {"weights",
           {{"redundancy", w.redundancy},
            {"participation", w.participation},
            {"axis_cut", w.axis_cut},
            {"centring", w.centring},
            {"footprint", w.footprint}}}};
}

}  // namespace lmc
