// Calibration: the rigid fits, both calibration modes on synthetic trials with known
// errors, the write-back into a layout, the warnings, and the published static trial.
#include <gtest/gtest.h>

#include <iostream>

#include "core/calibration/calibrate.h"
#include "core/calibration/calibrated_layout.h"
#include "core/io/layout_json.h"
#include "core/processing/batch.h"
#include "tests/support/reference_data.h"
#include "tests/support/synthetic_calibration.h"

namespace calibration_test {

using lmc::RigidTransform;
using lmc::Vec3;
namespace syn = lmc::test::synthetic_calibration;

// Anchored truth for the consensus fit: the truth with the same gauge the fit uses.
std::vector<RigidTransform> anchored(const std::vector<RigidTransform>& truth, const lmc::Layout& layout) {
  std::vector<RigidTransform> nominal;
  for (const auto& d : layout.devices) nominal.push_back(lmc::device_transform(d));
  return lmc::anchor_to_nominal(truth, nominal, std::vector<bool>(truth.size(), true));
}

void expect_near(const RigidTransform& got, const RigidTransform& want, double mm, double deg,
                 const std::string& what) {
  EXPECT_LT((got.t - want.t).norm(), mm) << what;
  EXPECT_LT(lmc::rotation_angle_deg(got.r.transpose() * want.r), deg) << what;
}

}  // namespace calibration_test

TEST(CalibrationPose, SetRotationReproducesTheMatrix) {
  for (const auto& angles : {std::array<double, 3>{10, -20, 30}, {-170, 45, 5}, {0, 89.9, 0}, {12, 90, 0}}) {
    lmc::DevicePose p;
    p.rx_deg = angles[0];
    p.ry_deg = angles[1];
    p.rz_deg = angles[2];
    lmc::DevicePose q;
    q.set_rotation(p.rotation());
    EXPECT_LT((q.rotation() - p.rotation()).norm(), 1e-9) << angles[0] << " " << angles[1] << " " << angles[2];
  }
}

TEST(CalibrationFit, KabschRecoversAKnownTransformAndHuberIgnoresOutliers) {
  const lmc::RigidTransform truth{calibration_test::syn::turn(12.0, 1), lmc::Vec3(30, -20, 55)};
  std::vector<lmc::Vec3> src, dst;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-80, 80);
  for (int i = 0; i < 400; ++i) {
    src.emplace_back(u(rng), u(rng) + 200, u(rng));
    dst.push_back(truth.apply(src.back()));
  }
  const std::vector<double> ones(src.size(), 1.0);
  calibration_test::expect_near(lmc::weighted_kabsch(src, dst, ones), truth, 1e-9, 1e-9, "exact");
  // 10 % of the targets 60 mm off in one direction: least squares is pulled, Huber much less.
  for (size_t i = 0; i < dst.size(); i += 10) dst[i] += lmc::Vec3(60, 0, 0);
  const lmc::RigidTransform plain = lmc::weighted_kabsch(src, dst, ones);
  const lmc::RigidTransform robust = lmc::robust_rigid_fit(src, dst, lmc::RigidTransform{}, {});
  EXPECT_GT((plain.t - truth.t).norm(), 5.0);
  EXPECT_LT((robust.t - truth.t).norm(), 0.5);
  EXPECT_LT(lmc::rotation_angle_deg(robust.r.transpose() * truth.r), 0.1);
}

