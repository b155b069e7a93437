// `lmc process` / `lmc report` end to end on a small synthetic session, including every malformed
// input the issue lists: each gives a clear per-trial message and the rest of the session still
// processes.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/c3d.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/trc.h"
#include "core/io/vicon_mapping.h"
#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace process_test {

using lmc::test::CliRun;

// Both streams together: these tests look for per-trial messages wherever they were printed.
CliRun run(const std::string& args) {
  return lmc::test::run_lmc(args);
}

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A plausible right hand 200 mm above the table, palm down, fingers towards −z (world frame).
HandFrame world_hand(double t) {
  HandFrame h;
  h.hand_present = true;
  const double y = 200.0 + 3.0 * std::sin(t);
  h.point(kPalm) = Vec3(0, y, 0);
  h.point(kPalmNormal) = Vec3(0, -1, 0);
  h.point(kPalmDirection) = Vec3(0, 0, -1);
  h.point(kElbow) = Vec3(0, y + 20, 250);
  h.point(kWrist) = Vec3(0, y, 60);
  for (int d = 0; d < kNumDigits; ++d) {
    const double x = d == 0 ? -50.0 : -30.0 + 20.0 * (d - 1);
    double z = d == 0 ? 20.0 : -20.0;
    h.point(digit_point(d, 0)) = Vec3(x, y, d == 0 ? 20.0 : 40.0);
    for (int j = 1; j < kJointsPerDigit; ++j) {
      h.point(digit_point(d, j)) = Vec3(x, y - 2.0 * j, z);
      z -= 25.0 - 3.0 * j;
    }
  }
  if (true) h.point(digit_point(0, 1)) = h.point(digit_point(0, 0));
  return h;
}

// Raw four-device recording of `seconds`, device frames from the paper-initial layout.
LmcRecording raw_recording(const Layout& layout, double seconds, int devices) {
  LmcRecording rec;
  rec.kind = RecordingKind::kRaw;
  for (int d = 0; d < devices; ++d) {
    const LayoutDevice& dev = layout.devices[static_cast<size_t>(std::min(d, layout.device_count() - 1))];
    const Eigen::Matrix3d r = dev.pose.rotation();
    const Eigen::Vector3d shift = dev.pose.translation() + dev.offset_mm;
    const double period = 1.0 / (25.0 + 2.0 * d);
    for (double t = 0.003 * d; t < seconds; t += period) {
      HandFrame w = world_hand(t);
      HandFrame f = w;
      f.device_id = d + 1;
      f.timestamp_us = 5'000'000 + static_cast<std::int64_t>(t * 1e6);
      for (int i = 0; i < kNumHandPoints; ++i) {
        f.point(i) = (i == kPalmNormal || i == kPalmDirection) ? Vec3(r.transpose() * w.point(i))
                                                               : Vec3(r.transpose() * (w.point(i) - shift));
      }
      rec.rows.push_back(f);
    }
  }
  return rec;
}

TrcData vicon_trc(double seconds, const ViconMapping& m) {
  TrcData trc;
  trc.marker_names = m.markers;
  const int frames = static_cast<int>(std::lround(seconds * 100));
  for (int f = 0; f < frames; ++f) {
    const HandFrame h = world_hand(f * 0.01);
    // Invert the mapping's one-to-one markers (enough for this test): marker = the point it feeds.
    std::vector<Eigen::Vector3d> row(m.markers.size(), Eigen::Vector3d::Zero());
    for (int i = 0; i < kNumHandPoints; ++i) {
      for (const auto& [mi, w] : m.terms[static_cast<size_t>(i)]) {
        if (w == 1.0) row[static_cast<size_t>(mi)] = h.point(i);
        if (w == 0.5) row[static_cast<size_t>(mi)] = h.point(i);
      }
    }
    trc.frame_numbers.push_back(f + 1);
    trc.times_s.push_back(f * 0.01);
    trc.positions.push_back(row);
  }
  return trc;
}

class ProcessCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::scratch_dir("process_cli");
    session_ = dir_ / "session";
    std::filesystem::create_directories(session_);
    layout_ = load_layout(test::asset_file("layouts/paper-initial.json"));
    mapping_ = load_vicon_mapping(test::asset_file("mappings/vicon-26-to-lmc.json"));
  }
  void add_trial(const std::string& name, int devices, double vicon_seconds, int nan_marker = -1) {
    save_lmc_recording(session_ / ("LMC_" + name + ".raw.txt"), raw_recording(layout_, 2.0, devices));
    if (vicon_seconds <= 0) return;
    TrcData trc = vicon_trc(vicon_seconds, mapping_);
    if (nan_marker >= 0) {
      for (auto& row : trc.positions) row[static_cast<size_t>(nan_marker)] = Eigen::Vector3d::Constant(std::nan(""));
    }
    save_trc(session_ / (name + ".trc"), trc);
  }
  std::filesystem::path dir_, session_;
  Layout layout_;
  ViconMapping mapping_;
};

TEST_F(ProcessCli, SessionWithMalformedTrialsReportsEachAndProcessesTheRest) {
  add_trial("Naiv_Static101", 4, 2.0);
  add_trial("Naiv_Static102", 4, 0.5);      // Vicon shorter than a second
  add_trial("Naiv_Static103", 4, 2.0, 12);  // Index3_1 missing throughout
  add_trial("Naiv_Static104", 4, 0.0);      // no Vicon file
  add_trial("Naiv_Static105", 5, 2.0);      // five devices, layout has four
  const auto out = dir_ / "out";
  const CliRun r = run("process " + session_.string() + " --method reference -o " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.all();
  EXPECT_NE(r.all().find("ok      Naiv_Static101"), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("FAILED  Naiv_Static102: "), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("Naiv_Static102.trc: only 50 frames (0.50 s at 100 Hz)"), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("must last at least 1.0 s"), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("FAILED  Naiv_Static103"), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("'Index3_1' is missing in every frame"), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("ok      Naiv_Static104"), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("no Vicon file"), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("FAILED  Naiv_Static105"), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("has only 4"), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("processed 2 of 5 trial(s)"), std::string::npos) << r.all();

  // Outputs of the good trial.
  for (const char* suffix : {".results.txt", ".measures.tsv", ".fused.txt", ".summary.json"}) {
    EXPECT_TRUE(std::filesystem::exists(out / (std::string("Naiv_Static101") + suffix))) << suffix;
  }
  const auto summary = nlohmann::json::parse(read_text(out / "Naiv_Static101.summary.json"));
  EXPECT_EQ(summary["method"], "reference");
  EXPECT_EQ(summary["tag"]["motion"], "static");
  // The synthetic hand is exact in both systems: finger lengths agree to well under a millimetre.
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(summary["comparison"]["finger_mean_diff_mm"][k].get<double>(), 0.0, 0.5) << k;
  // The fused file reads back as a resampled recording.
  const LmcRecording fused = read_lmc_recording(out / "Naiv_Static101.fused.txt");
  EXPECT_EQ(fused.kind, RecordingKind::kResampled);
  EXPECT_EQ(static_cast<int>(fused.rows.size()), summary["frames"].get<int>());
  const auto session = nlohmann::json::parse(read_text(out / "session.json"));
  ASSERT_EQ(session["trials"].size(), 5u);
  EXPECT_FALSE(session["trials"][1]["ok"].get<bool>());

  // lmc report over it.
  const CliRun rep = run("report " + out.string() + " -o " + (dir_ / "report").string());
  EXPECT_EQ(rep.exit_code, 0) << rep.all();
  const std::string md = read_text(dir_ / "report" / "report.md");
  EXPECT_NE(md.find("2 trial(s), 1 with Vicon"), std::string::npos) << md;
  const std::string vis = read_text(dir_ / "report" / "visibility.csv");
  EXPECT_NE(vis.find("initial,horizontal,static,LMC1"), std::string::npos) << vis;
}

TEST_F(ProcessCli, AnOutputThatCannotBeWrittenFailsItsTrialByName) {
  add_trial("Naiv_Static101", 4, 2.0);
  add_trial("Naiv_Static102", 4, 2.0);
  const auto out = dir_ / "out";
  // A folder where one trial's fused file should go: the rename over it fails on the committer's
  // thread, after the trial itself was processed.
  std::filesystem::create_directories(out / "Naiv_Static102.fused.txt");
  const CliRun r = run("process " + session_.string() + " --method reference -o " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.all();
  EXPECT_NE(r.all().find("ok      Naiv_Static101"), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("FAILED  Naiv_Static102: "), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("Naiv_Static102.fused.txt"), std::string::npos) << r.all();
  EXPECT_NE(r.all().find("processed 1 of 2 trial(s)"), std::string::npos) << r.all();
  const auto session = nlohmann::json::parse(read_text(out / "session.json"));
  ASSERT_EQ(session["trials"].size(), 2u);
  EXPECT_TRUE(session["trials"][0]["ok"].get<bool>());
  EXPECT_FALSE(session["trials"][1]["ok"].get<bool>());
  EXPECT_NE(session["trials"][1]["error"].get<std::string>().find("rename failed"), std::string::npos);
  // The other trial's files are all there, and no temporary file is left beside them.
  EXPECT_TRUE(std::filesystem::exists(out / "Naiv_Static101.fused.txt"));
  for (const auto& e : std::filesystem::directory_iterator(out)) {
    EXPECT_NE(e.path().filename().string().front(), '.') << e.path();
  }
}

TEST_F(ProcessCli, SingleTrialWithExplicitViconAndBadArguments) {
  add_trial("Naiv_Index101", 4, 2.0);
  const auto out = dir_ / "one";
  const CliRun r = run("process " + (session_ / "LMC_Naiv_Index101.raw.txt").string() + " --vicon " +
                       (session_ / "Naiv_Index101.trc").string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.all();
  EXPECT_NE(r.all().find("processed 1 of 1 trial(s) (default method)"), std::string::npos) << r.all();
  const std::string text = read_text(out / "Naiv_Index101.results.txt");
  EXPECT_NE(text.find("Visibility LMC4"), std::string::npos);
  EXPECT_NE(text.find("VICON Data"), std::string::npos);

  // The same trial with its Vicon data as C3D (our writer, DEC integer storage) gives the same numbers.
  const TrcData trc = read_trc(session_ / "Naiv_Index101.trc");
  C3dData c3d;
  c3d.labels = trc.marker_names;
  c3d.positions = trc.positions;
  C3dWriteOptions wo;
  wo.processor = C3dProcessor::kDec;
  wo.float_storage = false;
  wo.int_scale = 0.01;
  const auto c3d_dir = dir_ / "c3d";
  std::filesystem::create_directories(c3d_dir);
  std::filesystem::copy_file(session_ / "LMC_Naiv_Index101.raw.txt", c3d_dir / "LMC_Naiv_Index101.raw.txt");
  save_c3d(c3d_dir / "Naiv_Index101.c3d", c3d, wo);
  const CliRun rc = run("process " + c3d_dir.string() + " -o " + (dir_ / "one_c3d").string());
  EXPECT_EQ(rc.exit_code, 0) << rc.all();
  const auto a = nlohmann::json::parse(read_text(out / "Naiv_Index101.summary.json"));
  const auto b = nlohmann::json::parse(read_text(dir_ / "one_c3d" / "Naiv_Index101.summary.json"));
  EXPECT_NE(b["vicon_file"].get<std::string>().find(".c3d"), std::string::npos);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(a["vicon"]["finger_mean_mm"][k].get<double>(), b["vicon"]["finger_mean_mm"][k].get<double>(), 0.01)
        << k;
  }

  const CliRun missing = run("process " + (dir_ / "nope").string() + " -o " + out.string());
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.all().find("no such file or folder"), std::string::npos) << missing.all();
  const CliRun bad_method = run("process " + session_.string() + " --method magic -o " + out.string());
  EXPECT_NE(bad_method.exit_code, 0);
  const CliRun no_layout = run("process " + (session_ / "LMC_Naiv_Index101.raw.txt").string() +
                               " --layout does-not-exist -o " + out.string());
  EXPECT_EQ(no_layout.exit_code, 2) << no_layout.all();
  EXPECT_NE(no_layout.all().find("FAILED  Naiv_Index101"), std::string::npos) << no_layout.all();
}

}  // namespace process_test
}  // namespace lmc
