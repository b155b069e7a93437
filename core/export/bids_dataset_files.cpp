#include "core/export/bids_dataset_files.h"

#include <regex>

#include "core/common/number_format.h"
#include "core/export/bids_names.h"

namespace lmc {
namespace bids_files_detail {  // named: core compiles in unity batches

constexpr const char* kProgram = "lmc-workbench";

std::string size_cell(const std::optional<double>& mm) {
  return mm ? format_fixed(*mm, 1) : std::string("n/a");
}

}  // namespace bids_files_detail

nlohmann::json bids_dataset_description(const std::string& name) {
  return {
      {"Name", name},
      {"BIDSVersion", "1.9.0"},
      {"DatasetType", "raw"},
      {"GeneratedBy",
       nlohmann::json::array(
           {{{"Name", bids_files_detail::kProgram},
             {"Version", LMC_VERSION},
             {"Description", "lmc export bids: accepted trials of subject sessions, processed onto a 100 Hz grid"}}})}};
}

std::filesystem::path bids_dataset_root_of(const std::filesystem::path& dir) {
  std::error_code ec;
  for (std::filesystem::path p = std::filesystem::absolute(dir, ec).lexically_normal(); !p.empty();
       p = p.parent_path()) {
    if (std::filesystem::is_regular_file(p / "dataset_description.json", ec)) return p;
    if (p == p.parent_path()) break;
  }
  return {};
}

bool bids_dataset_is_ours(const nlohmann::json& description) {
  if (!description.is_object() || !description.contains("GeneratedBy") || !description["GeneratedBy"].is_array())
    return false;
  for (const auto& g : description["GeneratedBy"]) {
    if (g.is_object() && g.value("Name", std::string{}) == bids_files_detail::kProgram) return true;
  }
  return false;
}

std::string bids_participants_tsv(const std::vector<BidsParticipant>& participants) {
  std::string out = "participant_id\thandedness\thand_length_mm\thand_breadth_mm\n";
  for (const auto& p : participants) {
    out += bids_subject_dir(p.label) + "\t" + (p.handedness.empty() ? std::string("n/a") : p.handedness) + "\t" +
           bids_files_detail::size_cell(p.hand_length_mm) + "\t" + bids_files_detail::size_cell(p.hand_breadth_mm) +
           "\n";
  }
  return out;
}

nlohmann::json bids_participants_json() {
  return {{"participant_id",
           {{"Description", "The subject: sub- and the session's subject id, or a number when anonymised"}}},
          {"handedness",
           {{"Description", "The hand recorded, as the session's manifest gives it"},
            {"Levels", {{"right", "right hand"}, {"left", "left hand"}}}}},
          {"hand_length_mm",
           {{"Description", "Hand length: wrist crease to the tip of the middle finger"}, {"Units", "mm"}}},
          {"hand_breadth_mm", {{"Description", "Hand breadth across the metacarpal heads"}, {"Units", "mm"}}}};
}

std::string bids_scans_tsv(const std::vector<BidsScan>& scans) {
  std::string out = "filename\tacq_time\n";
  for (const auto& s : scans) out += s.filename + "\t" + (s.acq_time.empty() ? std::string("n/a") : s.acq_time) + "\n";
  return out;
}

std::string bids_acq_time(const std::string& utc) {
  static const std::regex form(R"((\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2})\.(\d{3})Z)");
  std::smatch m;
  if (!std::regex_match(utc, m, form)) return {};
  return m[1].str() + "." + m[2].str() + "000Z";
}

std::string bids_readme(bool anonymised) {
  std::string t;
  t += "Leap Motion Controller hand tracking, several controllers at once, with Vicon\n";
  t += "==========================================================================\n\n";
  t += "Exported by lmc-workbench (`lmc export bids`, version " LMC_VERSION ") from subject session folders.\n";
  t += "One subject per subject id (a second session folder of one id is its ses-2); every accepted trial,\n"
       "processed onto the 100 Hz grid.\n\n";
  t += "Naming\n------\n";
  t += "sub-<subject>/motion/"
       "sub-<subject>_task-<motion>_tracksys-<system>_acq-<layout>_run-<pose><repetition>_<suffix>\n";
  t += "* task: the motion (Static, Index, Thumb, Wrist, ...).\n";
  t += "* acq: the controller layout key of the trial's block (Naiv, Opti, ...); the layout itself is in layouts/.\n";
  t += "* run: the palm pose code followed by the repetition in two digits (run-102: pose 1, repetition 2),\n";
  t += "  the same digits as the trial name (Naiv_Index102).\n";
  t += "* tracksys: LMC1, LMC2, ... each controller's own hand realigned into the world frame; LMCfused the\n";
  t += "  fused hand; Vicon the trial's Vicon markers, when the trial had a Vicon file.\n";
  t += "BIDS labels hold letters and digits only: other characters of the study's names are dropped (Subject_7 -> "
       "Subject7).\n";
  if (anonymised) t += "Subjects are numbered 01, 02, ...; the key to the session ids is kept outside the dataset.\n";
  t += "\nData\n----\n";
  t += "Positions in mm in the rig's world frame: x along the table to the subject's right, y up (table top y = 0),\n";
  t += "z towards the subject (channels.json: SpatialAxes RSP). Each hand has 28 tracked points: Palm, Elbow, Wrist\n";
  t += "and <Thumb|Index|Middle|Ring|Pinky>_<Meta|Proxi|Inter|Dist|End> (Proxi is the MCP joint; the thumb's Meta\n";
  t += "equals its Proxi). Every tracking system of a trial shares one time base: row r is r / 100 s after the\n";
  t += "first row. A point without data in a frame (no hand, a Vicon gap) is n/a.\n";
  t += "events.tsv: go (the subject was told to go), stop (the last recorded frame), vicon_capture_start (Vicon's\n";
  t += "capture trigger, or the simulated Vicon's time zero), in seconds from the first row.\n";
  t += "\nlayouts/\n--------\n";
  t += "layouts/sub-<subject>_acq-<layout>_layout.json: the layout the subject's trials of that block were processed\n";
  t += "with (lmc-workbench layout JSON, format 1: each controller's slot, pose in mm and degrees, calibration "
       "offset).\n";
  t += "BIDS does not define this file; .bidsignore names the folder.\n";
  return t;
}

std::string bids_ignore() {
  return std::string(kBidsLayoutsDir) + "/\n";
}

}  // namespace lmc
