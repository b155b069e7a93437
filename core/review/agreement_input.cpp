#include "core/review/agreement_input.h"

#include <utility>

#include "core/hand/hand_frame.h"
#include "core/processing/measures.h"
#include "core/results/summary_reading.h"

namespace lmc {

namespace {

std::array<AgreementMeasure, kAgreementMeasures> make_agreement_measures() {
  std::array<AgreementMeasure, kAgreementMeasures> m;
  std::size_t i = 0;
  for (std::size_t f = 0; f < static_cast<std::size_t>(kNumFingers); ++f) {
    const std::string part(digit_name(f));
    m[i++] = {"finger_length_" + part, "finger length", part, "mm", "finger_mean_mm", f};
  }
  for (std::size_t a = 0; a < static_cast<std::size_t>(kNumAngles); ++a) {
    const std::string part(angle_name(static_cast<int>(a)));
    m[i++] = {"rom_" + part, "range of motion", part, "deg", "angle_rom_deg", a};
  }
  return m;
}

}  // namespace

const std::array<AgreementMeasure, kAgreementMeasures>& agreement_measures() {
  static const auto measures = make_agreement_measures();
  return measures;
}

AgreementTrial agreement_trial(std::string subject, nlohmann::json summary) {
  AgreementTrial t;
  t.subject = std::move(subject);
  const auto tag = summary.is_object() ? summary.value("tag", nlohmann::json::object()) : nlohmann::json::object();
  if (summary.is_object() && summary.contains("trial") && summary["trial"].is_string())
    t.trial = summary["trial"].get<std::string>();
  t.layout = tag.value("layout", "unknown");
  t.pose = tag.value("pose", "unknown");
  t.motion = tag.value("motion", "unknown");
  t.summary = std::move(summary);
  return t;
}

PairedTrials extract_paired_trials(const std::vector<AgreementTrial>& trials) {
  PairedTrials out;
  for (const AgreementTrial& t : trials) {
    if (!t.summary.is_object() || !summary_has_vicon(t.summary)) {
      ++out.without_vicon;
      continue;
    }
    PairedTrial p{t.subject, t.trial, t.layout, t.pose, t.motion, {}, {}};
    const auto& lmc = t.summary.contains("lmc") ? t.summary["lmc"] : nlohmann::json::object();
    const auto& vicon = t.summary["vicon"];
    for (std::size_t i = 0; i < kAgreementMeasures; ++i) {
      const AgreementMeasure& m = agreement_measures()[i];
      p.lmc[i] = summary_element(lmc, m.summary_key, m.index);
      p.vicon[i] = summary_element(vicon, m.summary_key, m.index);
    }
    out.trials.push_back(std::move(p));
  }
  return out;
}

}  // namespace lmc
