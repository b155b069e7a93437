#pragma once
// What `lmc process` writes per trial:
//  * <trial>.fused.txt      fused points in the study's resampled-file layout (one stream, id 1,
//                           100 Hz; no hand = nan,nan,nan), readable by read_lmc_recording;
//  * <trial>.measures.tsv   per-frame segment/finger lengths and joint angles (LMC, and Vicon when
//                           present) plus each device's five visibility labels;
//  * <trial>.summary.json   statistics, visibility tables, comparison, warnings, provenance;
//  * <trial>.results.txt    a text report laid out exactly like the authors' result file
//                           (Subject1_Naiv.results.txt) so both can be compared side by side.
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/processing/trial_pipeline.h"

namespace lmc {

// The authors' layout: "%f" numbers, tab-separated, "%0.2f" visibility, their headings.
std::string format_results_text(const TrialAnalysis& r);
std::string format_measures_tsv(const TrialAnalysis& r);
std::string format_fused_points(const TrialAnalysis& r);

// The four files' names and contents, formatted but not yet written (a batch formats them on the
// thread that processed the trial and writes them on another, core/io/file_committer.h).
struct TrialOutputFile {
  std::string name;
  std::string contents;
};
// `summary` is trial_summary_json(r), which a batch has already built for the trial's outcome.
std::vector<TrialOutputFile> trial_output_files(const TrialAnalysis& r, const nlohmann::json& summary);

}  // namespace lmc