// A controller clamps each coordinate at its axis cut (calibration_samples.h): points beyond it read
// on the cut. Whole-point Kabsch is pulled by them; the samples' axes inside the cut, fitted by the
// masked fit, give the transform back, from a start as far off as a misplaced controller.
TEST(CalibrationFit, ClampedCoordinatesAreMaskedNotFitted) {
  const lmc::RigidTransform truth{calibration_test::syn::turn(8.0, 2), lmc::Vec3(-120, 5, -240)};
  std::vector<lmc::Vec3> src, dst;
  std::vector<std::uint8_t> axes;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-50, 50);
  int clamped = 0;
  for (int i = 0; i < 600; ++i) {
    lmc::Vec3 device(u(rng), u(rng) + 245, u(rng) + 150);  // half the hand beyond y = 250
    dst.push_back(truth.apply(device));
    for (int k = 0; k < 3; ++k) device[k] = std::clamp(device[k], -250.0, 250.0);
    src.push_back(device);
    axes.push_back(lmc::unclamped_axes(device, lmc::kAllAxes));
    clamped += axes.back() == lmc::kAllAxes ? 0 : 1;
  }
  EXPECT_GT(clamped, 200);
  const std::vector<double> ones(src.size(), 1.0);
  const lmc::RigidTransform start{calibration_test::syn::turn(6.0, 0) * truth.r, truth.t + lmc::Vec3(12, -9, 8)};
  const lmc::RigidTransform whole = lmc::weighted_kabsch(src, dst, ones);
  EXPECT_GT((whole.t - truth.t).norm(), 2.0);
  calibration_test::expect_near(lmc::weighted_masked_fit(src, dst, axes, ones, start), truth, 1e-6, 1e-6, "masked");
  calibration_test::expect_near(lmc::robust_rigid_fit(src, dst, start, {}, nullptr, axes), truth, 1e-6, 1e-6,
                                "robust, masked");
  // With every axis trusted the masked fit has Kabsch's minimum.
  const std::vector<std::uint8_t> all(src.size(), lmc::kAllAxes);
  for (size_t i = 0; i < src.size(); ++i) src[i] = truth.inverse().apply(dst[i]);
  calibration_test::expect_near(lmc::weighted_masked_fit(src, dst, all, ones, start),
                                lmc::weighted_kabsch(src, dst, ones), 1e-6, 1e-6, "whole points");
}

TEST(CalibrationVicon, RecoversInjectedErrorsOfEveryController) {
  const lmc::Layout layout = calibration_test::syn::square_layout();
  const auto truth =
      calibration_test::syn::perturbed(layout, {{40, -10, 25}, {-60, 30, 10}, {5, 5, -70}, {0, 0, 0}}, {8, -6, 10, 3});
  const auto trial = calibration_test::syn::make_trial(truth, 500, 1.0, 3);
  const auto result = lmc::calibrate(trial.input, layout);
  ASSERT_TRUE(result.with_vicon);
  for (size_t d = 0; d < truth.size(); ++d) {
    const auto& dc = result.devices[d];
    ASSERT_TRUE(dc.fitted) << dc.slot;
    calibration_test::expect_near(dc.fitted_transform, truth[d], 0.3, 0.1, dc.slot);
    EXPECT_GT(dc.all.before_mm, 5.0) << dc.slot;
    EXPECT_LT(dc.all.after_mm, 2.0) << dc.slot;  // ≈ √3 · 1 mm noise
  }
  EXPECT_NEAR(result.devices[1].moved_mm, lmc::Vec3(-60, 30, 10).norm(), 0.3);
  EXPECT_NEAR(result.devices[2].turned_deg, 10.0, 0.1);
  EXPECT_LT(result.disagreement_after_mm, result.disagreement_before_mm);
  EXPECT_TRUE(result.all_warnings().empty()) << result.all_warnings().front();
}

TEST(CalibrationConsensus, RecoversErrorsRelativeToTheAnchorWithoutVicon) {
  const lmc::Layout layout = calibration_test::syn::square_layout();
  const auto truth =
      calibration_test::syn::perturbed(layout, {{40, -10, 25}, {-60, 30, 10}, {5, 5, -70}, {20, 0, 0}}, {8, -6, 10, 3});
  const auto trial = calibration_test::syn::make_trial(truth, 500, 1.0, 4, false);
  const auto result = lmc::calibrate(trial.input, layout);
  ASSERT_FALSE(result.with_vicon);
  const auto want = calibration_test::anchored(truth, layout);
  for (size_t d = 0; d < truth.size(); ++d) {
    ASSERT_TRUE(result.devices[d].fitted);
    calibration_test::expect_near(result.devices[d].fitted_transform, want[d], 1.0, 0.2, result.devices[d].slot);
  }
  EXPECT_GT(result.disagreement_before_mm, 20.0);
  EXPECT_LT(result.disagreement_after_mm, 2.0);
  EXPECT_GT(result.sweeps, 1);
}

