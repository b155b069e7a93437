// `lmc export c3d|trc` on simulated trials: the files read back with our own readers equal the
// processed trial (fused hand, each controller realigned, Vicon markers) to 1e-3 mm with missing
// points missing, labels as documented, the C3D's parameters in place, `lmc info` describes the
// C3D, an existing output is refused without --force, a trial without Vicon exports and says so,
// and an input that cannot be read is left out with a note while the others are written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/export/trial_points.h"
#include "core/hand/hand_frame.h"
#include "core/io/c3d.h"
#include "core/io/trc.h"
#include "core/processing/batch.h"
#include "tests/support/cli_runner.h"
#include "tests/support/quick_session.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace export_cli_test {  // named: test files share unity batches

namespace fs = std::filesystem;
using test::CliRun;
using test::run_lmc;
using test::shell_quote;

bool is_missing(const Eigen::Vector3d& p) {
  return p.array().isNaN().any();
}

// Compares one exported point series with the processed one; returns how many frames were missing.
int expect_series(const std::vector<std::vector<Eigen::Vector3d>>& file, int column, const std::vector<Vec3>& want,
                  const std::string& what) {
  int gaps = 0;
  EXPECT_EQ(file.size(), want.size()) << what;
  for (size_t f = 0; f < std::min(file.size(), want.size()); ++f) {
    const Eigen::Vector3d& got = file[f][static_cast<size_t>(column)];
    if (is_missing(want[f])) {
      EXPECT_TRUE(is_missing(got)) << what << " frame " << f;
      ++gaps;
    } else {
      EXPECT_LT((got - want[f]).cwiseAbs().maxCoeff(), 1e-3) << what << " frame " << f;
    }
  }
  return gaps;
}

std::vector<Vec3> track_series(const HandTrack& t, int point, int frames) {
  std::vector<Vec3> s;
  for (int f = 0; f < frames; ++f) s.push_back(f < t.frame_count ? t.at(f, point) : Vec3::Constant(std::nan("")));
  return s;
}

// Every exported series of `labels`/`positions` against the trial processed here in the test.
void expect_processed_trial(const std::vector<std::string>& labels,
                            const std::vector<std::vector<Eigen::Vector3d>>& positions, const TrialSources& job,
                            const std::string& what) {
  const TrialAnalysis r = process_sources_in_full(job, BatchOptions{});
  const int frames = r.world.frame_count;
  ASSERT_EQ(static_cast<int>(positions.size()), frames) << what;
  auto column = [&](const std::string& label) {
    const auto it = std::find(labels.begin(), labels.end(), label);
    EXPECT_NE(it, labels.end()) << what << ": no label " << label;
    return static_cast<int>(it - labels.begin());
  };
  int device_gaps = 0;
  for (const int i : exported_hand_points()) {
    expect_series(positions, column("F_" + landmark_name(i)), track_series(r.fused, i, frames),
                  what + " F_" + landmark_name(i));
    for (const auto& d : r.world.devices) {
      const std::string label = "LMC" + std::to_string(d.device_id) + "_" + landmark_name(i);
      device_gaps += expect_series(positions, column(label), track_series(d.track, i, frames), what + " " + label);
    }
  }
  EXPECT_EQ(r.world.devices.size(), 4u) << what;
  EXPECT_GT(device_gaps, 0) << what << ": the simulated controllers lose the hand now and then";
  if (job.vicon) {
    const MarkerSeries m = load_vicon_markers(*job.vicon);
    ASSERT_FALSE(m.names.empty());
    for (size_t k = 0; k < m.names.size(); ++k) {
      std::vector<Vec3> want;
      for (int f = 0; f < frames; ++f) {
        want.push_back(static_cast<size_t>(f) < m.positions.size() ? m.positions[static_cast<size_t>(f)][k]
                                                                   : Vec3::Constant(std::nan("")));
      }
      expect_series(positions, column("V_" + export_label(m.names[k])), want, what + " Vicon " + m.names[k]);
    }
    EXPECT_EQ(labels.size(), 28u * 5u + m.names.size()) << what;
  } else {
    EXPECT_EQ(labels.size(), 28u * 5u) << what;
  }
}

