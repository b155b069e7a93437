// Limits every reader of outside input keeps: a 2 GB file of garbage, a 200 MB file
// of one line, a header that claims 10⁹ frames and JSON nested 10⁵ deep each end in an
// lmc::Error that names the file — never an allocation failure, a stack overflow or a hang — and
// a refused file costs next to no memory. The big files are sparse (no disk is written), and the
// memory check reads the process's peak resident size before and after.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/common/error.h"
#include "core/io/c3d.h"
#include "core/io/json_checked.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/pose_set_tsv.h"
#include "core/io/recorder_sidecar.h"
#include "core/io/trc.h"
#include "core/session/session_journal.h"
#include "tests/support/reference_data.h"

namespace input_limits_test {

namespace fs = std::filesystem;

long peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024;  // Linux reports kilobytes
}

// A file of `bytes` whose first bytes are `prefix` and the rest zeros, without writing the zeros.
fs::path sparse_file(const fs::path& dir, const std::string& name, std::uintmax_t bytes, const std::string& prefix) {
  const fs::path p = dir / name;
  {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out << prefix;
  }
  fs::resize_file(p, bytes);
  return p;
}

// Runs `read`, which must throw lmc::Error naming `path` (its message holds `expect`), and must
// not raise the peak memory by more than 64 MB.
void expect_refused_cheaply(const fs::path& path, const std::function<void()>& read, const std::string& expect) {
  const long before = peak_rss_mb();
  try {
    read();
    ADD_FAILURE() << path << " was accepted";
  } catch (const lmc::Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path.string()), std::string::npos) << what;
    EXPECT_NE(what.find(expect), std::string::npos) << what;
  }
  EXPECT_LT(peak_rss_mb() - before, 64) << path << " cost memory out of proportion to what was read";
}

constexpr std::uintmax_t kTwoGb = std::uintmax_t{2} << 30;
constexpr std::uintmax_t k200Mb = std::uintmax_t{200} << 20;

TEST(InputLimits, TwoGigabytesOfGarbageAreRefusedAtTheFirstLineByEveryReader) {
  const auto dir = lmc::test::scratch_dir("input_limits_garbage");
  const auto zeros = sparse_file(dir, "zeros.txt", kTwoGb, "");
  expect_refused_cheaply(
      zeros, [&] { (void)lmc::read_lmc_recording(zeros); }, "NUL byte");
  expect_refused_cheaply(
      zeros, [&] { (void)lmc::read_trc(zeros); }, "NUL byte");
  expect_refused_cheaply(
      zeros, [&] { (void)lmc::load_pose_set(zeros); }, "NUL byte");
  expect_refused_cheaply(
      zeros, [&] { (void)lmc::read_c3d(zeros); }, "not a C3D file");
  expect_refused_cheaply(
      zeros, [&] { (void)lmc::read_json_file(zeros); }, "MB");
  expect_refused_cheaply(
      zeros, [&] { (void)lmc::load_layout(zeros); }, "MB");
  expect_refused_cheaply(
      zeros, [&] { (void)lmc::read_recorder_sidecar(zeros); }, "MB");
  expect_refused_cheaply(
      zeros, [&] { (void)lmc::read_journal(zeros); }, "MB");
  // Printable garbage with line breaks: the header check refuses it before the rest is read.
  const auto words = sparse_file(dir, "words.txt", kTwoGb, "lorem ipsum\tdolor\nsit amet\n");
  expect_refused_cheaply(
      words, [&] { (void)lmc::read_lmc_recording(words); }, "Device ID");
  expect_refused_cheaply(
      words, [&] { (void)lmc::read_trc(words); }, "PathFileType");
  expect_refused_cheaply(
      words, [&] { (void)lmc::load_pose_set(words); }, "not a pose set");
  fs::remove_all(dir);
}

TEST(InputLimits, AFileOfOneLongLineIsRefusedWithoutReadingIt) {
  const auto dir = lmc::test::scratch_dir("input_limits_one_line");
  const std::string letters(1 << 17, 'a');
  const auto one_line = sparse_file(dir, "one_line.txt", k200Mb, letters);
  expect_refused_cheaply(
      one_line, [&] { (void)lmc::read_lmc_recording(one_line); }, "longer than 64 KB");
  expect_refused_cheaply(
      one_line, [&] { (void)lmc::read_trc(one_line); }, "longer than 64 KB");
  expect_refused_cheaply(
      one_line, [&] { (void)lmc::load_pose_set(one_line); }, "longer than 64 KB");
  fs::remove_all(dir);
}

TEST(InputLimits, JsonNestedAHundredThousandDeepIsAnErrorNotAStackOverflow) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_THROW((void)lmc::parse_json_text(deep, "deep.json"), lmc::Error);
  const auto dir = lmc::test::scratch_dir("input_limits_deep");
  const fs::path sidecar = dir / "deep.session.json";
  {
    std::ofstream out(sidecar);
    out << R"({"format": "lmc-session", "extra": )" << deep << "}";
  }
  expect_refused_cheaply(
      sidecar, [&] { (void)lmc::read_recorder_sidecar(sidecar); }, "nested deeper than");
  const fs::path layout = dir / "deep-layout.json";
  {
    std::ofstream out(layout);
    out << R"({"name": "deep", "devices": )" << deep << "}";
  }
  expect_refused_cheaply(
      layout, [&] { (void)lmc::load_layout(layout); }, "nested deeper than");
  fs::remove_all(dir);
}

TEST(InputLimits, ATrcHeaderClaimingABillionFramesCostsOnlyTheRowsItHolds) {
  const auto dir = lmc::test::scratch_dir("input_limits_trc_claim");
  const fs::path trc = dir / "claims.trc";
  {
    std::ofstream out(trc);
    out << "PathFileType\t4\t(X/Y/Z)\tclaims.trc\n"
        << "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n"
        << "100\t100\t1000000000\t1\tmm\t100\t1\t1000000000\n"
        << "Frame#\tTime\tM1\t\t\n"
        << "\t\tX1\tY1\tZ1\n\n"
        << "1\t0.00\t1\t2\t3\n"
        << "2\t0.01\t1\t2\t3\n";
  }
  const long before = peak_rss_mb();
  try {
    const lmc::TrcData data = lmc::read_trc(trc);
    EXPECT_EQ(data.frame_count(), 2);
    ASSERT_FALSE(data.warnings.empty()) << "a header that disagrees with the rows must be said";
    EXPECT_NE(data.warnings.front().find("NumFrames"), std::string::npos) << data.warnings.front();
  } catch (const lmc::Error& e) {
    EXPECT_NE(std::string(e.what()).find("NumFrames"), std::string::npos) << e.what();
  }
  EXPECT_LT(peak_rss_mb() - before, 64);
  fs::remove_all(dir);
}

}  // namespace input_limits_test
