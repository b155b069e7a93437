#pragma once
// The dataset-level files of a BIDS-motion export, as text: what describes the dataset as a whole
// (dataset_description.json, README, participants.tsv/.json, .bidsignore) and each subject's
// scans.tsv. Only the manifest's subject fields a reader of the data needs go out (handedness,
// hand length and breadth); the operator's name and notes never do.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lmc {

// The layouts the controllers were in, one JSON per subject and layout key; a folder BIDS does
// not define, so .bidsignore names it and the README describes it.
inline constexpr const char* kBidsLayoutsDir = "layouts";

nlohmann::json bids_dataset_description(const std::string& name);
// True when `description` (a dataset_description.json) says this program generated the dataset.
bool bids_dataset_is_ours(const nlohmann::json& description);
// The BIDS dataset `dir` lies in: `dir` or its nearest parent holding a dataset_description.json;
// empty when none does. A per-trial export there would put files the dataset does not list into
// it (the validator's NOT_INCLUDED), so it is refused.
std::filesystem::path bids_dataset_root_of(const std::filesystem::path& dir);

struct BidsParticipant {
  std::string label;  // without "sub-"
  std::string handedness;
  std::optional<double> hand_length_mm, hand_breadth_mm;
};
std::string bids_participants_tsv(const std::vector<BidsParticipant>& participants);
nlohmann::json bids_participants_json();

struct BidsScan {
  std::string filename;  // relative to the subject folder ("motion/sub-…_motion.tsv")
  std::string acq_time;  // BIDS datetime, or empty: n/a
};
std::string bids_scans_tsv(const std::vector<BidsScan>& scans);
// The sidecars' UTC times as BIDS writes them (contract-figure: both formats' examples):
// "2026-11-27T16:42:03.552Z" as "2026-11-27T16:42:03.552000Z" (contract-figure); empty when
// `utc` is not in that form.
std::string bids_acq_time(const std::string& utc);

std::string bids_readme(bool anonymised);
std::string bids_ignore();

}  // namespace lmc
