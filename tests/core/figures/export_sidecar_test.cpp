#include "core/figures/export_sidecar.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "core/common/error.h"
#include "core/figures/figure_csv.h"
#include "core/figures/heatmap_svg.h"
#include "core/figures/svg_writer.h"
#include "tests/support/reference_data.h"

namespace lmc::export_sidecar_test {

Figure bland_altman_like() {
  Figure f;
  f.title = "Index MCP: LMC vs Vicon";
  f.x = {"mean of methods", "deg", {}};
  f.y = {"difference", "deg", {}};
  f.series.push_back(
      {"trials", {}, SeriesStyle::points, {10, 20, 30}, {1, std::numeric_limits<double>::quiet_NaN(), -1}});
  f.references.push_back({0.0, "bias 0.0", Dash::dashed});
  return f;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(FiguresExport, TheSidecarHasEveryKey) {
  const FigureProvenance how{{"sessions/S01/trial3.lmc"}, "bland-altman", {{"limits", 1.96}}};
  const auto j = figure_sidecar(bland_altman_like(), "ba_index", how);
  for (const char* key : {"format", "format_version", "title", "files", "inputs", "method", "parameters",
                          "software_version", "created_utc", "csv_columns", "figure"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["format"], "lmc-figure-export");
  EXPECT_EQ(j["title"], "Index MCP: LMC vs Vicon");
  EXPECT_EQ(j["files"]["svg"], "ba_index.svg");
  EXPECT_EQ(j["files"]["csv"], "ba_index.csv");
  EXPECT_EQ(j["inputs"], nlohmann::json::array({"sessions/S01/trial3.lmc"}));
  EXPECT_EQ(j["method"], "bland-altman");
  EXPECT_EQ(j["parameters"]["limits"], 1.96);
  EXPECT_EQ(j["software_version"], LMC_VERSION);
  EXPECT_EQ(j["created_utc"].get<std::string>().back(), 'Z');
  EXPECT_EQ(j["figure"]["x_axis"]["unit"], "deg");
  EXPECT_EQ(j["figure"]["series"][0]["colour"], nlohmann::json::array({230, 159, 0}));
  EXPECT_EQ(j["figure"]["reference_lines"][0]["label"], "bias 0.0");
}

TEST(FiguresExport, WritesTheThreeFilesWithTheSameContentAsTheWriters) {
  const auto dir = lmc::test::scratch_dir("figures_export");
  const Figure f = bland_altman_like();
  const auto written = write_figure_files(dir, "ba_index", f, {"a.lmc", "b.trc"}, "bland-altman", {{"k", 2}});
  EXPECT_EQ(written.svg, dir / "ba_index.svg");
  EXPECT_EQ(slurp(written.svg), to_svg(f));
  EXPECT_EQ(slurp(written.csv), to_csv(f));
  const auto j = nlohmann::json::parse(slurp(written.json));
  EXPECT_EQ(j["inputs"].size(), 2u);
  EXPECT_EQ(j["parameters"]["k"], 2);
  // Nothing but the three files (no temporary left behind).
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  EXPECT_EQ(n, 3u);
  std::filesystem::remove_all(dir);
}

TEST(FiguresExport, AGridIsWrittenWithPanelColumns) {
  const auto dir = lmc::test::scratch_dir("figures_export_grid");
  FigureGrid g;
  g.title = "stacked";
  g.x = {"time", "s", {}};
  g.panels = {bland_altman_like(), bland_altman_like()};
  const auto written = write_figure_files(dir, "stack", g, {}, "time series", nullptr);
  EXPECT_EQ(slurp(written.csv).rfind("panel,series,x,y\n", 0), 0u);
  const auto j = nlohmann::json::parse(slurp(written.json));
  EXPECT_EQ(j["figure"]["panels"].size(), 2u);
  EXPECT_TRUE(j["parameters"].is_object());
  std::filesystem::remove_all(dir);
}

TEST(FiguresExport, AnUnsafeBaseNameIsRefusedAndNothingIsWritten) {
  const auto dir = lmc::test::scratch_dir("figures_export_unsafe");
  for (const char* bad : {"../x", "", "a/b", "-x", "x.svg", "a b"}) {
    try {
      write_figure_files(dir, bad, bland_altman_like(), {}, "m", {});
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const lmc::Error& e) {
      EXPECT_NE(std::string(e.what()).find("figure file name"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  EXPECT_FALSE(std::filesystem::exists(dir.parent_path() / "x.svg"));
  std::filesystem::remove_all(dir);
}

TEST(FiguresExport, AMissingFolderIsNamed) {
  const auto dir = lmc::test::scratch_dir("figures_export_missing") / "not_there";
  try {
    write_figure_files(dir, "ok", bland_altman_like(), {}, "m", {});
    ADD_FAILURE() << "wrote into a missing folder";
  } catch (const lmc::Error& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
    EXPECT_EQ(e.where().file, dir.string());
  }
  std::filesystem::remove_all(dir.parent_path());
}

TEST(FiguresExport, AHeatmapIsWrittenWithItsScaleInTheSidecar) {
  const auto dir = lmc::test::scratch_dir("figures_export_heatmap");
  Heatmap h;
  h.title = "Coverage";
  h.rows = {"thumb"};
  h.columns = {"open hand"};
  h.scale_label = "share of frames";
  h.panels = {{"1+", {0.5}}};
  const WrittenFigure w = write_figure_files(dir, "coverage", h, {"layout.json"}, "coverage", {});
  EXPECT_EQ(slurp(w.svg), to_svg(h, 800, 520));
  EXPECT_EQ(slurp(w.csv), to_csv(h));
  const auto j = nlohmann::json::parse(slurp(w.json));
  EXPECT_EQ(j["csv_columns"], nlohmann::json::array({"panel", "row", "column_group", "column", "value"}));
  EXPECT_EQ(j["figure"]["kind"], "heatmap");
  EXPECT_EQ(j["figure"]["colour_scale"]["name"], "viridis");
  EXPECT_EQ(j["figure"]["colour_scale"]["label"], "share of frames");
  EXPECT_EQ(j["figure"]["panels"][0]["title"], "1+");
  EXPECT_EQ(j["figure"]["rows"], nlohmann::json::array({"thumb"}));
}

}  // namespace lmc::export_sidecar_test