TEST(LmcExport, WritesC3dAndTrcEqualToTheProcessedTrial) {
  const fs::path dir = test::scratch_dir("lmc_export");
  // One trial with its simulated Vicon (truth) file, one without.
  CliRun r = run_lmc(
      "record --backend sim --fast --quiet --seconds 3 --seed 7 --layout paper-initial --trial Naiv_Index101 "
      "--motion horizontal/index -o " +
          shell_quote((dir / "S01").string()),
      dir / "l");
  ASSERT_EQ(r.exit_code, 0) << r.all();
  r = run_lmc(
      "record --backend sim --fast --quiet --seconds 2 --seed 8 --layout paper-initial --trial Naiv_Index102 "
      "--motion horizontal/index -o " +
          shell_quote((dir / "S02").string()),
      dir / "l");
  ASSERT_EQ(r.exit_code, 0) << r.all();
  ASSERT_TRUE(fs::remove(dir / "S02" / "Naiv_Index102.trc"));

  const fs::path out = dir / "out";
  const std::string inputs =
      shell_quote((dir / "S01" / "LMC_Naiv_Index101.raw.txt").string()) + " " + shell_quote((dir / "S02").string());
  r = run_lmc("export c3d " + inputs + " -o " + shell_quote(out.string()), dir / "l");
  ASSERT_EQ(r.exit_code, 0) << r.all();
  EXPECT_NE(r.out.find("exported 2 trial(s) as C3D"), std::string::npos) << r.all();
  EXPECT_NE(r.out.find("Naiv_Index101.c3d ("), std::string::npos) << r.all();
  EXPECT_NE(r.out.find("with Vicon"), std::string::npos) << r.all();
  EXPECT_NE(r.out.find("note: Naiv_Index102: no Vicon file"), std::string::npos) << r.all();
  std::vector<fs::path> written;
  for (const auto& e : fs::directory_iterator(out)) written.push_back(e.path().filename());
  std::sort(written.begin(), written.end());
  EXPECT_EQ(written, (std::vector<fs::path>{"Naiv_Index101.c3d", "Naiv_Index102.c3d"}));

  const auto jobs1 = discover_trials(dir / "S01", std::nullopt);
  const auto jobs2 = discover_trials(dir / "S02", std::nullopt);
  ASSERT_EQ(jobs1.size(), 1u);
  ASSERT_EQ(jobs2.size(), 1u);
  ASSERT_TRUE(jobs1[0].vicon.has_value());
  ASSERT_FALSE(jobs2[0].vicon.has_value());

  const C3dData c = read_c3d(out / "Naiv_Index101.c3d");
  EXPECT_LT(c.point_scale, 0.0);
  EXPECT_DOUBLE_EQ(c.point_rate_hz, 100.0);
  EXPECT_EQ(c.units, "mm");
  EXPECT_EQ(c.manufacturer_version, LMC_VERSION);
  EXPECT_EQ(c.labels.at(0), "F_Palm");
  EXPECT_EQ(c.labels.at(static_cast<size_t>(28 + 28 + 11)), "LMC2_Index_Dist");
  EXPECT_EQ(c.descriptions.at(11), "fused hand: index finger last joint (Finger2_Dist)");
  expect_processed_trial(c.labels, c.positions, jobs1[0], "C3D with Vicon");
  expect_processed_trial(read_c3d(out / "Naiv_Index102.c3d").labels, read_c3d(out / "Naiv_Index102.c3d").positions,
                         jobs2[0], "C3D without Vicon");

  // TRC, the same points.
  const fs::path trc_out = dir / "trc";
  r = run_lmc("export trc " + shell_quote((dir / "S01").string()) + " -o " + shell_quote(trc_out.string()), dir / "l");
  ASSERT_EQ(r.exit_code, 0) << r.all();
  const TrcData trc = read_trc(trc_out / "Naiv_Index101.trc");
  EXPECT_EQ(trc.units, "mm");
  EXPECT_DOUBLE_EQ(trc.data_rate_hz, 100.0);
  EXPECT_TRUE(trc.warnings.empty());
  expect_processed_trial(trc.marker_names, trc.positions, jobs1[0], "TRC");

  // lmc info describes the exported C3D.
  r = run_lmc("info " + shell_quote((out / "Naiv_Index101.c3d").string()), dir / "l");
  ASSERT_EQ(r.exit_code, 0) << r.all();
  EXPECT_NE(r.out.find("type:       C3D motion file"), std::string::npos) << r.out;
  EXPECT_GT(c.frame_count(), 250);  // a 3 s trial at 100 Hz
  EXPECT_NE(r.out.find("frames:     " + std::to_string(c.frame_count())), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("LMC4_Pinky_End"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(std::string("version ") + LMC_VERSION), std::string::npos) << r.out;
  r = run_lmc("info --json " + shell_quote((out / "Naiv_Index101.c3d").string()), dir / "l");
  ASSERT_EQ(r.exit_code, 0) << r.all();
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("type"), "c3d");
  EXPECT_EQ(j.at("frames"), c.frame_count());
  EXPECT_EQ(j.at("storage"), "float");
  EXPECT_EQ(j.at("markers"), static_cast<int>(c.labels.size()));

  // An existing output is refused, and nothing is touched; --force replaces it.
  const auto before = fs::last_write_time(out / "Naiv_Index101.c3d");
  r = run_lmc("export c3d " + inputs + " -o " + shell_quote(out.string()), dir / "l");
  EXPECT_EQ(r.exit_code, 1) << r.all();
  EXPECT_NE(r.err.find("use --force"), std::string::npos) << r.all();
  EXPECT_NE(r.err.find("Naiv_Index101.c3d"), std::string::npos) << r.all();
  EXPECT_EQ(fs::last_write_time(out / "Naiv_Index101.c3d"), before);
  r = run_lmc("export c3d " + inputs + " --force -o " + shell_quote(out.string()), dir / "l");
  EXPECT_EQ(r.exit_code, 0) << r.all();

  // An input that cannot be read is left out and said; the rest is written (exit code 2).
  const fs::path partial = dir / "partial";
  r = run_lmc("export trc " + shell_quote((dir / "S02").string()) + " " + shell_quote((dir / "nowhere").string()) +
                  " -o " + shell_quote(partial.string()),
              dir / "l");
  EXPECT_EQ(r.exit_code, 2) << r.all();
  EXPECT_NE(r.out.find("note: left out " + (dir / "nowhere").string()), std::string::npos) << r.all();
  EXPECT_NE(r.out.find("1 left out"), std::string::npos) << r.all();
  EXPECT_TRUE(fs::exists(partial / "Naiv_Index102.trc"));
}

