#include "core/figures/figure_csv.h"

#include <algorithm>
#include <cmath>

#include "core/figures/locale_free_number.h"

namespace lmc {
namespace {

double value_at(const std::vector<double>& v, size_t i) {
  return i < v.size() ? v[i] : std::nan("");
}

void rows(std::string& out, const std::string& prefix, const Figure& f) {
  for (const Series& s : f.series) {
    const std::string name = csv_field(s.name);
    const size_t n = std::max(s.x.size(), s.y.size());
    for (size_t i = 0; i < n; ++i)
      out += prefix + name + "," + exact_c(value_at(s.x, i)) + "," + exact_c(value_at(s.y, i)) + "\n";
  }
}

}  // namespace

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string to_csv(const Figure& figure) {
  std::string out = "series,x,y\n";
  rows(out, "", figure);
  return out;
}

std::string to_csv(const FigureGrid& grid) {
  std::string out = "panel,series,x,y\n";
  for (size_t p = 0; p < grid.panels.size(); ++p) rows(out, std::to_string(p + 1) + ",", grid.panels[p]);
  return out;
}

std::string to_csv(const Heatmap& heatmap) {
  std::string out = "panel,row,column_group,column,value\n";
  const bool grouped = heatmap.column_groups.size() == heatmap.columns.size();
  for (size_t p = 0; p < heatmap.panels.size(); ++p)
    for (size_t r = 0; r < heatmap.rows.size(); ++r)
      for (size_t c = 0; c < heatmap.columns.size(); ++c)
        out += std::to_string(p + 1) + "," + csv_field(heatmap.rows[r]) + "," +
               (grouped ? csv_field(heatmap.column_groups[c]) : std::string()) + "," + csv_field(heatmap.columns[c]) +
               "," + exact_c(heatmap.at(p, r, c)) + "\n";
  return out;
}

}  // namespace lmc
