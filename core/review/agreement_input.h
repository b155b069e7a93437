#pragma once
// The per-trial LMC-vs-Vicon pairs the agreement statistics are computed from (Review
// tab). A trial's summary JSON already holds one value per finger length and joint ROM for each
// system; agreement is judged on those per-trial values (not per frame), so a trial is one
// observation and a subject with several trials needs the repeated-measures forms downstream.
#include <array>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace lmc {

// One processed trial as the Review tab loads it: the subject comes from the session folder, the
// rest from the summary's tag (agreement_trial() fills them) or from the caller.
struct AgreementTrial {
  std::string subject;
  std::string trial;
  std::string layout;
  std::string pose;
  std::string motion;
  nlohmann::json summary;
};

// Fills trial, layout, pose and motion from the summary ("unknown" where the tag lacks one, as
// `lmc report` groups them).
AgreementTrial agreement_trial(std::string subject, nlohmann::json summary);

// The measures compared: 5 per-trial mean finger lengths, then 6 joint ranges of motion.
inline constexpr std::size_t kAgreementMeasures = 11;

struct AgreementMeasure {
  std::string name;              // "finger_length_thumb", "rom_index_mcp", …
  std::string quantity;          // "finger length" / "range of motion"
  std::string part;              // "thumb", "index_mcp", …
  std::string unit;              // "mm" / "deg"
  const char* summary_key = "";  // the summary's statistics key, read from "lmc" and "vicon"
  std::size_t index = 0;         // element of that array
};

const std::array<AgreementMeasure, kAgreementMeasures>& agreement_measures();

// One trial's paired values; NaN where the summary has null (never 0).
struct PairedTrial {
  std::string subject;
  std::string trial;
  std::string layout;
  std::string pose;
  std::string motion;
  std::array<double, kAgreementMeasures> lmc{};
  std::array<double, kAgreementMeasures> vicon{};
};

struct PairedTrials {
  std::vector<PairedTrial> trials;  // trials with Vicon, in input order
  std::size_t without_vicon = 0;    // trials skipped because they had no Vicon recording
};

PairedTrials extract_paired_trials(const std::vector<AgreementTrial>& trials);

}  // namespace lmc
