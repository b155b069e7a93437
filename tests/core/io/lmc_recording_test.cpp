#include "core/io/lmc_recording.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "core/common/error.h"
#include "core/common/nan.h"
#include "tests/core/io/io_test_support.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace {

using test::expect_error_at;
using test::io_fixture;
using test::same_double;
using ::testing::HasSubstr;

// A hand frame whose coordinates exercise the formatter: long fractions, negative zero, tiny
// magnitudes and magnitudes just inside the reader's 10 m limit.
HandFrame make_frame(int device, std::int64_t frame_id, double rate, std::int64_t ts, bool hand, int seed) {
  HandFrame f;
  f.device_id = device;
  f.frame_id = frame_id;
  f.frame_rate_hz = rate;
  f.timestamp_us = ts;
  f.hand_present = hand;
  for (int i = 0; i < kNumHandPoints; ++i) {
    for (int a = 0; a < 3; ++a) {
      const int k = seed * 97 + i * 3 + a;
      double v = std::sin(k * 0.731) * 250.0 + 1.0 / (k + 3.0);
      if (k % 41 == 0) v = -0.0;
      if (k % 53 == 0) v = 1e-300 * (k + 1);
      if (k % 59 == 0) v = -9999.999999999998 / (1.0 + k * 1e-9);  // near the 10 m plausibility limit
      f.points[static_cast<size_t>(i)][a] = hand ? v : kNaN;
    }
  }
  return f;
}

void expect_same_rows(const LmcRecording& a, const LmcRecording& b) {
  ASSERT_EQ(a.rows.size(), b.rows.size());
  for (size_t r = 0; r < a.rows.size(); ++r) {
    const HandFrame& x = a.rows[r];
    const HandFrame& y = b.rows[r];
    SCOPED_TRACE("row " + std::to_string(r));
    EXPECT_EQ(x.device_id, y.device_id);
    EXPECT_EQ(x.frame_id, y.frame_id);
    EXPECT_TRUE(same_double(x.frame_rate_hz, y.frame_rate_hz));
    EXPECT_EQ(x.timestamp_us, y.timestamp_us);
    ASSERT_EQ(x.hand_present, y.hand_present);
    if (!x.hand_present) continue;  // points are only meaningful with a hand
    for (int i = 0; i < kNumHandPoints; ++i) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_TRUE(same_double(x.point(i)[c], y.point(i)[c]))
            << hand_point_name(i) << "[" << c << "] " << x.point(i)[c] << " vs " << y.point(i)[c];
      }
    }
  }
  EXPECT_EQ(a.visibility, b.visibility);
}

LmcRecording round_trip(const LmcRecording& rec) {
  std::ostringstream out;
  write_lmc_recording(out, rec);
  std::istringstream in(out.str());
  return parse_lmc_recording(in, "<memory>");
}

TEST(LmcRecordingRoundTrip, RawWithNoHandRowsFractionalRatesAndEightDevices) {
  LmcRecording rec;
  rec.kind = RecordingKind::kRaw;
  rec.rows.push_back(make_frame(2, 494, 0.0, 2998371808, false, 1));
  rec.rows.push_back(make_frame(1, 497, 69.6427, 2998394550, true, 2));
  // The largest timestamp the reader accepts (2^53 µs); beyond it is refused (ImplausibleTimestampIsRefused).
  rec.rows.push_back(make_frame(8, 12, 66.6533, std::int64_t{1} << 53, true, 3));
  rec.rows.push_back(make_frame(4, -1, 1.0 / 3.0, -5, false, 4));
  const LmcRecording back = round_trip(rec);
  EXPECT_EQ(back.kind, RecordingKind::kRaw);
  EXPECT_TRUE(back.warnings.empty());
  expect_same_rows(rec, back);
  EXPECT_EQ(back.device_ids(), (std::vector<int>{1, 2, 4, 8}));
}

TEST(LmcRecordingRoundTrip, RawNoHandRowEndsAfterTimestamp) {
  const std::string row = format_lmc_row(make_frame(2, 494, 0.0, 2998371808, false, 0), RecordingKind::kRaw);
  EXPECT_EQ(row, "2\t494\t0\t2998371808\t\n");  // exactly as the authors' acquisition wrote it
}