TEST(CalibrationWarnings, SwappedSerialsAreNamedInBothModes) {
  const lmc::Layout layout = calibration_test::syn::square_layout();
  std::vector<lmc::RigidTransform> truth;
  for (const auto& d : layout.devices) truth.push_back(lmc::device_transform(d));
  std::swap(truth[1], truth[2]);  // LMC2's controller stands where LMC3 should, and back
  for (const bool vicon : {true, false}) {
    const auto trial = calibration_test::syn::make_trial(truth, 300, 1.0, 5, vicon);
    const auto result = lmc::calibrate(trial.input, layout);
    ASSERT_EQ(result.warnings.size(), 1U) << (vicon ? "with Vicon" : "without");
    EXPECT_NE(result.warnings[0].find("LMC2 and LMC3 look swapped"), std::string::npos) << result.warnings[0];
    // The correction is then > 100 mm: the implausible-correction warning names both too.
    EXPECT_NE(result.devices[1].warnings.front().find("larger than a misplaced controller explains"),
              std::string::npos);
  }
}

TEST(CalibrationWarnings, AControllerWithoutDataIsLeftAsItWas) {
  const lmc::Layout layout = calibration_test::syn::square_layout();
  std::vector<lmc::RigidTransform> truth;
  for (const auto& d : layout.devices) truth.push_back(lmc::device_transform(d));
  auto trial = calibration_test::syn::make_trial(truth, 200, 1.0, 6);
  trial.input.device_frame.devices.pop_back();  // LMC4 recorded nothing
  trial.input.labels.pop_back();
  const auto result = lmc::calibrate(trial.input, layout);
  EXPECT_FALSE(result.devices[3].fitted);
  ASSERT_EQ(result.devices[3].warnings.size(), 1U);
  EXPECT_EQ(result.devices[3].warnings[0], "LMC4: only 0 usable samples with Vicon points (needs 100): left as it was");
  const lmc::Layout out = lmc::calibrated_layout(layout, result, {"T", "T.trc", "2026-01-01T00:00:00Z"});
  EXPECT_EQ(out.devices[3], layout.devices[3]);
}

TEST(CalibrationLayout, WrittenBackLayoutReproducesTheFittedTransforms) {
  lmc::Layout layout = calibration_test::syn::square_layout();
  layout.devices[0].pose.rx_deg = 20;
  layout.devices[0].offset_mm = lmc::Vec3(1, 2, 3);
  const auto truth =
      calibration_test::syn::perturbed(layout, {{10, 20, 30}, {-5, 0, 8}, {0, 0, 0}, {3, 3, 3}}, {5, 2, 1, 0.5});
  const auto trial = calibration_test::syn::make_trial(truth, 200, 0.5, 7);
  const auto result = lmc::calibrate(trial.input, layout);
  const lmc::Layout out =
      lmc::calibrated_layout(layout, result, {"Naiv_Static101", "Naiv_Static101.trc", "2026-11-23T16:00:00Z"});
  EXPECT_EQ(out.name, "square (calibrated)");
  EXPECT_NE(
      out.description.find("from trial Naiv_Static101 against Vicon file Naiv_Static101.trc on 2026-11-23T16:00:00Z"),
      std::string::npos);
  EXPECT_EQ(lmc::validate_layout(out), "");
  for (size_t d = 0; d < out.devices.size(); ++d) {
    EXPECT_EQ(out.devices[d].pose.translation(),
              layout.devices[d].pose.translation());  // position corrections go to the offset
    for (const lmc::Vec3& p : {lmc::Vec3(0, 0, 0), lmc::Vec3(10, 200, -30)})
      EXPECT_LT((out.devices[d].to_world(p) - result.devices[d].fitted_transform.apply(p)).norm(), 1e-9);
  }
  // Through JSON and back: the same numbers.
  EXPECT_EQ(lmc::layout_from_json(lmc::layout_to_json(out), "mem"), out);
  const std::string table = lmc::residual_table(result);
  EXPECT_NE(table.find("LMC1"), std::string::npos);
  EXPECT_NE(table.find("Disagreement between controllers"), std::string::npos);
}

