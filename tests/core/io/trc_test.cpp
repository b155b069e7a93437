#include "core/io/trc.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "core/common/error.h"
#include "core/common/nan.h"
#include "tests/core/io/io_test_support.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace trc_test {

using test::expect_error_at;
using test::io_fixture;
using test::same_double;
using ::testing::HasSubstr;

TEST(TrcRead, MissingMarkersEmptyNanAndBlankLine) {
  const auto path = io_fixture("trc_missing_markers.trc");
  const TrcData trc = read_trc(path);
  EXPECT_EQ(trc.marker_names, (std::vector<std::string>{"Wrist", "Tip"}));
  ASSERT_EQ(trc.frame_count(), 4);  // header claims 9
  EXPECT_EQ(trc.frame_numbers, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(trc.times_s[1], 0.01);
  EXPECT_EQ(trc.positions[0][0], Eigen::Vector3d(1.5, 2.5, 3.5));
  EXPECT_TRUE(trc.positions[1][0].array().isNaN().all());  // empty cells
  EXPECT_TRUE(trc.positions[2][0].array().isNaN().all());  // NaN
  EXPECT_TRUE(trc.positions[3][1].array().isNaN().all());  // nan
  EXPECT_EQ(trc.positions[3][0], Eigen::Vector3d(1.75, 2.75, 3.75));
  EXPECT_EQ(trc.positions[2][1], Eigen::Vector3d(12, 22, 32));
  ASSERT_EQ(trc.warnings.size(), 1u);
  EXPECT_THAT(trc.warnings[0], HasSubstr("NumFrames 9 but the file holds 4 rows"));
  EXPECT_EQ(trc.marker_index("Tip"), 1);
  EXPECT_EQ(trc.marker_index("Elbow"), -1);
}

// Rows of plain numbers take a quick path (trc.cpp); a row with anything else is read by the full
// checks. Both must give the same values, frame numbers, times and gap counts.
TEST(TrcRead, PlainRowsAndRowsWithSpacesExponentsOrGapsReadAlike) {
  const std::string header =
      "PathFileType\t4\t(X/Y/Z)\tt.trc\n"
      "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n"
      "100\t100\t2\t2\tmm\t100\t1\t2\n"
      "Frame#\tTime\tA\t\t\tB\t\t\n"
      "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\n\n";
  const TrcData plain = parse_trc_text(header +
                                           "1\t0\t149.41004537989676\t-2.5\t0.125\t0\t0\t0\n"
                                           "2\t0.01\t-0.000012345\t12\t7.25\t1\t2\t3\t\t\n",
                                       "plain.trc");
  const TrcData general = parse_trc_text(header +
                                             "1\t0.0\t 149.41004537989676\t-2.5e0\t+0.125\t0\t0\t0\n"
                                             "2\t1e-2\t-1.2345e-5\t12.0\t7.25 \t1\t2\t3\t \t\n",
                                         "general.trc");
  for (const TrcData* trc : {&plain, &general}) {
    ASSERT_EQ(trc->frame_count(), 2);
    EXPECT_EQ(trc->frame_numbers, (std::vector<int>{1, 2}));
    EXPECT_EQ(trc->times_s, (std::vector<double>{0.0, 0.01}));
    EXPECT_EQ(trc->positions[0][0], Eigen::Vector3d(149.41004537989676, -2.5, 0.125));
    EXPECT_TRUE(trc->positions[0][1].array().isNaN().all()) << "0 0 0 is an exporter's gap";
    EXPECT_EQ(trc->positions[1][0], Eigen::Vector3d(-0.000012345, 12, 7.25));
    EXPECT_EQ(trc->positions[1][1], Eigen::Vector3d(1, 2, 3));
    ASSERT_EQ(trc->warnings.size(), 1u);
    EXPECT_THAT(trc->warnings[0], HasSubstr("1 marker sample(s) were 0,0,0"));
  }
  // A value beyond the plausible range in an otherwise plain row is refused by the full checks,
  // with its place.
  expect_error_at([&] { (void)parse_trc_text(header + "1\t0\t1\t2\t3\t4\t5\t123456.5\n", "far.trc"); }, "far.trc", 7,
                  15, "implausible");
}

TEST(TrcRoundTrip, WriteThenReadIsExactIncludingGaps) {
  TrcData trc;
  trc.data_rate_hz = 250.0;
  trc.camera_rate_hz = 250.0;
  trc.units = "m";
  trc.orig_data_start_frame = 7;
  trc.marker_names = {"A", "B", "C"};
  for (int f = 0; f < 5; ++f) {
    trc.frame_numbers.push_back(7 + f);
    trc.times_s.push_back(f / 250.0);
    std::vector<Eigen::Vector3d> row;
    for (int m = 0; m < 3; ++m) {
      row.emplace_back(std::sin(f * 3 + m) / 7.0, -0.0, 1e-9 * (f + 1) + m);
    }
    if (f == 2) row[2].setConstant(kNaN);  // last marker missing: trailing empty cells
    if (f == 3) row[0].setConstant(kNaN);
    trc.positions.push_back(row);
  }
  std::ostringstream out;
  write_trc(out, trc, "C:\\lab\\t.trc");
  std::istringstream in(out.str());
  const TrcData back = parse_trc(in, "<memory>");
  EXPECT_TRUE(back.warnings.empty());
  EXPECT_EQ(back.units, "m");
  EXPECT_EQ(back.data_rate_hz, 250.0);
  EXPECT_EQ(back.orig_data_start_frame, 7);
  EXPECT_EQ(back.marker_names, trc.marker_names);
  EXPECT_EQ(back.frame_numbers, trc.frame_numbers);
  EXPECT_EQ(back.times_s, trc.times_s);
  ASSERT_EQ(back.frame_count(), 5);
  for (int f = 0; f < 5; ++f) {
    for (int m = 0; m < 3; ++m) {
      for (int a = 0; a < 3; ++a) {
        EXPECT_TRUE(same_double(back.positions[f][m][a], trc.positions[f][m][a])) << f << " " << m << " " << a;
      }
    }
  }
  TrcData mm = back;
  mm.to_millimetres();
  EXPECT_EQ(mm.units, "mm");
  EXPECT_DOUBLE_EQ(mm.positions[0][1].z(), back.positions[0][1].z() * 1000.0);
  EXPECT_TRUE(std::isnan(mm.positions[2][2].x()));
}

TEST(TrcRoundTrip, WriterFillsFrameNumbersAndTimesWhenAbsent) {
  TrcData trc;
  trc.marker_names = {"M"};
  trc.positions = {{Eigen::Vector3d(1, 2, 3)}, {Eigen::Vector3d(4, 5, 6)}};
  std::ostringstream out;
  write_trc(out, trc);
  std::istringstream in(out.str());
  const TrcData back = parse_trc(in, "<memory>");
  EXPECT_EQ(back.frame_numbers, (std::vector<int>{1, 2}));
  EXPECT_EQ(back.times_s, (std::vector<double>{0.0, 0.01}));
}

TEST(TrcErrors, UnknownUnitsNameFileLineColumn) {
  const auto path = io_fixture("trc_unknown_units.trc").string();
  expect_error_at([&] { read_trc(path); }, path, 3, 17, "unknown units 'inch'");
  TrcData trc;
  trc.units = "furlong";
  EXPECT_THROW(trc.to_millimetres(), Error);
  std::ostringstream out;
  EXPECT_THROW(write_trc(out, trc), Error);
}

TEST(TrcErrors, WrongColumnCount) {
  const auto path = io_fixture("trc_wrong_column_count.trc").string();
  const long len = static_cast<long>(std::string("2\t0.01\t1\t2\t3\t11\t21").size());
  expect_error_at([&] { read_trc(path); }, path, 7, len + 1, "row has 7 fields; expected 8");
}

TEST(TrcErrors, NonNumericCell) {
  const auto path = io_fixture("trc_non_numeric.trc").string();
  expect_error_at([&] { read_trc(path); }, path, 8, 23, "marker 'Tip' Y is not a number: '22x'");
}

// Infinity was read as a gap and 1e308 as a position; both are refused with the value.
TEST(TrcErrors, InfiniteOrImplausibleCoordinateIsRefused) {
  const auto trc_with = [](const std::string& cell, const std::string& units) {
    return "PathFileType\t3\t(X/Y/Z)\th.trc\n"
           "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n"
           "100\t100\t2\t1\t" +
           units +
           "\t100\t1\t2\n"
           "Frame#\tTime\tTip\t\t\n"
           "\t\tX1\tY1\tZ1\n"
           "1\t0\t1\t2\t3\n"
           "2\t0.01\t1\t" +
           cell + "\t3\n";
  };
  const auto parse = [](const std::string& text) {
    std::istringstream in(text);
    return parse_trc(in, "hostile.trc");
  };
  expect_error_at([&] { parse(trc_with("1e308", "mm")); }, "hostile.trc", 7, 0,
                  "marker 'Tip' Y = '1e308' mm is implausible");
  expect_error_at([&] { parse(trc_with("-200", "m")); }, "hostile.trc", 7, 0, "'-200' m is implausible");
  expect_error_at([&] { parse(trc_with("inf", "mm")); }, "hostile.trc", 7, 0, "marker 'Tip' Y is infinite: 'inf'");
  EXPECT_EQ(parse(trc_with("-99999", "mm")).frame_count(), 2);  // inside 100 m
}

TEST(TrcErrors, NotATrcFileAndEmptyFile) {
  const auto path = io_fixture("raw_non_numeric.txt").string();
  expect_error_at([&] { read_trc(path); }, path, 1, 1, "not a TRC file");
  const auto empty = io_fixture("raw_empty.txt").string();
  expect_error_at([&] { read_trc(empty); }, empty, 1, 0, "empty file");
  std::istringstream in(std::string("PathFileType\t4\n\0\0\0", 18));
  expect_error_at([&] { parse_trc(in, "nul.trc"); }, "nul.trc", 2, 1, "binary file");
}

TEST(TrcErrors, TruncatedLastRowIsDroppedWithWarning) {
  std::ostringstream out;
  TrcData trc;
  trc.marker_names = {"M", "N"};
  trc.positions = {{Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6)}};
  write_trc(out, trc);
  std::istringstream in(out.str() + "2\t0.01\t1\t2");
  const TrcData back = parse_trc(in, "cut.trc");
  EXPECT_EQ(back.frame_count(), 1);
  ASSERT_EQ(back.warnings.size(), 1u);
  EXPECT_THAT(back.warnings[0], HasSubstr("cut.trc:8: last line is incomplete"));
}