TEST(LmcRecordingRoundTrip, ResampledWithNanRows) {
  LmcRecording rec;
  rec.kind = RecordingKind::kResampled;
  for (int step = 0; step < 3; ++step) {
    for (int d = 1; d <= 4; ++d) {
      rec.rows.push_back(make_frame(d, 0, 100.0, 2998371808 + step * 10000, (d + step) % 3 != 0, step * 4 + d));
    }
  }
  const std::string no_hand = format_lmc_row(rec.rows[2], RecordingKind::kResampled);
  EXPECT_THAT(no_hand, HasSubstr("\tnan,nan,nan\tnan,nan,nan\t"));
  const LmcRecording back = round_trip(rec);
  EXPECT_EQ(back.kind, RecordingKind::kResampled);
  expect_same_rows(rec, back);
  EXPECT_FALSE(back.rows[2].hand_present);
  EXPECT_TRUE(std::isnan(back.rows[2].point(kPalm).x()));
}

TEST(LmcRecordingRoundTrip, RaytracedWithLabelsLooksLikeTheAuthors) {
  LmcRecording rec;
  rec.kind = RecordingKind::kRaytraced;
  rec.rows.push_back(make_frame(1, 0, 100.0, 3215220961, true, 5));
  rec.rows.push_back(make_frame(2, 0, 100.0, 3215220961, false, 6));
  rec.rows.push_back(make_frame(3, 0, 100.0, 3215230961, true, 7));
  rec.rows[2].point(kPalm) = Vec3(99.0, -10.0, 0.5);
  rec.visibility = {FingerLabels{1, 0, 1, 1, 0}, FingerLabels{-1, -1, -1, -1, -1}, FingerLabels{0, 0, 0, 0, 1}};
  std::ostringstream out;
  write_lmc_recording(out, rec);
  const std::string text = out.str();
  EXPECT_EQ(text.rfind(" Device  ID   Frame  ID   Frame  Rate   Time  Stamp   Palm  Position.x ", 0), 0u);
  EXPECT_THAT(text, HasSubstr("   visibility_pinky \n"));
  EXPECT_THAT(text, HasSubstr("\n 3   0   100   3215230961   99.0   -10.0   0.5   "));
  EXPECT_THAT(text, HasSubstr("   1.0   0.0   1.0   1.0   0.0 \n"));
  const LmcRecording back = round_trip(rec);
  EXPECT_EQ(back.kind, RecordingKind::kRaytraced);
  expect_same_rows(rec, back);
}

TEST(LmcRecordingRoundTrip, RaytracedRowWithHandNeedsLabels) {
  EXPECT_THROW(format_lmc_row(make_frame(1, 0, 100.0, 1, true, 1), RecordingKind::kRaytraced), Error);
  LmcRecording rec;
  rec.kind = RecordingKind::kRaytraced;
  rec.rows.push_back(make_frame(1, 0, 100.0, 1, true, 1));
  std::ostringstream out;
  EXPECT_THROW(write_lmc_recording(out, rec), Error);
}

TEST(LmcRecordingRoundTrip, SaveIsAtomicAndReadable) {
  const auto dir = test::scratch_dir("io_save_recording");
  LmcRecording rec;
  rec.rows.push_back(make_frame(3, 7, 58.25, 123456789, true, 9));
  rec.rows.push_back(make_frame(3, 8, 58.25, 123470000, false, 9));
  save_lmc_recording(dir / "r.txt", rec);
  const LmcRecording back = read_lmc_recording(dir / "r.txt");
  expect_same_rows(rec, back);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);  // no temporary left behind
}

TEST(LmcRecordingRead, CrLfLineEndingsAndTabSeparatedRaytraced) {
  LmcRecording rec;
  rec.kind = RecordingKind::kRaytraced;
  rec.rows.push_back(make_frame(1, 0, 100.0, 10, true, 1));
  rec.visibility = {FingerLabels{1, 1, 0, 0, -1}};
  // Convert the authors' space padding into tabs and LF into CRLF: still the same recording.
  std::ostringstream out;
  write_lmc_recording(out, rec);
  std::istringstream lines(out.str());
  std::string line;
  std::getline(lines, line);
  std::string header = "Device ID\tFrame ID\tFrame Rate\tTime Stamp";
  for (int i = 0; i < kNumHandPoints; ++i) {
    for (const char* axis : {".x", ".y", ".z"}) header += "\t" + std::string(hand_point_name(i)) + axis;
  }
  for (int d = 0; d < kNumDigits; ++d) header += "\tvisibility_" + std::string(digit_name(d));
  std::string tabbed = header + "\r\n";
  std::getline(lines, line);
  std::istringstream words(line);
  std::string w;
  bool first = true;
  while (words >> w) {
    tabbed += (first ? "" : "\t") + w;
    first = false;
  }
  tabbed += "\r\n";
  std::istringstream in(tabbed);
  const LmcRecording back = parse_lmc_recording(in, "tabbed.txt");
  EXPECT_EQ(back.kind, RecordingKind::kRaytraced);
  expect_same_rows(rec, back);
}