// The published static trial with the authors' hand-measured layout: calibration must make the
// controllers agree better on the points they all see, with and without the Vicon file.
TEST(CalibrationReference, PublishedStaticTrialControllersAgreeBetterAfterwards) {
  const auto lmc_file = lmc::test::reference_file("validation/Interp_LMC_Naiv_Static101.txt");
  const auto trc_file = lmc::test::reference_file("validation/Naiv_Static101.trc");
  LMC_REQUIRE_REFERENCE_FILE(lmc_file);
  LMC_REQUIRE_REFERENCE_FILE(trc_file);
  const lmc::Layout layout = lmc::load_layout_or_preset("paper-initial");
  const lmc::LmcRecording rec = lmc::read_lmc_recording(lmc_file);
  const lmc::HandTrack vicon =
      lmc::apply_vicon_mapping(lmc::default_vicon_mapping(), lmc::load_vicon_markers(trc_file));
  // Without Vicon; with Vicon as it is; with Vicon anchored to the layout's frame (the trial's
  // Vicon origin is ≈ 100 mm and 10° from the layout's, which the plain run must say).
  for (const int mode : {0, 1, 2}) {
    const bool with_vicon = mode > 0;
    lmc::CalibrationOptions options;
    options.anchor_vicon_to_layout = mode == 2;
    const auto input = lmc::prepare_calibration_input(rec, with_vicon ? &vicon : nullptr, {});
    const auto result = lmc::calibrate(input, layout, options);
    std::cout << "mode " << mode << "\n" << lmc::residual_table(result);
    EXPECT_LT(result.disagreement_after_mm, result.disagreement_before_mm);
    EXPECT_GT(result.covisible_samples, 1000);
    for (const auto& d : result.devices) {
      EXPECT_TRUE(d.fitted) << d.slot;
      if (with_vicon) {
        EXPECT_LT(d.all.after_mm, d.all.before_mm) << d.slot;
      }
    }
    if (mode == 1) {
      ASSERT_FALSE(result.warnings.empty());
      EXPECT_NE(result.warnings[0].find("the Vicon frame is probably not the layout's world frame"), std::string::npos)
          << result.warnings[0];
    }
  }
}

// A Vicon origin that is not the layout's: every controller appears moved by the same amount.
// The plain run says so; anchored to the layout, only the controllers' relative errors remain.
TEST(CalibrationVicon, ACommonShiftIsReportedAndAnchoringKeepsTheLayoutsFrame) {
  const lmc::Layout layout = calibration_test::syn::square_layout();
  const lmc::Vec3 shift(60, -20, 30);
  const auto truth =
      calibration_test::syn::perturbed(layout, {shift, shift + lmc::Vec3(10, 0, 0), shift, shift}, {0, 0, 0, 0});
  const auto trial = calibration_test::syn::make_trial(truth, 300, 1.0, 8);
  const auto plain = lmc::calibrate(trial.input, layout);
  ASSERT_FALSE(plain.warnings.empty());
  EXPECT_NE(plain.warnings[0].find("every controller moved by 72."), std::string::npos) << plain.warnings[0];
  lmc::CalibrationOptions options;
  options.anchor_vicon_to_layout = true;
  const auto anchored = lmc::calibrate(trial.input, layout, options);
  EXPECT_TRUE(anchored.warnings.empty());
  ASSERT_EQ(anchored.notes.size(), 1U);
  // Truth relative to the anchor: LMC2 is 10 mm further along x than the others, the mean is 0.
  EXPECT_NEAR(anchored.devices[1].moved_mm, 7.5, 0.3);
  EXPECT_NEAR(anchored.devices[0].moved_mm, 2.5, 0.3);
  EXPECT_LT(anchored.devices[1].all.after_mm, 2.0);
}