// A session folder whose one trial is malformed (its recording cut to the header) and whose other
// trial lost its Vicon file: the good trial is written with the hands only, the other is left out,
// both are said, and the exit code is 2.
TEST(LmcExport, APartialSessionExportsWhatItCanAndSaysWhatItLeftOut) {
  const fs::path dir = test::scratch_dir("lmc_export_partial");
  const fs::path s = dir / "S01";
  ASSERT_EQ(test::record_quick_session(s, dir / "l", "S01", 1), "");
  const fs::path broken = s / "LMC_Naiv_Static101.raw.txt";
  const std::string text = test::read_text_file(broken);
  ASSERT_TRUE(fs::exists(s / "Naiv_Index101.trc"));
  {
    std::ofstream cut(broken, std::ios::trunc);
    cut << text.substr(0, text.find('\n') + 1);
  }
  fs::remove(s / "Naiv_Index101.trc");
  const fs::path out = dir / "out";
  const CliRun r = run_lmc("export trc " + shell_quote(s.string()) + " -o " + shell_quote(out.string()), dir / "l");
  EXPECT_EQ(r.exit_code, 2) << r.all();
  EXPECT_NE(r.out.find("note: left out Naiv_Static101: the LMC recording has no data rows"), std::string::npos)
      << r.all();
  EXPECT_NE(r.out.find("note: Naiv_Index101: no Vicon file"), std::string::npos) << r.all();
  EXPECT_NE(r.out.find("exported 1 trial(s) as TRC"), std::string::npos) << r.all();
  std::vector<fs::path> written;
  for (const auto& e : fs::directory_iterator(out)) written.push_back(e.path().filename());
  EXPECT_EQ(written, (std::vector<fs::path>{"Naiv_Index101.trc"}));
  const TrcData trc = read_trc(out / "Naiv_Index101.trc");
  EXPECT_EQ(trc.marker_count(), 5 * 28);
  EXPECT_EQ(trc.marker_names.front(), "F_Palm");
  EXPECT_EQ(trc.marker_names.back(), "LMC4_Pinky_End");
}

}  // namespace export_cli_test
}  // namespace lmc