// --- malformed input: each names file, line and column -------------------------------------

TEST(LmcRecordingErrors, WrongColumnCount) {
  const auto path = io_fixture("raw_wrong_column_count.txt").string();
  const long line_length = static_cast<long>(std::string("3\t12\t60\t2998390000\t1,2,3\t4,5,6\t7,8,9\t").size());
  expect_error_at([&] { read_lmc_recording(path); }, path, 3, line_length + 1,
                  "row has 7 fields; expected 4 (no hand) or 34");
}

TEST(LmcRecordingErrors, NonNumericFieldIsRejectedNotTruncated) {
  const auto path = io_fixture("raw_non_numeric.txt").string();
  expect_error_at([&] { read_lmc_recording(path); }, path, 2, 7,
                  "Frame Rate is not a finite non-negative number: '12abc'");
}

TEST(LmcRecordingErrors, PointWithTwoNumbers) {
  const auto path = io_fixture("raw_point_two_numbers.txt").string();
  // 25 characters of bookkeeping, 5 points of 12 characters before Finger1_Meta.
  expect_error_at([&] { read_lmc_recording(path); }, path, 3, 86,
                  "point 'Finger1_Meta' must be 3 comma-separated numbers x,y,z, found '1.5,2.5'");
}

TEST(LmcRecordingErrors, PointWithGarbageComponent) {
  const auto path = io_fixture("raw_point_garbage.txt").string();
  expect_error_at([&] { read_lmc_recording(path); }, path, 3, 94, "point 'Finger1_Meta' z is not a number: '3x'");
}

TEST(LmcRecordingErrors, DeviceIdOutOfRange) {
  const auto path = io_fixture("raw_device_out_of_range.txt").string();
  expect_error_at([&] { read_lmc_recording(path); }, path, 2, 1, "Device ID 9 is outside 1..8");
}

// 1e308 passed as a coordinate (and turned fused frames into NaN), inf was reported as
// "missing (NaN)", an INT64 timestamp overflowed the resampler. Each is refused with its value.
std::string raw_text_with(const std::string& coordinate, const std::string& timestamp = "1000") {
  HandFrame f;
  f.device_id = 1;
  f.frame_id = 7;
  f.frame_rate_hz = 60.0;
  f.timestamp_us = 1000;
  f.hand_present = true;
  for (auto& p : f.points) p = Vec3(1.0, 2.0, 3.0);
  std::string row = format_lmc_row(f, RecordingKind::kRaw);
  const size_t at = row.find("\t1,2,3\t");
  row.replace(at, 7, "\t1," + coordinate + ",3\t");
  row.replace(row.find("\t1000\t"), 6, "\t" + timestamp + "\t");
  return lmc_recording_header(RecordingKind::kRaw) + format_lmc_row(f, RecordingKind::kRaw) + row;
}

void expect_recording_error(const std::string& text, const std::string& fragment) {
  std::istringstream in(text);
  expect_error_at([&] { parse_lmc_recording(in, "hostile.txt"); }, "hostile.txt", 3, 0, fragment);
}

TEST(LmcRecordingErrors, ImplausibleCoordinatesAreRefusedWithTheirValue) {
  expect_recording_error(raw_text_with("1e308"), "point 'Palm Position' y = '1e308' mm is implausible (more than 10 m");
  expect_recording_error(raw_text_with("-10000.5"), "'-10000.5' mm is implausible");
  expect_recording_error(raw_text_with("inf"), "point 'Palm Position' y is infinite: 'inf'");
  expect_recording_error(raw_text_with("-infinity"), "is infinite");
  // Inside the limit and NaN ("missing") still read.
  std::istringstream ok(raw_text_with("-9999.5"));
  EXPECT_EQ(parse_lmc_recording(ok, "ok.txt").rows.size(), 2u);
}

