// Simulated rig: determinism, rates, calibration convention, axis cut, occlusion, ground truth.
#include <cmath>
#include <map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/hand/reference_poses.h"
#include "core/io/layout_json.h"
#include "core/io/pose_set_tsv.h"
#include "core/io/vicon_mapping.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_explain.h"
#include "devices/sim/sim_config.h"
#include "devices/sim/sim_rig.h"
#include "tests/devices/sim/sim_fixtures.h"
#include "tests/support/reference_data.h"

namespace lmc::devices {
namespace sim_test {

using sim_fixtures::exact;
using sim_fixtures::paper_initial;

TEST(SimRig, SameSeedSameTrialOtherSeedOtherTrial) {
  SimConfig c;
  c.seed = 11;
  const SimTrial a = generate_sim_trial(paper_initial(), c, 2.0);
  const SimTrial b = generate_sim_trial(paper_initial(), c, 2.0);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (size_t i = 0; i < a.events.size(); ++i) {
    ASSERT_EQ(a.events[i].time_s, b.events[i].time_s);
    ASSERT_EQ(a.events[i].is_frame, b.events[i].is_frame);
    if (!a.events[i].is_frame) continue;
    ASSERT_EQ(a.events[i].frame.frame.timestamp_us, b.events[i].frame.frame.timestamp_us);
    ASSERT_EQ(a.events[i].frame.frame.points, b.events[i].frame.frame.points);
  }
  c.seed = 12;
  const SimTrial other = generate_sim_trial(paper_initial(), c, 2.0);
  EXPECT_NE(other.devices[0].serial, a.devices[0].serial);
  EXPECT_NE(other.events.size(), a.events.size());
}

TEST(SimRig, EachDeviceStreamsAtAVariableRateInsideTheStudysRange) {
  const SimTrial t = generate_sim_trial(paper_initial(), SimConfig{}, 10.0);
  ASSERT_EQ(t.devices.size(), 4u);
  std::map<std::string, std::vector<double>> times;
  for (const auto& e : t.events)
    if (e.is_frame) times[e.frame.serial].push_back(e.time_s);
  for (const auto& [serial, ts] : times) {
    const double rate = static_cast<double>(ts.size()) / 10.0;
    EXPECT_GE(rate, 11.0) << serial;
    EXPECT_LE(rate, 34.0) << serial;
    double lo = 1e9, hi = 0;
    for (size_t i = 1; i < ts.size(); ++i) {
      lo = std::min(lo, ts[i] - ts[i - 1]);
      hi = std::max(hi, ts[i] - ts[i - 1]);
    }
    EXPECT_GE(lo, 1.0 / 34.0 - 1e-9);
    EXPECT_LE(hi, 1.0 / 11.0 + 1e-9);
    EXPECT_GT(hi - lo, 0.002) << "rate should vary";
  }
  // Frame ids count up by one per device; the first reported rate is 0, as the service does.
  std::map<std::string, std::int64_t> last;
  for (const auto& e : t.events) {
    if (!e.is_frame) continue;
    auto it = last.find(e.frame.serial);
    if (it == last.end()) {
      EXPECT_EQ(e.frame.frame.frame_rate_hz, 0.0);
    } else {
      EXPECT_EQ(e.frame.frame.frame_id, it->second + 1);
    }
    last[e.frame.serial] = e.frame.frame.frame_id;
  }
}

// Each simulated controller is its slot's model: it reports that model's name and product id, and a
// model with another nominal rate runs proportionally faster or slower than the study's 11–34 Hz;
// a stand-in model makes every controller report itself as that one.
TEST(SimRig, EachControllerIsItsSlotsModelOrTheStandIn) {
  Layout l = paper_initial();
  set_models_from_list(l, "ir170,lmc2,lmc,study", sensor_catalogue());
  const SimTrial t = generate_sim_trial(l, SimConfig{}, 10.0);
  ASSERT_EQ(t.devices.size(), 4u);
  EXPECT_EQ(t.devices[0].model, "simulated Stereo IR 170");
  EXPECT_EQ(t.devices[0].product_id, 0x1203u);
  EXPECT_EQ(t.devices[1].model, "simulated Leap Motion Controller 2");
  EXPECT_EQ(t.devices[1].product_id, 0x1206u);
  EXPECT_EQ(t.devices[2].model, "simulated Leap Motion Controller");
  EXPECT_EQ(t.devices[3].model, "simulated Leap Motion Controller");
  EXPECT_EQ(t.devices[3].product_id, 0x0003u);
  std::map<std::string, int> frames;
  for (const auto& e : t.events)
    if (e.is_frame) ++frames[e.frame.serial];
  const double ir170_rate = frames[t.devices[0].serial] / 10.0;
  EXPECT_GE(ir170_rate, 11.0 * 0.75);
  EXPECT_LE(ir170_rate, 34.0 * 0.75);
  SimConfig c;
  c.stand_in_model = "lmc2";
  const SimTrial stand_in = generate_sim_trial(paper_initial(), c, 1.0);
  for (const auto& d : stand_in.devices) {
    EXPECT_EQ(d.model, "simulated Leap Motion Controller 2");
    EXPECT_EQ(d.product_id, 0x1206u);
  }
  nlohmann::json j = sim_config_to_json(c);
  EXPECT_EQ(j["stand_in_model"], "lmc2");
  j["stand_in_model"] = "lmc9";
  EXPECT_THROW(sim_config_from_json(j, "sim.json"), Error);
}

TEST(SimRig, RealigningWithPoseAndLayoutOffsetGivesTheTruth) {
  const Layout layout = paper_initial();
  SimRig rig(layout, exact());
  int checked = 0;
  for (int i = 0; i < 200 && checked < 40; ++i) {
    const SimEvent e = rig.next();
    if (!e.is_frame || !e.frame.frame.hand_present) continue;
    const HandFrame truth = rig.truth_at(e.time_s);
    const LayoutDevice& ld = layout.devices[static_cast<size_t>(e.frame.frame.device_id - 1)];
    for (int p = 0; p < kNumHandPoints; ++p) {
      if (p == kPalmNormal || p == kPalmDirection) {
        EXPECT_LT((ld.pose.rotation() * e.frame.frame.point(p) - truth.point(p)).norm(), 1e-9);
        continue;
      }
      EXPECT_LT((ld.to_world(e.frame.frame.point(p)) - truth.point(p)).norm(), 1e-9) << p;
      // Without the offset the error is exactly the calibration error.
      EXPECT_LT(((ld.pose.to_world(e.frame.frame.point(p)) + ld.offset_mm) - truth.point(p)).norm(), 1e-9);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 40);
  EXPECT_EQ(rig.calibration_error(1), layout.devices[1].offset_mm);
  EXPECT_NE(rig.calibration_error(1), Eigen::Vector3d::Zero());
}

TEST(SimRig, NoiseIsAboutOneMillimetreAndElbowIsOffByTenToTwenty) {
  const Layout layout = paper_initial();
  SimConfig c = exact();
  c.noise = true;
  c.elbow_error = true;
  SimRig rig(layout, c);
  double sum_sq = 0;
  int n = 0;
  std::map<int, std::vector<double>> elbow;
  for (int i = 0; i < 800; ++i) {
    const SimEvent e = rig.next();
    if (!e.is_frame || !e.frame.frame.hand_present) continue;
    const HandFrame truth = rig.truth_at(e.time_s);
    const LayoutDevice& ld = layout.devices[static_cast<size_t>(e.frame.frame.device_id - 1)];
    const Vec3 d = ld.to_world(e.frame.frame.point(kPalm)) - truth.point(kPalm);
    sum_sq += d.squaredNorm();
    n += 3;
    elbow[e.frame.frame.device_id].push_back((ld.to_world(e.frame.frame.point(kElbow)) - truth.point(kElbow)).norm());
  }
  ASSERT_GT(n, 300);
  EXPECT_NEAR(std::sqrt(sum_sq / n), 1.0, 0.15);
  for (const auto& [id, errs] : elbow) {
    double mean = 0;
    for (double v : errs) mean += v;
    mean /= static_cast<double>(errs.size());
    EXPECT_GT(mean, 9.0) << id;
    EXPECT_LT(mean, 21.5) << id;
  }
}

TEST(SimRig, CoordinatesAreCutAt250mm) {
  Layout layout = paper_initial();
  layout.devices[0].pose.x_mm = -220;  // the hand is far along this device's x axis
  SimConfig c = exact();
  c.axis_cut = true;
  c.fov_test = false;
  SimRig rig(layout, c);
  bool cut_seen = false;
  for (int i = 0; i < 200; ++i) {
    const SimEvent e = rig.next();
    if (!e.is_frame || !e.frame.frame.hand_present) continue;
    for (int p = 0; p < kNumHandPoints; ++p) {
      if (p == kPalmNormal || p == kPalmDirection) continue;
      for (int k = 0; k < 3; ++k) {
        EXPECT_LE(std::abs(e.frame.frame.point(p)[k]), 250.0);
        if (std::abs(e.frame.frame.point(p)[k]) == 250.0) cut_seen = true;
      }
    }
  }
  EXPECT_TRUE(cut_seen);
}

TEST(SimRig, NoHandWhenTheDeviceCannotSeeIt) {
  Layout layout = paper_initial();
  layout.devices[2].pose.rx_deg = 180;  // looks at the floor
  SimRig rig(layout, SimConfig{});
  int lmc3 = 0, lmc3_hand = 0, others_hand = 0;
  for (int i = 0; i < 400; ++i) {
    const SimEvent e = rig.next();
    if (!e.is_frame) continue;
    if (e.frame.frame.device_id == 3) {
      ++lmc3;
      lmc3_hand += e.frame.frame.hand_present ? 1 : 0;
    } else {
      others_hand += e.frame.frame.hand_present ? 1 : 0;
    }
  }
  EXPECT_GT(lmc3, 20);
  EXPECT_EQ(lmc3_hand, 0);
  EXPECT_GT(others_hand, 100);
}

TEST(SimRig, HiddenFingersComeFromALaggingBiasedInternalModel) {
  // Vertical hand over the initial layout: the devices look at the palm's edge, so fingers hide
  // behind one another; during index flexion the reported hidden finger lags the truth.
  const Layout layout = paper_initial();
  SimConfig c = exact();
  c.occlusion = true;
  apply_motion_spec(c, "vertical/index");
  SimRig rig(layout, c);
  const VisibilityLimits limits = make_limits(VisibilityParams::from_sensor(common_sensor(layout)));
  int hidden = 0, hidden_and_off = 0, visible_exact = 0, visible = 0;
  for (int i = 0; i < 1500; ++i) {
    const SimEvent e = rig.next();
    if (!e.is_frame || !e.frame.frame.hand_present) continue;
    const HandFrame truth = rig.truth_at(e.time_s);
    const LayoutDevice& ld = layout.devices[static_cast<size_t>(e.frame.frame.device_id - 1)];
    const auto why = explain_visibility(prepare_frame(truth), DeviceView::from_device(ld), limits);
    for (int dg = 0; dg < kNumDigits; ++dg) {
      const Vec3 tip = ld.to_world(e.frame.frame.point(digit_point(dg, 4)));
      const double err = (tip - truth.point(digit_point(dg, 4))).norm();
      if (why.fingers[static_cast<size_t>(dg)].visible()) {
        ++visible;
        visible_exact += err < 1e-6 ? 1 : 0;
      } else if (dg == static_cast<int>(Digit::kIndex)) {  // the moving finger
        ++hidden;
        hidden_and_off += err > 1.0 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(hidden, 50);
  EXPECT_GT(visible, 50);
  EXPECT_EQ(visible_exact, visible);
  EXPECT_GT(hidden_and_off, hidden / 2);
}

TEST(SimRig, GroundTruthTrcMapsBackToTheTruthHand) {
  SimConfig c;
  apply_motion_spec(c, "thumb");
  const SimTrial t = generate_sim_trial(paper_initial(), c, 1.0);
  ASSERT_EQ(t.truth.size(), 100u);
  ASSERT_EQ(t.truth_trc.frame_count(), 100);
  EXPECT_EQ(t.truth_trc.marker_count(), 26);
  EXPECT_EQ(t.truth_trc.marker_names.front(), "Forearm1");
  MarkerSeries ms;
  ms.names = t.truth_trc.marker_names;
  ms.positions = t.truth_trc.positions;
  ms.rate_hz = 100;
  const HandTrack back = apply_vicon_mapping(default_vicon_mapping(), ms);
  ASSERT_EQ(back.frame_count, 100);
  for (int f = 0; f < 100; f += 7) {
    for (int p = 0; p < kNumHandPoints; ++p) {
      if (p == kPalmNormal || p == kPalmDirection) continue;
      EXPECT_LT((back.at(f, p) - t.truth[static_cast<size_t>(f)].point(p)).norm(), 1e-9) << f << " " << p;
    }
  }
}

TEST(SimRig, PoseSetFileIsPlayedInALoopWithInterpolation) {
  const HandModel model;
  PoseSet set;
  set.frames.push_back(reference_pose(model, HandOrientation::kHorizontal, HandMotion::kOpen));
  set.frames.push_back(reference_pose(model, HandOrientation::kHorizontal, HandMotion::kIndexFlexion));
  set.labels.resize(2);
  set.labels[1].motion = HandMotion::kIndexFlexion;
  set.labels[1].progress = 1.0;
  const auto path = test::scratch_dir("sim_poses") / "two.tsv";
  save_pose_set(path, set);
  SimConfig c = exact();
  apply_motion_spec(c, path.string());
  EXPECT_EQ(c.pose_set_path, path.string());
  c.pose_set_rate_hz = 10.0;
  SimRig rig(paper_initial(), c);
  const HandFrame a = rig.truth_at(0.0), mid = rig.truth_at(0.05), b = rig.truth_at(0.1), loop = rig.truth_at(0.2);
  const int tip = digit_point(Digit::kIndex, Joint::kEnd);
  EXPECT_LT((a.point(tip) - set.frames[0].point(tip)).norm(), 1e-9);
  EXPECT_LT((b.point(tip) - set.frames[1].point(tip)).norm(), 1e-9);
  EXPECT_LT((mid.point(tip) - 0.5 * (a.point(tip) + b.point(tip))).norm(), 1e-9);
  EXPECT_LT((loop.point(tip) - a.point(tip)).norm(), 1e-9);
  EXPECT_GT((a.point(tip) - b.point(tip)).norm(), 50.0);
}

TEST(SimConfig, JsonRoundTripAndErrorsNameThePath) {
  SimConfig c;
  c.seed = 99;
  apply_motion_spec(c, "vertical/wrist");
  c.noise = false;
  c.calibration = SimConfig::Calibration::kCustom;
  c.calibration_offsets_mm["LMC2"] = Eigen::Vector3d(1, 2, 3);
  c.unplugs.push_back({"LMC3", 2.0, 0.5});
  const SimConfig back = sim_config_from_json(sim_config_to_json(c), "mem");
  EXPECT_EQ(back.seed, 99u);
  EXPECT_EQ(back.orientation, HandOrientation::kVertical);
  EXPECT_EQ(back.motion, HandMotion::kWristFlexion);
  EXPECT_FALSE(back.noise);
  EXPECT_EQ(back.calibration_offsets_mm.at("LMC2"), Eigen::Vector3d(1, 2, 3));
  ASSERT_EQ(back.unplugs.size(), 1u);
  EXPECT_EQ(back.unplugs[0].slot, "LMC3");
  try {
    sim_config_from_json(nlohmann::json{{"calibration", "maybe"}}, "cfg.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/calibration"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sim_config_from_json(nlohmann::json{{"motion", "juggling"}}, "cfg.json"), Error);
  EXPECT_THROW(sim_config_from_json(nlohmann::json{{"rate_min_hz", 40}, {"rate_max_hz", 30}}, "cfg.json"), Error);
}

// Found by fuzzing: a clock start beyond int64 was converted with undefined behaviour.
TEST(SimConfig, ADeviceClockStartOutsideWholeMicrosecondsIsRefusedNamingTheKey) {
  for (const double bad : {1e19, -1.0, 9007199254740994.0}) {
    try {
      sim_config_from_json(nlohmann::json{{"device_clock_start_us", bad}}, "cfg.json");
      FAIL() << bad << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()),
                "cfg.json: at /device_clock_start_us: must be between 0 and 2^53 µs (285 years)");
    }
  }
  EXPECT_EQ(sim_config_from_json(nlohmann::json{{"device_clock_start_us", 9007199254740992.0}}, "cfg.json")
                .device_clock_start_us,
            9007199254740992LL);
}

TEST(SimConfig, UnknownKeysAreRejectedWithTheirPath) {
  // A misspelt switch must not leave the behaviour on in silence.
  try {
    sim_config_from_json(nlohmann::json{{"noize", false}}, "cfg.json");
    FAIL() << "\"noize\" was accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cfg.json"), std::string::npos) << what;
    EXPECT_NE(what.find("/noize"), std::string::npos) << what;
    EXPECT_NE(what.find("noise"), std::string::npos) << "the message lists the known keys: " << what;
  }
  try {
    sim_config_from_json(
        nlohmann::json::parse(R"({"unplugs": [{"slot": "LMC1", "at_s": 1}, {"slot": "LMC2", "at": 2}]})"), "cfg.json");
    FAIL() << "\"at\" inside an unplug was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/unplugs/1/at"), std::string::npos) << e.what();
  }
  // Every key the simulator writes into a sidecar reads back.
  EXPECT_NO_THROW(sim_config_from_json(sim_config_to_json(SimConfig{}), "mem"));
}

}  // namespace sim_test
}  // namespace lmc::devices
