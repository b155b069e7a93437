#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "core/common/error.h"
#include "core/io/lmc_recording.h"
#include "core/processing/resample.h"

namespace lmc {
namespace {

HandFrame frame_at(int device, std::int64_t t_us, bool hand = true, double offset = 0.0) {
  HandFrame f;
  f.device_id = device;
  f.timestamp_us = t_us;
  f.hand_present = hand;
  if (hand) {
    const double t = static_cast<double>(t_us) * 1e-6;
    for (int i = 0; i < kNumHandPoints; ++i) f.point(i) = Vec3(10.0 * t + i + offset, 200.0 - 5.0 * t, i * 0.5);
  }
  return f;
}

TEST(CubicSpline, ReproducesCubicInteriorAndLinearExactly) {
  std::vector<double> t{0.0, 0.013, 0.05, 0.061, 0.1};
  std::vector<double> y;
  for (double v : t) y.push_back(3.0 - 2.0 * v);
  std::vector<double> q{0.0, 0.01, 0.02, 0.1, 0.2};
  std::vector<double> out(q.size(), -99.0);
  cubic_spline_eval(t, y, 1, q, out);
  for (size_t k = 0; k < 4; ++k) EXPECT_NEAR(out[k], 3.0 - 2.0 * q[k], 1e-12);
  EXPECT_EQ(out[4], -99.0);  // outside: untouched
}

TEST(Resample, GridStartsAtFirstHandAndInterpolatesLinearMotion) {
  LmcRecording rec;
  rec.rows.push_back(frame_at(1, 1000000, false));  // no hand yet
  for (std::int64_t t = 1'020'000; t <= 1'300'000; t += 33'000) rec.rows.push_back(frame_at(1, t));
  for (std::int64_t t = 1'035'000; t <= 1'290'000; t += 41'000) rec.rows.push_back(frame_at(2, t));
  ResampleReport report;
  const GridTrial g = resample_recording(rec, {}, &report);
  EXPECT_EQ(g.start_us, 1'020'000);
  ASSERT_EQ(g.devices.size(), 2u);
  EXPECT_EQ(g.frame_count, 27);  // 1.020 … 1.280 s: last sample of device 1 at 1.284 s
  const auto& d1 = g.devices[0].track;
  for (int f = 0; f < g.frame_count; ++f) {
    const double t = 1.02 + 0.01 * f;
    ASSERT_TRUE(d1.has_hand(f)) << f;
    EXPECT_NEAR(d1.at(f, 3).x(), 10.0 * t + 3, 1e-9);
  }
  // Device 2 starts at 1.035 s: grid 1.02, 1.03 are NaN for it.
  EXPECT_FALSE(g.devices[1].track.has_hand(0));
  EXPECT_FALSE(g.devices[1].track.has_hand(1));
  EXPECT_TRUE(g.devices[1].track.has_hand(2));
  EXPECT_TRUE(report.summary_lines().empty());
}

// The re-basing sums are checked before they are formed (signed overflow is undefined): a time
// stamp that would overflow once re-based is refused, naming its row.
TEST(Resample, ATimestampThatOverflowsWhenRebasedIsRefusedNamingItsRow) {
  LmcRecording rec;
  rec.rows.push_back(frame_at(1, 1'000'000));
  rec.rows.push_back(frame_at(1, 0));  // back by 1 s: a clock reset, the rest re-based by +1.033 s
  rec.rows.push_back(frame_at(1, std::numeric_limits<std::int64_t>::max()));
  try {
    resample_recording(rec, {});
    FAIL() << "a recording whose re-based time stamps overflow was resampled";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("row 3: timestamp arithmetic leaves the plausible range"), std::string::npos) << what;
  }
}

TEST(Resample, GapsAndHandLossAreNaNNotBridged) {
  LmcRecording rec;
  for (std::int64_t t : {0, 30'000, 60'000}) rec.rows.push_back(frame_at(1, t));
  for (std::int64_t t : {160'000, 190'000}) rec.rows.push_back(frame_at(1, t));  // 100 ms gap
  rec.rows.push_back(frame_at(1, 220'000, false));                               // hand lost
  for (std::int64_t t : {240'000, 270'000}) rec.rows.push_back(frame_at(1, t));
  ResampleReport report;
  const GridTrial g = resample_recording(rec, {}, &report);
  const auto& tr = g.devices[0].track;
  EXPECT_TRUE(tr.has_hand(6));
  for (int f = 7; f <= 15; ++f) EXPECT_FALSE(tr.has_hand(f)) << f;
  EXPECT_TRUE(tr.has_hand(16));
  EXPECT_TRUE(tr.has_hand(19));
  for (int f = 20; f <= 23; ++f) EXPECT_FALSE(tr.has_hand(f)) << f;  // across the hand-less row
  EXPECT_TRUE(tr.has_hand(24));
  ASSERT_EQ(report.devices.size(), 1u);
  EXPECT_EQ(report.devices[0].gaps, 1);
}

// Four controllers on one bus stream at 11–34 Hz: 77 ms between frames is a device's normal
// rhythm and is interpolated; a pause of several frames is still a gap. A 100 Hz device keeps the
// 50 ms floor. --fixed-gap (adaptive_gap = false) applies 50 ms to every device.
TEST(Resample, GapLimitFollowsEachDevicesOwnFrameRate) {
  LmcRecording rec;
  for (std::int64_t t = 0; t <= 770'000; t += 77'000) rec.rows.push_back(frame_at(1, t));            // 13 Hz
  for (std::int64_t t = 1'000'000; t <= 1'231'000; t += 77'000) rec.rows.push_back(frame_at(1, t));  // after 230 ms
  for (std::int64_t t = 0; t <= 300'000; t += 10'000) {
    if (t < 100'000 || t > 150'000) rec.rows.push_back(frame_at(2, t));  // 100 Hz with a 60 ms hole
  }
  ResampleReport report;
  const GridTrial g = resample_recording(rec, {}, &report);
  ASSERT_EQ(report.devices.size(), 2u);
  EXPECT_DOUBLE_EQ(report.devices[0].median_interval_ms, 77.0);
  EXPECT_DOUBLE_EQ(report.devices[0].gap_limit_ms, 192.5);
  EXPECT_DOUBLE_EQ(report.devices[1].gap_limit_ms, 50.0);
  const auto& d1 = g.devices[0].track;
  for (int f = 0; f <= 77; ++f) EXPECT_TRUE(d1.has_hand(f)) << f;    // 0 … 770 ms, no gap inside
  for (int f = 78; f <= 99; ++f) EXPECT_FALSE(d1.has_hand(f)) << f;  // 230 ms pause
  EXPECT_TRUE(d1.has_hand(100));
  EXPECT_EQ(report.devices[0].gaps, 1);
  const auto& d2 = g.devices[1].track;
  EXPECT_TRUE(d2.has_hand(9));
  for (int f = 10; f <= 15; ++f) EXPECT_FALSE(d2.has_hand(f)) << f;
  EXPECT_TRUE(d2.has_hand(16));
  EXPECT_EQ(report.devices[1].gaps, 1);
  ASSERT_EQ(report.summary_lines().size(), 2u);
  EXPECT_NE(report.summary_lines()[0].find("limit of 193 ms"), std::string::npos) << report.summary_lines()[0];

  ResampleOptions fixed;
  fixed.adaptive_gap = false;
  ResampleReport strict;
  const GridTrial gf = resample_recording(rec, fixed, &strict);
  EXPECT_DOUBLE_EQ(strict.devices[0].gap_limit_ms, 50.0);
  EXPECT_EQ(strict.devices[0].gaps, 14);  // every one of its 15 samples stands alone
  EXPECT_FALSE(gf.devices[0].track.has_hand(1));
  EXPECT_TRUE(gf.devices[0].track.has_hand(0));
}

TEST(Resample, ReportsOutOfOrderDuplicatesAndClockResets) {
  LmcRecording rec;
  rec.rows.push_back(frame_at(1, 100'000));
  rec.rows.push_back(frame_at(1, 130'000));
  rec.rows.push_back(frame_at(1, 120'000));  // out of order
  rec.rows.push_back(frame_at(1, 130'000));  // duplicate, same data
  rec.rows.push_back(frame_at(1, 160'000));
  rec.rows.push_back(frame_at(1, 160'000, true, 5.0));  // duplicate, different data
  rec.rows.push_back(frame_at(1, 5'000));               // clock reset (back by 155 ms > limit 100 ms)
  rec.rows.push_back(frame_at(1, 35'000));
  ResampleOptions o;
  o.clock_reset_ms = 100.0;
  ResampleReport report;
  const GridTrial g = resample_recording(rec, o, &report);
  ASSERT_EQ(report.devices.size(), 1u);
  const auto& s = report.devices[0];
  EXPECT_EQ(s.out_of_order, 1);
  EXPECT_EQ(s.duplicates, 2);
  EXPECT_EQ(s.clock_resets, 1);
  const auto lines = report.summary_lines();
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("LMC1"), std::string::npos);
  EXPECT_NE(lines[0].find("clock reset"), std::string::npos);
  bool conflicting = false;
  for (const auto& i : report.issues) conflicting = conflicting || i.kind == StreamIssueKind::kConflictingDuplicate;
  EXPECT_TRUE(conflicting);
  // Re-based: the post-reset part continues after 160 ms (typical step 30 ms: 190 ms, 220 ms).
  EXPECT_EQ(g.start_us, 100'000);
  EXPECT_EQ(g.frame_count, 13);  // 100 … 220 ms
}

TEST(Resample, NoHandAnywhereIsAnError) {
  LmcRecording rec;
  rec.rows.push_back(frame_at(1, 0, false));
  EXPECT_THROW(resample_recording(rec), Error);
}

TEST(Resample, ResampledRecordingRowsAreTheGrid) {
  LmcRecording rec;
  rec.kind = RecordingKind::kResampled;
  for (int f = 0; f < 3; ++f) {
    rec.rows.push_back(frame_at(1, 10'000 * f));
    rec.rows.push_back(frame_at(2, 10'000 * f, f != 1));
  }
  rec.rows.push_back(frame_at(1, 30'000));
  std::vector<std::string> warnings;
  const GridTrial g = grid_from_resampled(rec, &warnings);
  EXPECT_EQ(g.frame_count, 4);
  EXPECT_FALSE(g.devices[1].track.has_hand(1));
  EXPECT_FALSE(g.devices[1].track.has_hand(3));
  EXPECT_TRUE(g.devices[0].track.has_hand(3));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("LMC2"), std::string::npos);

  // A resampled file in which no device ever saw the hand still gives its grid, and says so.
  LmcRecording empty;
  empty.kind = RecordingKind::kResampled;
  for (int f = 0; f < 3; ++f) empty.rows.push_back(frame_at(1, 10'000 * f, false));
  std::vector<std::string> w2;
  EXPECT_EQ(grid_from_resampled(empty, &w2).frame_count, 3);
  ASSERT_EQ(w2.size(), 1u);
  EXPECT_NE(w2[0].find("no device saw the hand"), std::string::npos);
}

// One row whose timestamp jumps by 10^4 s made a 10 s recording ask for a grid of
// several GB; the resampler refuses it, naming the file and the line of the jump.
TEST(ResampleLimits, TimestampJumpIsRefusedWithFileAndLine) {
  LmcRecording rec;
  for (std::int64_t t = 0; t <= 10'000'000; t += 33'333) rec.rows.push_back(frame_at(1, t));
  for (const std::int64_t t : {10'000'000'000, 10'000'033'333}) {  // 10^4 s later, hand where it was
    HandFrame later = frame_at(1, 10'000'000);
    later.timestamp_us = t;
    rec.rows.push_back(later);
  }
  std::stringstream text;
  write_lmc_recording(text, rec);
  const LmcRecording read = parse_lmc_recording(text, "jump.txt");
  // Header on line 1, so row r is line r + 1: the jump (second-last row) is on line rows.size().
  const long jump_line = static_cast<long>(read.rows.size());
  try {
    resample_recording(read);
    FAIL() << "a 10^4 s grid was built";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.where().file, "jump.txt");
    EXPECT_EQ(e.where().line, jump_line) << what;
    EXPECT_NE(what.find("jumps 9990"), std::string::npos) << what;
    EXPECT_NE(what.find("refusing"), std::string::npos) << what;
  }
  // The same recording without the jump still resamples.
  rec.rows.resize(rec.rows.size() - 2);
  EXPECT_GT(resample_recording(rec).frame_count, 990);
}

TEST(ResampleLimits, Int64TimestampsAreAnErrorNotOverflow) {
  for (const std::int64_t extreme :
       {std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::min()}) {
    LmcRecording rec;
    rec.rows.push_back(frame_at(1, 0));
    rec.rows.push_back(frame_at(1, 33'000));
    rec.rows.push_back(frame_at(1, extreme, false));
    rec.rows.push_back(frame_at(1, 66'000));
    EXPECT_THROW(resample_recording(rec), Error) << extreme;
  }
  // Alternating extremes: each "clock reset" re-bases further; the arithmetic must stay checked.
  LmcRecording saw;
  for (int k = 0; k < 200; ++k) saw.rows.push_back(frame_at(1, (k % 2 == 0 ? 1 : -1) * (std::int64_t{1} << 53)));
  EXPECT_THROW(resample_recording(saw), Error);
}

}  // namespace
}  // namespace lmc