// Bare "x,y,z" fields are read in one pass; a field with spaces or a '+' goes the careful way.
// Both must give the same point.
TEST(LmcRecordingErrors, ATripletWithSpacesOrAPlusReadsAsTheBareOne) {
  std::istringstream bare_in(raw_text_with("2.5"));
  const LmcRecording bare = parse_lmc_recording(bare_in, "bare.txt");
  ASSERT_EQ(bare.rows.size(), 2u);
  EXPECT_EQ(bare.rows[1].point(0), Vec3(1.0, 2.5, 3.0));
  for (const std::string y : {"+2.5", " 2.5", "2.5 ", " +2.5 ", "2.50", "25e-1"}) {
    std::istringstream in(raw_text_with(y));
    const LmcRecording r = parse_lmc_recording(in, "spaced.txt");
    ASSERT_EQ(r.rows.size(), 2u) << "'" << y << "'";
    EXPECT_EQ(r.rows[1].point(0), bare.rows[1].point(0)) << "'" << y << "'";
    EXPECT_TRUE(r.rows[1].hand_present) << "'" << y << "'";
  }
  // A missing coordinate ("nan") is read as missing by either way: the row has no hand.
  std::istringstream nan_in(raw_text_with("nan"));
  const LmcRecording with_nan = parse_lmc_recording(nan_in, "nan.txt");
  ASSERT_EQ(with_nan.rows.size(), 2u);
  EXPECT_FALSE(with_nan.rows[1].hand_present);
}

TEST(LmcRecordingErrors, ImplausibleTimestampIsRefused) {
  expect_recording_error(raw_text_with("2", "9223372036854775807"),
                         "Time Stamp '9223372036854775807' µs is implausible");
  expect_recording_error(raw_text_with("2", "-9007199254740993"), "is implausible");
  std::istringstream ok(raw_text_with("2", "9007199254740992"));
  EXPECT_EQ(parse_lmc_recording(ok, "ok.txt").rows.size(), 2u);
}

TEST(LmcRecordingErrors, EmptyFile) {
  const auto path = io_fixture("raw_empty.txt").string();
  expect_error_at([&] { read_lmc_recording(path); }, path, 1, 0, "empty file");
}

TEST(LmcRecordingErrors, NotARecording) {
  const auto path = io_fixture("not_a_recording.csv").string();
  expect_error_at([&] { read_lmc_recording(path); }, path, 1, 1, "not an LMC recording");
}

TEST(LmcRecordingErrors, MissingFile) {
  const auto path = io_fixture("does_not_exist.txt").string();
  expect_error_at([&] { read_lmc_recording(path); }, path, 0, 0, "cannot open");
}

TEST(LmcRecordingErrors, BinaryFileGivesAClearMessage) {
  const auto dir = test::scratch_dir("io_binary_recording");
  const auto path = (dir / "capture.bin").string();
  {
    std::ofstream out(path, std::ios::binary);
    out << "Device ID\tFrame ID\n";
    const char junk[] = {'\x7f', 'E', 'L', 'F', '\0', '\x02', '\x01'};
    out.write(junk, sizeof(junk));
  }
  expect_error_at([&] { read_lmc_recording(path); }, path, 2, 5, "binary file");
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << "Device ID\tFrame ID\tFrame Rate\n\xE9t\xE9\n";  // Latin-1, not UTF-8
  }
  expect_error_at([&] { read_lmc_recording(path); }, path, 2, 1, "invalid UTF-8");
}

TEST(LmcRecordingErrors, HeaderWithWrongColumnName) {
  std::string header = lmc_recording_header(RecordingKind::kRaw);
  header.replace(header.find("Frame Rate"), 10, "Frame Rat3");
  std::istringstream in(header + "1\t2\t3\t4\t\n");
  expect_error_at([&] { parse_lmc_recording(in, "h.txt"); }, "h.txt", 1, 20, "header column 3 is 'Frame Rat3'");
}

TEST(LmcRecordingErrors, MalformedLastLineWithNewlineIsAnError) {
  std::istringstream in(lmc_recording_header(RecordingKind::kRaw) + "1\t2\t3\n");
  expect_error_at([&] { parse_lmc_recording(in, "short.txt"); }, "short.txt", 2, 6, "row has 3 fields");
}

TEST(LmcRecordingTruncation, CutLastLineIsDroppedWithWarning) {
  const auto path = io_fixture("raw_truncated_last_line.txt");
  const LmcRecording rec = read_lmc_recording(path);
  ASSERT_EQ(rec.rows.size(), 2u);
  EXPECT_FALSE(rec.rows[0].hand_present);
  EXPECT_TRUE(rec.rows[1].hand_present);
  EXPECT_EQ(rec.rows[1].point(digit_point(Digit::kPinky, Joint::kEnd)), Vec3(1.5, 2.5, 3.5));
  ASSERT_EQ(rec.warnings.size(), 1u);
  EXPECT_THAT(rec.warnings[0], HasSubstr(path.string() + ":4: last line is incomplete"));
}

