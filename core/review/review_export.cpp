#include "core/review/review_export.h"

#include "core/figures/export_sidecar.h"
#include "core/io/atomic_write.h"
#include "core/reports/session_report.h"
#include "core/review/review_figures.h"
#include "core/review/visibility_map.h"

namespace fs = std::filesystem;

namespace lmc {
namespace {

void add_written(std::vector<fs::path>& out, const WrittenFigure& w) {
  out.push_back(w.svg);
  out.push_back(w.csv);
  out.push_back(w.json);
}

void write_text(std::vector<fs::path>& out, const fs::path& path, const std::string& text) {
  write_file_atomically(path, text);
  out.push_back(path);
}

}  // namespace

std::vector<fs::path> write_review_exports(const fs::path& dir, const ReviewExportInput& in, std::stop_token stop) {
  if (stop.stop_requested()) return {};
  fs::create_directories(dir);
  std::vector<fs::path> written;
  const AgreementTable table = agreement_table(in.trials, in.agreement);
  nlohmann::json params = in.parameters;
  params["agreement_motion"] =
      in.agreement.motion.empty() ? nlohmann::json("all") : nlohmann::json(in.agreement.motion);
  write_text(written, dir / "agreement.csv", agreement_csv(table));
  write_text(written, dir / "agreement.json", nlohmann::json(table).dump(2) + "\n");
  for (const auto& group : table.groups) {
    for (const auto& m : group.measures) {
      if (stop.stop_requested()) return written;
      const std::string stem = figure_stem("bland-altman-" + group.layout + "-" + group.pose + "-" + m.measure.name);
      add_written(written, write_figure_files(dir, stem, bland_altman_figure(group, m), in.inputs,
                                              "bland-altman (" + m.bland_altman.method + ")", params));
    }
  }
  if (stop.stop_requested()) return written;
  const VisibilityMap map = visibility_map(in.trials);
  add_written(written, write_figure_files(dir, "visibility-map", visibility_map_figure(map), in.inputs,
                                          "visibility rate per controller x motion x layout", params));
  write_text(written, dir / "visibility-map-table.csv", visibility_map_csv(map));
  if (stop.stop_requested()) return written;
  std::vector<ReportInput> report_inputs;
  for (const auto& t : in.trials) report_inputs.push_back({t.subject, t.summary});
  const SessionReport report = build_session_report(report_inputs);
  write_text(written, dir / "study-tables.md", report.markdown);
  write_text(written, dir / "study-trials.csv", report.trials_csv);
  write_text(written, dir / "study-finger-length.csv", report.finger_length_csv);
  write_text(written, dir / "study-joint-angles.csv", report.joint_angle_csv);
  write_text(written, dir / "study-visibility.csv", report.visibility_csv);
  return written;
}

std::vector<fs::path> write_trial_export(const fs::path& dir, const TrialSeries& series,
                                         const std::vector<std::string>& inputs, const std::string& method,
                                         const nlohmann::json& parameters, bool each_controller, std::stop_token stop) {
  if (stop.stop_requested()) return {};
  fs::create_directories(dir);
  std::vector<fs::path> written;
  const std::string stem = figure_stem("trial-" + series.trial);
  add_written(written, write_figure_files(dir, stem, trial_figure(series, each_controller), inputs,
                                          "time series (" + method + " fusion)", parameters, 900, 1600));
  if (stop.stop_requested()) return written;
  write_text(written, dir / (stem + ".series.csv"), trial_series_csv(series));
  return written;
}

}  // namespace lmc
