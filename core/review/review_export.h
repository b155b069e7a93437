#pragma once
// What the Review tab's Export buttons and `lmc figures` write, one implementation for
// both: every figure as SVG with the exact data behind it as CSV and a JSON sidecar (inputs,
// method, parameters, software version), and the tables as CSV/JSON/Markdown.
//   agreement.csv / agreement.json        Bland–Altman, RMSE, r, ICC per layout × pose and measure
//   bland-altman-<group>-<measure>.*      one plot per group and measure (svg, csv, json)
//   visibility-map.*                      the study's map (svg, csv, json) and visibility-map-table.csv
//   study-tables.md, study-*.csv          the study's headline tables (lmc report's)
//   trial-<name>.*                        a trial's angles and finger lengths against Vicon (svg, csv,
//                                         json) and <…>.series.csv (every series and label, wide)
#include <filesystem>
#include <stop_token>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/review/agreement_table.h"
#include "core/review/trial_series.h"

namespace lmc {

struct ReviewExportInput {
  std::vector<AgreementTrial> trials;  // processed trials (their summaries)
  AgreementOptions agreement;
  std::vector<std::string> inputs;                       // the folders or files they came from, for the sidecars
  std::string method;                                    // the fusion method's name
  nlohmann::json parameters = nlohmann::json::object();  // processing parameters (process_options_json)
};

// Writes into `dir` (created when missing); returns the files written. Throws lmc::Error naming the
// file when a write fails; files already written stay (each is written atomically). A stop request
// is honoured between files: what was written is complete, the rest is not started.
std::vector<std::filesystem::path> write_review_exports(const std::filesystem::path& dir,
                                                        const ReviewExportInput& input, std::stop_token stop = {});

std::vector<std::filesystem::path> write_trial_export(const std::filesystem::path& dir, const TrialSeries& series,
                                                      const std::vector<std::string>& inputs, const std::string& method,
                                                      const nlohmann::json& parameters, bool each_controller = false,
                                                      std::stop_token stop = {});

}  // namespace lmc