TEST(LmcRecordingTruncation, APointCutInTheLastFieldIsDroppedWithWarning) {
  // A full disk can stop a write inside the last point of a row ("x,y"): the rows before it are
  // the recording, and they stay readable.
  const LmcRecording whole = read_lmc_recording(io_fixture("raw_truncated_last_line.txt"));
  ASSERT_FALSE(whole.rows.empty());
  std::ostringstream out;
  write_lmc_recording(out, whole);
  const std::string text = out.str();
  const std::string last_row = text.substr(text.rfind('\n', text.size() - 2) + 1);
  const std::string cut = text.substr(0, text.size() - last_row.size()) +
                          last_row.substr(0, last_row.rfind(',') - 1);  // inside the last point's "x,y"
  std::istringstream in(cut);
  const LmcRecording rec = parse_lmc_recording(in, "cut.txt");
  EXPECT_EQ(rec.rows.size(), whole.rows.size() - 1);
  ASSERT_EQ(rec.warnings.size(), 1u);
  EXPECT_THAT(rec.warnings[0], HasSubstr("last line is incomplete (no final newline, cut off mid-field)"));
}

TEST(LmcRecordingTruncation, NumberCutMidFieldIsNotKept) {
  // A no-hand row cut inside its timestamp still has 4 fields; the missing trailing tab that every
  // other line has shows it was cut, so the bogus timestamp 29983 is not kept.
  std::istringstream in(lmc_recording_header(RecordingKind::kRaw) + "1\t496\t0\t2998379547\t\n2\t494\t0\t29983");
  const LmcRecording rec = parse_lmc_recording(in, "cut.txt");
  ASSERT_EQ(rec.rows.size(), 1u);
  EXPECT_EQ(rec.rows[0].timestamp_us, 2998379547);
  ASSERT_EQ(rec.warnings.size(), 1u);
  EXPECT_THAT(rec.warnings[0], HasSubstr("cut.txt:3:"));
}

TEST(LmcRecordingTruncation, CompleteLastLineWithoutNewlineIsKept) {
  std::istringstream in(lmc_recording_header(RecordingKind::kRaw) + "1\t496\t0\t2998379547\t");
  const LmcRecording rec = parse_lmc_recording(in, "ok.txt");
  EXPECT_EQ(rec.rows.size(), 1u);
  EXPECT_TRUE(rec.warnings.empty());
}

TEST(LmcRecordingRead, PartlyMissingRowIsNoHandWithWarning) {
  std::string row = "1\t0\t100\t5\tnan,1,2\t";
  for (int i = 1; i < kNumHandPoints; ++i) row += "1,2,3\t";
  row += "\n";
  std::istringstream in(lmc_recording_header(RecordingKind::kResampled) + row);
  const LmcRecording rec = parse_lmc_recording(in, "partial.txt");
  ASSERT_EQ(rec.rows.size(), 1u);
  EXPECT_FALSE(rec.rows[0].hand_present);
  ASSERT_EQ(rec.warnings.size(), 1u);
  EXPECT_THAT(rec.warnings[0], HasSubstr("some coordinates missing"));
}

// --- the study's own files -------------------------------------------------------------------

std::map<int, int> rows_per_device(const LmcRecording& rec) {
  std::map<int, int> n;
  for (const auto& r : rec.rows) ++n[r.device_id];
  return n;
}

