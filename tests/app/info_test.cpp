// Runs the real `lmc info` binary (lmc::test::cli_path()) on the study's files and on bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/lmc_recording.h"
#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace {

using lmc::test::CliRun;
using lmc::test::read_text_file;
using ::testing::HasSubstr;

// The whitespace-separated words of the output line whose first word is `first` (empty when
// there is none). std::regex is avoided: GCC 12 warns inside <regex> at -O1 (breaks -Werror).
std::vector<std::string> row_starting_with(const std::string& text, const std::string& first) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string x; words >> x;) w.push_back(x);
    if (!w.empty() && w[0] == first) return w;
  }
  return {};
}

CliRun run_in(const std::string& args, const std::string& scratch_name) {
  return lmc::test::run_lmc(args, lmc::test::scratch_dir(scratch_name));
}

TEST(LmcInfo, RawRecordingText) {
  const auto path = lmc::test::reference_file("acquisition/LMC_Naiv_Static101.raw.txt");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const CliRun r = run_in("info " + lmc::test::shell_quote(path.string()), "info_raw_text");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("LMC recording (raw)"));
  EXPECT_THAT(r.out, HasSubstr("devices:    4 (1, 2, 3, 4)"));
  EXPECT_THAT(r.out, HasSubstr("rows:       500"));
  // One table row per device: id, then its row count.
  const std::pair<int, int> expected[] = {{1, 118}, {2, 121}, {3, 131}, {4, 130}};
  for (const auto& [id, rows] : expected) {
    const auto row = row_starting_with(r.out, std::to_string(id));
    ASSERT_GE(row.size(), 3u) << "no table row for device " << id << " in:\n" << r.out;
    EXPECT_EQ(row[1], std::to_string(rows)) << r.out;
  }
  EXPECT_THAT(r.out, HasSubstr("warnings:   none"));
}

