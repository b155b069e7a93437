#include "core/figures/export_sidecar.h"

#include <cmath>

#include "core/common/error.h"
#include "core/common/safe_name.h"
#include "core/common/utc_time.h"
#include "core/figures/colour_scale.h"
#include "core/figures/figure_csv.h"
#include "core/figures/heatmap_svg.h"
#include "core/figures/svg_writer.h"
#include "core/io/atomic_write.h"

namespace lmc {
namespace {

using nlohmann::json;

json axis_json(const Axis& a) {
  json j = {{"label", a.label}, {"unit", a.unit}};
  if (a.range) j["range"] = {a.range->lo, a.range->hi};
  return j;
}

const char* style_name(SeriesStyle s) {
  switch (s) {
    case SeriesStyle::points:
      return "points";
    case SeriesStyle::line_and_points:
      return "line_and_points";
    case SeriesStyle::line:
      break;
  }
  return "line";
}

const char* dash_name(Dash d) {
  switch (d) {
    case Dash::dashed:
      return "dashed";
    case Dash::dotted:
      return "dotted";
    case Dash::solid:
      break;
  }
  return "solid";
}

// What the picture shows beyond the CSV's numbers: axes, series names and colours, reference lines.
json describe(const Figure& f, bool with_x) {
  json j = {{"title", f.title}, {"y_axis", axis_json(f.y)}};
  if (with_x) j["x_axis"] = axis_json(f.x);
  json series = json::array();
  for (size_t i = 0; i < f.series.size(); ++i) {
    const Rgb c = colour_of(f.series[i], i);
    series.push_back({{"name", f.series[i].name},
                      {"style", style_name(f.series[i].style)},
                      {"colour", {c.r, c.g, c.b}},
                      {"samples", std::max(f.series[i].x.size(), f.series[i].y.size())}});
  }
  j["series"] = series;
  json refs = json::array();
  for (const ReferenceLine& r : f.references)
    refs.push_back(
        {{"label", r.label}, {"y", std::isfinite(r.y) ? json(r.y) : json(nullptr)}, {"dash", dash_name(r.dash)}});
  j["reference_lines"] = refs;
  j["notes"] = f.notes;
  return j;
}

json common(const std::string& title, const std::string& base_name, const FigureProvenance& how) {
  return {{"format", kFigureExportFormat},
          {"format_version", 1},
          {"title", title},
          {"files", {{"svg", base_name + ".svg"}, {"csv", base_name + ".csv"}}},
          {"missing_values", "empty CSV cell"},
          {"inputs", how.inputs},
          {"method", how.method},
          {"parameters", how.parameters.is_null() ? json::object() : how.parameters},
          {"software_version", LMC_VERSION},
          {"created_utc", utc_now_iso8601()}};
}

void check_target(const std::filesystem::path& dir, const std::string& base_name) {
  require_safe_name(base_name, "figure file name");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw Error(ErrorLocation{dir.string()}, "the folder to export the figure into does not exist");
}

WrittenFigure write_three(const std::filesystem::path& dir, const std::string& base_name, const std::string& svg,
                          const std::string& csv, const json& sidecar) {
  WrittenFigure w{dir / (base_name + ".svg"), dir / (base_name + ".csv"), dir / (base_name + ".json")};
  write_file_atomically(w.svg, svg);
  write_file_atomically(w.csv, csv);
  write_file_atomically(w.json, sidecar.dump(2) + "\n");
  return w;
}

}  // namespace

json figure_sidecar(const Figure& figure, const std::string& base_name, const FigureProvenance& how) {
  json j = common(figure.title, base_name, how);
  j["csv_columns"] = {"series", "x", "y"};
  j["figure"] = describe(figure, true);
  return j;
}

json figure_sidecar(const FigureGrid& grid, const std::string& base_name, const FigureProvenance& how) {
  json j = common(grid.title, base_name, how);
  j["csv_columns"] = {"panel", "series", "x", "y"};
  json panels = json::array();
  for (const Figure& f : grid.panels) panels.push_back(describe(f, false));
  j["figure"] = {{"x_axis", axis_json(grid.x)}, {"panels", panels}, {"notes", grid.notes}};
  return j;
}

json figure_sidecar(const Heatmap& heatmap, const std::string& base_name, const FigureProvenance& how) {
  json j = common(heatmap.title, base_name, how);
  j["csv_columns"] = {"panel", "row", "column_group", "column", "value"};
  json panels = json::array();
  for (const HeatmapPanel& p : heatmap.panels) panels.push_back({{"title", p.title}});
  j["figure"] = {{"kind", "heatmap"},
                 {"rows", heatmap.rows},
                 {"row_title", heatmap.row_title},
                 {"columns", heatmap.columns},
                 {"column_groups", heatmap.column_groups},
                 {"column_title", heatmap.column_title},
                 {"panels", panels},
                 {"colour_scale",
                  {{"name", std::string(kSequentialScaleName)}, {"range", {0.0, 1.0}}, {"label", heatmap.scale_label}}},
                 {"notes", heatmap.notes}};
  return j;
}

WrittenFigure write_figure_files(const std::filesystem::path& dir, const std::string& base_name, const Figure& figure,
                                 const std::vector<std::string>& inputs, const std::string& method,
                                 const json& parameters, int width_px, int height_px) {
  check_target(dir, base_name);
  const FigureProvenance how{inputs, method, parameters};
  return write_three(dir, base_name, to_svg(figure, width_px, height_px), to_csv(figure),
                     figure_sidecar(figure, base_name, how));
}

WrittenFigure write_figure_files(const std::filesystem::path& dir, const std::string& base_name, const FigureGrid& grid,
                                 const std::vector<std::string>& inputs, const std::string& method,
                                 const json& parameters, int width_px, int height_px) {
  check_target(dir, base_name);
  const FigureProvenance how{inputs, method, parameters};
  return write_three(dir, base_name, to_svg(grid, width_px, height_px), to_csv(grid),
                     figure_sidecar(grid, base_name, how));
}

WrittenFigure write_figure_files(const std::filesystem::path& dir, const std::string& base_name, const Heatmap& heatmap,
                                 const std::vector<std::string>& inputs, const std::string& method,
                                 const json& parameters, int width_px, int height_px) {
  check_target(dir, base_name);
  const FigureProvenance how{inputs, method, parameters};
  return write_three(dir, base_name, to_svg(heatmap, width_px, height_px), to_csv(heatmap),
                     figure_sidecar(heatmap, base_name, how));
}

}  // namespace lmc