std::string file_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(LmcRecordingReference, RawAcquisitionFile) {
  const auto path = test::reference_file("acquisition/LMC_Naiv_Static101.raw.txt");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const LmcRecording rec = read_lmc_recording(path);
  EXPECT_EQ(rec.kind, RecordingKind::kRaw);
  EXPECT_TRUE(rec.warnings.empty());
  EXPECT_EQ(rows_per_device(rec), (std::map<int, int>{{1, 118}, {2, 121}, {3, 131}, {4, 130}}));
  EXPECT_EQ(rec.device_ids(), (std::vector<int>{1, 2, 3, 4}));
  // First line: device 2 saw no hand.
  EXPECT_EQ(rec.rows[0].device_id, 2);
  EXPECT_EQ(rec.rows[0].frame_id, 494);
  EXPECT_EQ(rec.rows[0].timestamp_us, 2998371808);
  EXPECT_FALSE(rec.rows[0].hand_present);
  EXPECT_EQ(rec.rows[2].frame_rate_hz, 69.6427);
  // Line 10: the first hand.
  const HandFrame& first_hand = rec.rows[8];
  EXPECT_TRUE(first_hand.hand_present);
  EXPECT_EQ(first_hand.device_id, 2);
  EXPECT_EQ(first_hand.frame_id, 497);
  EXPECT_EQ(first_hand.frame_rate_hz, 60.9174);
  EXPECT_EQ(first_hand.point(kPalm), Vec3(-23.916, 260.652, -31.3887));
  EXPECT_EQ(first_hand.point(Digit::kPinky, Joint::kEnd), Vec3(9.76394, 251.795, -95.1886));
  long no_hand = 0;
  for (const auto& r : rec.rows) no_hand += r.hand_present ? 0 : 1;
  EXPECT_EQ(no_hand, 32);
  // Our writer reproduces the authors' file byte for byte.
  std::ostringstream out;
  write_lmc_recording(out, rec);
  EXPECT_EQ(out.str(), file_text(path));
}

TEST(LmcRecordingReference, ResampledAcquisitionFile) {
  const auto path = test::reference_file("acquisition/Interp_LMC_Naiv_Static101.resampled.txt");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const LmcRecording rec = read_lmc_recording(path);
  EXPECT_EQ(rec.kind, RecordingKind::kResampled);
  EXPECT_EQ(rec.rows.size(), 1984u);
  EXPECT_EQ(rows_per_device(rec), (std::map<int, int>{{1, 496}, {2, 496}, {3, 496}, {4, 496}}));
  EXPECT_FALSE(rec.rows[0].hand_present);  // "nan,nan,nan"
  EXPECT_EQ(rec.rows[1].device_id, 2);
  EXPECT_EQ(rec.rows[1].frame_rate_hz, 100.0);
  EXPECT_EQ(rec.rows[1].timestamp_us, 2998371808);
  EXPECT_EQ(rec.rows[1].point(kPalm), Vec3(-23.916, 260.652, -31.3887));
  EXPECT_EQ(rec.rows[1].point(kPalmNormal), Vec3(-0.10993, -0.992444, 0.0544927));
  std::ostringstream out;
  write_lmc_recording(out, rec);
  EXPECT_EQ(out.str(), file_text(path));
}

TEST(LmcRecordingReference, RaytracedValidationFile) {
  const auto path = test::reference_file("validation/Interp_LMC_Naiv_Static101.raytraced.txt");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const LmcRecording rec = read_lmc_recording(path);
  EXPECT_EQ(rec.kind, RecordingKind::kRaytraced);
  ASSERT_EQ(rec.rows.size(), 200u);
  ASSERT_EQ(rec.visibility.size(), 200u);
  EXPECT_EQ(rows_per_device(rec), (std::map<int, int>{{1, 50}, {2, 50}, {3, 50}, {4, 50}}));
  EXPECT_EQ(rec.rows[0].device_id, 1);
  EXPECT_EQ(rec.rows[0].timestamp_us, 3215220961);
  EXPECT_EQ(rec.rows[0].point(kPalm), Vec3(66.006, 263.579, -54.7098));
  EXPECT_EQ(rec.rows[2].point(kPalm), Vec3(73.3232, 252.194, 70.4106));
  EXPECT_EQ(rec.visibility[0], (FingerLabels{1, 1, 1, 1, 1}));
  std::ostringstream out;
  write_lmc_recording(out, rec);
  EXPECT_EQ(out.str(), file_text(path));  // space padding and "99.0" style as the authors wrote
}

TEST(LmcRecordingReference, ResampledValidationInput) {
  const auto path = test::reference_file("validation/Interp_LMC_Naiv_Static101.txt");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const LmcRecording rec = read_lmc_recording(path);
  EXPECT_EQ(rec.kind, RecordingKind::kResampled);
  ASSERT_EQ(rec.rows.size(), 200u);
  // Same frames as the raytraced file, without the labels.
  const auto raytraced = test::reference_file("validation/Interp_LMC_Naiv_Static101.raytraced.txt");
  if (std::filesystem::exists(raytraced)) {
    const LmcRecording labelled = read_lmc_recording(raytraced);
    LmcRecording unlabelled = labelled;
    unlabelled.visibility = rec.visibility;
    expect_same_rows(rec, unlabelled);
  }
}

}  // namespace
}  // namespace lmc