TEST(LmcInfo, RawRecordingJson) {
  const auto path = lmc::test::reference_file("acquisition/LMC_Naiv_Static101.raw.txt");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const CliRun r = run_in("info --json " + lmc::test::shell_quote(path.string()), "info_raw_json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("type"), "recording");
  EXPECT_EQ(j.at("variant"), "raw");
  EXPECT_EQ(j.at("rows"), 500);
  EXPECT_EQ(j.at("device_count"), 4);
  EXPECT_EQ(j.at("device_ids"), nlohmann::json({1, 2, 3, 4}));
  const int rows[] = {118, 121, 131, 130};
  ASSERT_EQ(j.at("devices").size(), 4u);
  int hand_rows = 0;
  for (int i = 0; i < 4; ++i) {
    const auto& d = j.at("devices")[static_cast<size_t>(i)];
    EXPECT_EQ(d.at("id"), i + 1);
    EXPECT_EQ(d.at("rows"), rows[i]);
    hand_rows += d.at("hand_rows").get<int>();
    const double median = d.at("rate_median_hz").get<double>();
    EXPECT_LE(d.at("rate_p5_hz").get<double>(), median);
    EXPECT_GE(d.at("rate_p95_hz").get<double>(), median);
    // ~120 rows in ~5.1 s: a median between 15 and 60 Hz, as the table shows.
    EXPECT_GT(median, 15.0);
    EXPECT_LT(median, 60.0);
  }
  EXPECT_EQ(hand_rows, 500 - 32);  // 32 lines end after the timestamp (no hand)
  EXPECT_EQ(j.at("hand_rows"), hand_rows);
  EXPECT_NEAR(j.at("duration_s").get<double>(), 5.119, 0.001);
  EXPECT_TRUE(j.at("warnings").empty());
}

TEST(LmcInfo, TrcJson) {
  const auto path = lmc::test::reference_file("validation/Naiv_Static101.trc");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const CliRun r = run_in("info --json " + lmc::test::shell_quote(path.string()), "info_trc_json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("type"), "trc");
  EXPECT_EQ(j.at("markers"), 26);
  EXPECT_EQ(j.at("frames"), 100);
  EXPECT_EQ(j.at("units"), "mm");
  EXPECT_EQ(j.at("data_rate_hz"), 100.0);
  EXPECT_EQ(j.at("marker_stats")[0].at("name"), "Forearm1");
  EXPECT_EQ(j.at("missing_fraction"), 0.0);
  ASSERT_EQ(j.at("warnings").size(), 1u);
  EXPECT_THAT(j.at("warnings")[0].get<std::string>(), HasSubstr("NumFrames 511"));
}

TEST(LmcInfo, TrcWithGapsText) {
  const auto path = lmc::test::source_dir() / "tests/fixtures/io/trc_missing_markers.trc";
  const CliRun r = run_in("info " + lmc::test::shell_quote(path.string()), "info_trc_text");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("markers:    2"));
  EXPECT_THAT(r.out, HasSubstr("frames:     4"));
  EXPECT_EQ(row_starting_with(r.out, "Wrist"), (std::vector<std::string>{"Wrist", "50.0"})) << r.out;  // 2 of 4 missing
  EXPECT_EQ(row_starting_with(r.out, "Tip"), (std::vector<std::string>{"Tip", "25.0"})) << r.out;
}

TEST(LmcInfo, LayoutJson) {
  const auto path = lmc::test::source_dir() / "assets/layouts/paper-initial.json";
  const CliRun r = run_in("info --json " + lmc::test::shell_quote(path.string()), "info_layout_json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("type"), "layout");
  EXPECT_EQ(j.at("device_count"), 4);
  EXPECT_EQ(j.at("devices")[0].at("slot"), "LMC1");
  EXPECT_EQ(j.at("devices")[0].at("pose").at("x"), -60.0);  // docs/algorithms/frames.md table
  EXPECT_EQ(j.at("devices")[1].at("offset_mm")[0], -12.92);
}

// A row whose timestamp jumps by 10^4 s was reported as a 10,000 s recording without
// a word; `lmc process` refuses such a file, and `lmc info` says why beforehand.
TEST(LmcInfo, WarnsAboutImplausibleDuration) {
  const auto dir = lmc::test::scratch_dir("info_time_jump_input");
  const auto path = dir / "jump.raw.txt";
  std::string text = lmc::lmc_recording_header(lmc::RecordingKind::kRaw);
  lmc::HandFrame f;
  f.device_id = 1;
  f.frame_rate_hz = 30.0;
  for (int k = 0; k < 10; ++k) {
    f.frame_id = k;
    f.timestamp_us = 33'333 * k;
    text += lmc::format_lmc_row(f, lmc::RecordingKind::kRaw);
  }
  f.timestamp_us = 10'000'000'000;
  text += lmc::format_lmc_row(f, lmc::RecordingKind::kRaw);
  std::ofstream(path) << text;
  const CliRun r = run_in("info " + lmc::test::shell_quote(path.string()), "info_time_jump");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("is implausible for 11 rows"));
  EXPECT_THAT(r.out, HasSubstr("a timestamp likely jumps"));
}

TEST(LmcInfo, BadFileExitsOneWithFileNameOnStderr) {
  const auto path = lmc::test::source_dir() / "tests/fixtures/io/raw_point_garbage.txt";
  const CliRun r = run_in("info " + lmc::test::shell_quote(path.string()), "info_bad");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_THAT(r.err, HasSubstr(path.string() + ":3:94:"));
  EXPECT_THAT(r.err, HasSubstr("'3x'"));
}

TEST(LmcInfo, UnknownAndBinaryFilesExitOne) {
  const auto dir = lmc::test::scratch_dir("info_unknown_inputs");
  {
    std::ofstream(dir / "notes.txt") << "hello\n";
    std::ofstream bin(dir / "blob.dat", std::ios::binary);
    bin.write("\x89PNG\r\n\x1a\n\0\0", 10);
  }
  CliRun r = run_in("info " + lmc::test::shell_quote((dir / "notes.txt").string()), "info_unknown_a");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("notes.txt:1:1: unrecognised file"));
  r = run_in("info " + lmc::test::shell_quote((dir / "blob.dat").string()), "info_unknown_b");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("blob.dat:1:1: invalid UTF-8"));
  r = run_in("info " + lmc::test::shell_quote((dir / "missing.txt").string()), "info_unknown_c");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("missing.txt"));
}

}  // namespace
