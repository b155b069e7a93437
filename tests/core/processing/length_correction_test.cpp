// Per-subject finger-length correction on constructed hands: a "controller"
// hand whose finger bones are a known fraction of the true hand's, posed with the same joint
// angles. Fitting must find the inverse fractions, applying them must give the true hand back and
// leave every joint angle as it was; bad input must be refused with a message naming the problem.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>

#include "core/common/error.h"
#include "core/hand/hand_model.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/vicon_mapping.h"
#include "core/processing/batch.h"
#include "core/processing/length_correction.h"
#include "core/processing/length_correction_json.h"
#include "core/processing/measures.h"
#include "core/processing/process_options_json.h"
#include "core/processing/trial_pipeline.h"
#include "core/processing/trial_summary.h"
#include "tests/support/reference_data.h"
#include "tests/support/shared_real_trial.h"

namespace length_correction_test {

using namespace lmc;

// The controllers' bias of the study-errors simulator (devices/README.md): thumb … little.
constexpr std::array<double, kNumFingers> kShort = {0.876, 0.861, 0.818, 0.800, 0.760};

// A hand of this size with each digit's phalanges (the bones of its finger length) scaled.
HandModel scaled_hand(double hl, double hb, const std::array<double, kNumFingers>& scale) {
  HandGeometry g = HandModel(hl, hb).geometry();
  for (size_t d = 0; d < kNumDigits; ++d)
    for (double& len : g.phalanx_mm[d]) len *= scale[d];
  return HandModel(g);
}

// Frames of a hand moving through flexion, so that a correction has to follow bent fingers.
HandTrack moving_track(const HandModel& model, int frames) {
  HandTrack t(frames);
  for (int f = 0; f < frames; ++f) {
    HandJointAngles a;
    const double s = static_cast<double>(f) / frames;
    a.wrist_flexion_deg = 20 * s - 10;
    a.thumb.mcp_flexion_deg = 30 * s;
    a.thumb.ip_flexion_deg = 40 * s;
    for (auto& fa : a.fingers) {
      fa.mcp_flexion_deg = 60 * s;
      fa.pip_flexion_deg = 80 * s;
      fa.dip_flexion_deg = 50 * s;
      fa.mcp_abduction_deg = 5;
    }
    HandPlacement p;
    p.wrist_mm = Vec3(10, 150 + 20 * s, -30);
    const HandFrame h = model.pose(a, p);
    for (int i = 0; i < kNumHandPoints; ++i) t.at(f, i) = h.point(i);
  }
  return t;
}

// Joint angles come from acos, which near 0° turns a cosine one rounding step below 1 into
// 8.5e-7°: "unchanged" is judged to 1e-5°, far below any angle that means anything.
constexpr double kSameAngleDeg = 1e-5;

std::string error_of(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(LengthCorrection, FitToViconRecoversAKnownScaleAndApplyGivesTheTrueHandBack) {
  const HandTrack truth = moving_track(HandModel(183, 82), 40);
  const HandTrack fused = moving_track(scaled_hand(183, 82, kShort), 40);
  const LengthCorrection c = fit_length_correction_to_vicon(measure_track(fused), measure_track(truth), "constructed");
  EXPECT_EQ(c.source, LengthSource::kVicon);
  EXPECT_EQ(c.fit_frames, 40);
  for (size_t f = 0; f < kNumFingers; ++f)
    EXPECT_NEAR(c.factor[f], 1.0 / kShort[f], 1e-12) << digit_name(static_cast<int>(f));
  // The true hand's index is 0.265 + 0.143 + 0.097 of the hand length (Buchholz et al. 1992).
  EXPECT_NEAR(c.target_mm[1], (0.265 + 0.143 + 0.097) * 183, 1e-9);
  EXPECT_NEAR(c.fused_mm[1], 0.861 * (0.265 + 0.143 + 0.097) * 183, 1e-9);

  HandTrack corrected = fused;
  apply_length_correction(corrected, c);
  for (int fr = 0; fr < truth.frame_count; ++fr)
    for (int i = 0; i < kNumHandPoints; ++i)
      EXPECT_LT((corrected.at(fr, i) - truth.at(fr, i)).norm(), 1e-9) << "frame " << fr << ", " << hand_point_name(i);
}

TEST(LengthCorrection, FitToHandDimensionsUsesTheHandModelsFingers) {
  const auto expected = expected_finger_lengths_mm(176, 75);
  const MeasureStats truth = summarize(measure_track(moving_track(HandModel(176, 75), 10)));
  for (size_t f = 0; f < kNumFingers; ++f) EXPECT_NEAR(expected[f], truth.finger_mean[f], 1e-9);
  EXPECT_NEAR(expected[0], (0.196 + 0.158) * 176, 1e-9);  // thumb: proximal + distal phalanx

  const HandTrack fused = moving_track(scaled_hand(176, 75, kShort), 10);
  const LengthCorrection c = fit_length_correction_to_hand(measure_track(fused), 176, 75, "constructed");
  EXPECT_EQ(c.source, LengthSource::kHandDimensions);
  EXPECT_EQ(c.hand_length_mm, 176);
  for (size_t f = 0; f < kNumFingers; ++f) EXPECT_NEAR(c.factor[f], 1.0 / kShort[f], 1e-12);
}

TEST(LengthCorrection, ApplyKeepsEveryJointAngleAndScalesOnlyTheFingersLengths) {
  const HandTrack before = moving_track(HandModel(), 30);
  LengthCorrection c;
  c.factor = {1.30, 1.10, 0.90, 1.20, 1.25};
  HandTrack after = before;
  apply_length_correction(after, c);
  const auto mb = measure_track(before), ma = measure_track(after);
  for (int fr = 0; fr < before.frame_count; ++fr) {
    for (int a = 0; a < kNumAngles; ++a)
      EXPECT_NEAR(ma[fr].angle_deg[a], mb[fr].angle_deg[a], kSameAngleDeg) << angle_name(a) << " frame " << fr;
    for (int f = 0; f < kNumFingers; ++f)
      EXPECT_NEAR(ma[fr].finger_mm[f], c.factor[f] * mb[fr].finger_mm[f], 1e-9) << finger_name(f);
    // Palm, vectors, forearm, metacarpal bases, MCP joints (and the thumb's MCP) do not move.
    for (int i = 0; i < kNumHandPoints; ++i) {
      const int digit = (i - kFirstDigitPoint) / kJointsPerDigit, joint = (i - kFirstDigitPoint) % kJointsPerDigit;
      const bool moves =
          i >= kFirstDigitPoint && joint > (digit == 0 ? 2 : 1);  // beyond the thumb's Inter / a finger's Proxi
      if (!moves) {
        EXPECT_EQ(after.at(fr, i), before.at(fr, i)) << hand_point_name(i);
      }
    }
  }
}

TEST(LengthCorrection, NanStaysNan) {
  HandTrack t = moving_track(HandModel(), 3);
  for (int i = 0; i < kNumHandPoints; ++i) t.at(1, i) = Vec3::Constant(kNaN);
  t.at(2, digit_point(Digit::kRing, Joint::kInter)) = Vec3::Constant(kNaN);
  LengthCorrection c;
  c.factor = {1.2, 1.2, 1.2, 1.2, 1.2};
  apply_length_correction(t, c);
  EXPECT_FALSE(t.has_hand(1));
  EXPECT_TRUE(is_finite(t.at(2, digit_point(Digit::kMiddle, Joint::kEnd))));
  EXPECT_FALSE(is_finite(t.at(2, digit_point(Digit::kRing, Joint::kEnd))));
}

TEST(LengthCorrection, RefusesAMissingFingerAZeroBoneAndImplausibleInput) {
  const HandTrack truth = moving_track(HandModel(), 10);
  const auto fused = measure_track(moving_track(scaled_hand(190, 85, kShort), 10));
  auto vicon = measure_track(truth);
  for (auto& m : vicon) m.finger_mm[2] = kNaN;  // the middle finger's markers never seen
  EXPECT_NE(error_of([&] {
              fit_length_correction_to_vicon(fused, vicon, "trial T with T.trc");
            }).find("trial T with T.trc: no frame has the middle in both the fused hand and Vicon"),
            std::string::npos);

  auto collapsed = fused;
  for (auto& m : collapsed) m.segment_mm[10] = 0.0;  // Ring_distal
  EXPECT_NE(error_of([&] {
              fit_length_correction_to_vicon(collapsed, measure_track(truth), "trial T");
            }).find("trial T: the fused Ring_distal bone is 0.00 mm long on average"),
            std::string::npos);

  auto wrong_units = measure_track(truth);
  for (auto& m : wrong_units)
    for (double& v : m.finger_mm) v *= 10;  // Vicon in 0.1 mm, or another subject's file
  EXPECT_NE(error_of([&] {
              fit_length_correction_to_vicon(fused, wrong_units, "trial T");
            }).find("the thumb's length factor is 11.416"),
            std::string::npos);

  EXPECT_NE(error_of([&] {
              fit_length_correction_to_hand(fused, 0, 80, "trial T");
            }).find("hand length and breadth must be positive numbers in mm (given 0.0 and 80.0)"),
            std::string::npos);
  EXPECT_NE(error_of([&] { fit_length_correction_to_hand(fused, kNaN, 80, "trial T"); }).find("must be positive"),
            std::string::npos);
  EXPECT_NE(error_of([&] { expected_finger_lengths_mm(1900, 85); }).find("hand length must be in (50, 400) mm"),
            std::string::npos);
}

TEST(LengthCorrection, FileRoundTripsAndABadFileIsNamed) {
  const auto dir = test::scratch_dir("length_correction");
  const HandTrack truth = moving_track(HandModel(), 10);
  LengthCorrection c = fit_length_correction_to_vicon(measure_track(moving_track(scaled_hand(190, 85, kShort), 10)),
                                                      measure_track(truth), "constructed");
  c.subject = "S07";
  c.fit_trial = "Naiv_Static101";
  c.fit_lmc_file = "S07/LMC_Naiv_Static101.raw.txt";
  c.fit_vicon_file = "S07/Naiv_Static101.trc";
  const auto path = dir / "S07.lengths.json";
  write_length_correction(path, c);
  const LengthCorrection back = read_length_correction(path);
  EXPECT_EQ(back.subject, "S07");
  EXPECT_EQ(back.fit_trial, "Naiv_Static101");
  EXPECT_EQ(back.fit_vicon_file, "S07/Naiv_Static101.trc");
  EXPECT_EQ(back.source, LengthSource::kVicon);
  EXPECT_EQ(back.fit_frames, 10);
  for (size_t f = 0; f < kNumFingers; ++f) {
    EXPECT_EQ(back.factor[f], c.factor[f]);  // JSON keeps doubles exactly
    EXPECT_EQ(back.target_mm[f], c.target_mm[f]);
  }

  const auto bad = [&](const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json j = length_correction_json(c);
    edit(j);
    std::ofstream(dir / "bad.json") << j.dump();
    return error_of([&] { read_length_correction(dir / "bad.json"); });
  };
  const std::string file = (dir / "bad.json").string();
  EXPECT_EQ(bad([](auto& j) { j.erase("factor"); }), file + ": at /factor: missing required field");
  EXPECT_EQ(bad([](auto& j) {
              j["factor"] = {1.1, 1.2};
            }),
            file + ": at /factor: expected 5 numbers (thumb, index, middle, ring, pinky)");
  EXPECT_EQ(bad([](auto& j) { j["factor"][3] = "1.2"; }), file + ": at /factor/3: expected a number");
  EXPECT_NE(bad([](auto& j) {
              j["factor"][4] = 0.1;
            }).find(file + ": at /factor: the pinky's length factor is 0.100, outside 0.5–2.0"),
            std::string::npos);
  EXPECT_EQ(bad([](auto& j) { j["method"] = "reference"; }),
            file + ": at /method: a length correction is fitted on and applied to the default fusion only");
  EXPECT_EQ(bad([](auto& j) { j["facter"] = 1; }).substr(0, file.size() + 17), file + ": at /facter: unk");
  EXPECT_EQ(bad([](auto& j) { j["source"] = "guess"; }),
            file + ": at /source: expected \"vicon\" or \"hand_dimensions\"");
  std::ofstream(dir / "bad.json") << "{\"format\": \"lmc-length-correction\",\n \"version\": 1,,\n}";
  EXPECT_NE(error_of([&] { read_length_correction(dir / "bad.json"); }).find(file + ":2:"), std::string::npos);
}

// In the pipeline, on the study's real trial (skips when the study's data folder is absent).
TEST(LengthCorrection, PipelineAppliesItAfterTheDefaultFusionOnlyAndTheReferenceRefusesIt) {
  const auto files = test::shared_real_trial_files();
  LMC_REQUIRE_REFERENCE_FILE(files.lmc);
  LMC_REQUIRE_REFERENCE_FILE(files.trc);
  const auto [rec, vicon, layout] = test::load_shared_real_trial();

  LengthCorrection c;
  c.subject = "Subject1";
  c.fit_trial = "Naiv_Static101";
  c.factor = {1.15, 1.20, 1.23, 1.26, 1.31};

  ProcessOptions reference;
  reference.method = FusionMethod::kReference;
  EXPECT_FALSE(process_options_json(reference).contains("length_correction"));  // cache keys made without one unchanged
  reference.length_correction = c;
  EXPECT_NE(error_of([&] {
              process_trial("Naiv_Static101", rec, layout, &vicon, reference);
            }).find("a length correction applies to the default fusion only"),
            std::string::npos);

  ProcessOptions plain;
  ProcessOptions corrected;
  corrected.length_correction = c;
  EXPECT_EQ(process_options_json(corrected)["length_correction"]["factor"][4], 1.31);
  const TrialAnalysis r0 = process_trial("Naiv_Static101", rec, layout, &vicon, plain);
  const TrialAnalysis r1 = process_trial("Naiv_Static101", rec, layout, &vicon, corrected);
  ASSERT_EQ(r0.lmc_frames.size(), r1.lmc_frames.size());
  for (size_t fr = 0; fr < r0.lmc_frames.size(); ++fr)
    for (size_t a = 0; a < kNumAngles; ++a) {
      const double before = r0.lmc_frames[fr].angle_deg[a], after = r1.lmc_frames[fr].angle_deg[a];
      if (std::isnan(before)) {
        EXPECT_TRUE(std::isnan(after));
      } else {
        EXPECT_NEAR(after, before, kSameAngleDeg) << angle_name(static_cast<int>(a));
      }
    }
  for (size_t f = 0; f < kNumFingers; ++f)
    EXPECT_NEAR(r1.lmc_stats.finger_mean[f], c.factor[f] * r0.lmc_stats.finger_mean[f], 1e-9);
  EXPECT_EQ(r1.vicon_stats.finger_mean, r0.vicon_stats.finger_mean);  // Vicon is never touched
  const nlohmann::json summary = trial_summary_json(r1);
  EXPECT_EQ(summary["length_correction"]["subject"], "Subject1");
  EXPECT_FALSE(trial_summary_json(r0).contains("length_correction"));
  // Fitted on this very trial: said in the trial's warnings.
  EXPECT_NE(std::find(r1.warnings.begin(), r1.warnings.end(),
                      "the length correction was fitted on this trial: its lengths here are not an independent test"),
            r1.warnings.end());
}

}  // namespace length_correction_test
