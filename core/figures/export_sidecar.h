#pragma once
// An exported figure is three files side by side: base.svg (the picture), base.csv (the exact
// data behind it, figure_csv.h) and base.json, this sidecar, saying where the data came from and
// how it was computed, so a figure found in a folder months later can be traced and redrawn.
//   {"format": "lmc-figure-export", "format_version": 1, "title", "files": {"svg", "csv"},
//    "csv_columns", "inputs": [...], "method", "parameters": {...}, "figure": {axes, series,
//    reference lines, notes}, "software_version", "created_utc"}
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/figures/figure.h"
#include "core/figures/heatmap.h"

namespace lmc {

inline constexpr const char* kFigureExportFormat = "lmc-figure-export";

// Where the data came from and how it was turned into the figure: `inputs` are files or session
// names, `method` names the computation ("bland-altman", "time series"), `parameters` its settings.
struct FigureProvenance {
  std::vector<std::string> inputs;
  std::string method;
  nlohmann::json parameters = nlohmann::json::object();
};

nlohmann::json figure_sidecar(const Figure& figure, const std::string& base_name, const FigureProvenance& how);
nlohmann::json figure_sidecar(const FigureGrid& grid, const std::string& base_name, const FigureProvenance& how);
// A heatmap's "figure" holds its rows, columns (and groups), panel titles, what the colour means
// and the scale ("viridis" over [0, 1]), and its notes.
nlohmann::json figure_sidecar(const Heatmap& heatmap, const std::string& base_name, const FigureProvenance& how);

struct WrittenFigure {
  std::filesystem::path svg, csv, json;
};

// Writes dir/base.svg, dir/base.csv and then dir/base.json, each atomically
// (core/io/atomic_write.h), the sidecar last so its presence means the set is complete. Throws
// lmc::Error naming the problem when base_name is not a safe file name (core/common/safe_name.h:
// "../x" is refused), when dir is not an existing folder, or when a write fails.
WrittenFigure write_figure_files(const std::filesystem::path& dir, const std::string& base_name, const Figure& figure,
                                 const std::vector<std::string>& inputs, const std::string& method,
                                 const nlohmann::json& parameters, int width_px = 800, int height_px = 500);
WrittenFigure write_figure_files(const std::filesystem::path& dir, const std::string& base_name, const FigureGrid& grid,
                                 const std::vector<std::string>& inputs, const std::string& method,
                                 const nlohmann::json& parameters, int width_px = 800, int height_px = 800);
WrittenFigure write_figure_files(const std::filesystem::path& dir, const std::string& base_name, const Heatmap& heatmap,
                                 const std::vector<std::string>& inputs, const std::string& method,
                                 const nlohmann::json& parameters, int width_px = 800, int height_px = 520);

}  // namespace lmc