TEST(TrcReference, ViconStaticTrial) {
  const auto path = test::reference_file("validation/Naiv_Static101.trc");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const TrcData trc = read_trc(path);
  EXPECT_EQ(trc.marker_count(), 26);
  EXPECT_EQ(trc.frame_count(), 100);
  EXPECT_EQ(trc.units, "mm");
  EXPECT_EQ(trc.data_rate_hz, 100.0);
  EXPECT_EQ(trc.marker_names.front(), "Forearm1");
  EXPECT_EQ(trc.marker_names.back(), "Pinky4_1");
  EXPECT_EQ(trc.marker_index("Hand4"), 6);
  EXPECT_EQ(trc.frame_numbers.front(), 1);
  EXPECT_EQ(trc.times_s[1], 0.01);
  EXPECT_EQ(trc.positions[0][0], Eigen::Vector3d(132.65334, 225.2972, 373.95145));
  EXPECT_EQ(trc.positions[0][1], Eigen::Vector3d(82.928391, 322.67084, 146.97191));
  EXPECT_EQ(trc.frame_numbers.back(), 100);
  EXPECT_EQ(trc.positions[99][0], Eigen::Vector3d(134.29497, 201.15451, 373.45135));
  ASSERT_EQ(trc.warnings.size(), 1u);
  EXPECT_THAT(trc.warnings[0], HasSubstr("NumFrames 511 but the file holds 100 rows"));
}

}  // namespace trc_test
}  // namespace lmc
