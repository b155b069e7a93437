#include "core/reports/robust_terms_report.h"

#include <cstdio>

namespace lmc {

std::string format_robust_terms(const RobustTerms& t, const RobustWeights& w) {
  std::string out = "robust metric R = " + std::to_string(t.total) + " (lower is better):\n";
  char line[200];
  for (const RobustTermInfo& term : robust_term_infos()) {
    std::snprintf(line, sizeof line, "  %-14s %9.6f  x %5.3f  %s\n", term.name, t.*(term.value),
                  robust_term_weight(w, term), term.meaning);
    out += line;
  }
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
  auto row = [&](const char* name, const std::string& weight, double RobustTerms::*field) {
    std::snprintf(cell, sizeof cell, "  %-14s %7s", name, weight.c_str());
    out += cell;
    for (const auto& t : splits) {
      std::snprintf(cell, sizeof cell, " %11.6f", t.*field);
      out += cell;
    }
    out += "\n";
  };
  for (const RobustTermInfo& term : robust_term_infos()) {
    std::snprintf(cell, sizeof cell, "%.3f", robust_term_weight(w, term));
    row(term.name, cell, term.value);
  }
  row("R", "", &RobustTerms::total);
  return out;
}

nlohmann::json robust_terms_to_json(const RobustTerms& t, const RobustWeights& w) {
  nlohmann::json j = nlohmann::json::object();
  nlohmann::json weights = nlohmann::json::object();
  for (const RobustTermInfo& term : robust_term_infos()) {
    j[term.key] = t.*(term.value);
    if (term.weight != nullptr) weights[term.key] = w.*(term.weight);
  }
  j["R"] = t.total;
  j["weights"] = weights;
  return j;
}

}  // namespace lmc
