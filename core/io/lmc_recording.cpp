#include "core/io/lmc_recording.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <istream>
#include <limits>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>

#include "core/common/error.h"
#include "core/common/nan.h"
#include "core/io/atomic_write.h"
#include "core/io/delimited_text.h"

namespace lmc {
namespace {

// Column layout (docs/formats.md): 4 bookkeeping columns, then 30 points.
constexpr int kMetaColumns = 4;
constexpr std::array<std::string_view, kMetaColumns> kMetaNames = {"Device ID", "Frame ID", "Frame Rate", "Time Stamp"};
constexpr int kPointColumns = kMetaColumns + kNumHandPoints;                   // raw/resampled: 34
constexpr int kSplitColumns = kMetaColumns + 3 * kNumHandPoints + kNumDigits;  // raytraced: 99
constexpr std::array<char, 3> kAxes = {'x', 'y', 'z'};
// The study's rig has four controllers; the recorder supports up to eight (one LeapC connection).
constexpr int kMaxDeviceId = 8;
// Plausibility limits. A controller sees ~0.6 m; a coordinate beyond 10 m (in mm) is
// a corrupt or hostile value, and 1e308 turned every fused frame into NaN downstream. Timestamps
// beyond 2^53 µs (≈ 285 years) are no clock reading, and would overflow the resampler's arithmetic.
constexpr double kMaxAbsCoordinateMm = 10000.0;
constexpr std::int64_t kMaxAbsTimestampUs = std::int64_t{1} << 53;

// How the columns are laid out in the file.
enum class ColumnStyle {
  kPointTriplets,  // raw / resampled: one "x,y,z" field per point, tab-separated
  kSplitNumbers,   // raytraced: one number per column plus visibility labels
};

struct HeaderInfo {
  ColumnStyle style = ColumnStyle::kPointTriplets;
  bool whitespace_separated = false;  // the authors' raytraced files: space-padded
  bool ends_with_separator = false;   // the authors' lines all end in a tab / space
};

std::vector<std::string> triplet_column_names() {
  std::vector<std::string> names(kMetaNames.begin(), kMetaNames.end());
  for (int i = 0; i < kNumHandPoints; ++i) {
    const std::string base(hand_point_name(i));
    names.push_back(base + ".x," + base + ".y," + base + ".z");
  }
  return names;
}

std::vector<std::string> split_column_names() {
  std::vector<std::string> names(kMetaNames.begin(), kMetaNames.end());
  for (int i = 0; i < kNumHandPoints; ++i) {
    for (const char axis : kAxes) names.push_back(std::string(hand_point_name(i)) + "." + axis);
  }
  for (int d = 0; d < kNumDigits; ++d) names.push_back("visibility_" + std::string(digit_name(d)));
  return names;
}

HeaderInfo read_header(const text::Line& line, const std::string& source) {
  HeaderInfo info;
  const std::string_view t = line.text;
  if (text::is_blank(t)) {
    text::fail_at(source, line.number, 1, "first line is empty: expected the header, starting with 'Device ID'");
  }
  std::vector<text::Field> fields;
  if (t.find('\t') != std::string_view::npos) {
    info.ends_with_separator = t.back() == '\t';
    text::split_fields(t, '\t', fields);
    while (!fields.empty() && text::is_blank(fields.back().text)) fields.pop_back();
    if (text::normalise_name(fields.front().text) != "device id") {
      text::fail_at(source, line.number, 1,
                    "not an LMC recording: the header must start with 'Device ID', found " +
                        text::quoted_excerpt(fields.front().text));
    }
    std::vector<std::string> expected;
    if (fields.size() == static_cast<size_t>(kPointColumns)) {
      expected = triplet_column_names();
      info.style = ColumnStyle::kPointTriplets;
    } else if (fields.size() == static_cast<size_t>(kSplitColumns)) {
      expected = split_column_names();
      info.style = ColumnStyle::kSplitNumbers;
    } else {
      text::fail_at(source, line.number, 0,
                    "header has " + std::to_string(fields.size()) + " columns; expected " +
                        std::to_string(kPointColumns) + " (raw or resampled recording) or " +
                        std::to_string(kSplitColumns) + " (raytraced)");
    }
    for (size_t i = 0; i < fields.size(); ++i) {
      if (text::normalise_name(fields[i].text) != text::normalise_name(expected[i])) {
        text::fail_at(source, line.number, fields[i].column,
                      "header column " + std::to_string(i + 1) + " is " + text::quoted_excerpt(fields[i].text) +
                          ", expected '" + expected[i] + "'");
      }
    }
    return info;
  }
  // Space-padded (the authors' raytraced output): column names containing spaces ("Device  ID")
  // are split into words too, so compare word by word against the expected names' words.
  info.whitespace_separated = true;
  info.ends_with_separator = t.back() == ' ';
  info.style = ColumnStyle::kSplitNumbers;
  text::split_whitespace(t, fields);
  std::vector<std::string> words;
  for (const auto& name : split_column_names()) {
    std::vector<text::Field> parts;
    text::split_whitespace(name, parts);
    for (const auto& p : parts) words.push_back(text::normalise_name(p.text));
  }
  if (fields.size() < 2 || text::normalise_name(fields[0].text) != "device" ||
      text::normalise_name(fields[1].text) != "id") {
    text::fail_at(source, line.number, fields.empty() ? 1 : fields[0].column,
                  "not an LMC recording: the header must start with 'Device ID'");
  }
  for (size_t i = 0; i < std::min(fields.size(), words.size()); ++i) {
    if (text::normalise_name(fields[i].text) != words[i]) {
      text::fail_at(source, line.number, fields[i].column,
                    "unexpected header word " + text::quoted_excerpt(fields[i].text) + ", expected '" + words[i] + "'");
    }
  }
  if (fields.size() != words.size()) {
    text::fail_at(source, line.number, 0,
                  "space-separated header has " + std::to_string(fields.size()) + " words; a raytraced recording has " +
                      std::to_string(words.size()) + " (" + std::to_string(kSplitColumns) + " columns)");
  }
  return info;
}

// Why a row could not be read. `short_row` marks "too few fields" so the caller can tell a
// truncated last line from a malformed one.
struct RowFailure {
  long column = 0;
  std::string message;
  bool short_row = false;
};

struct ParsedRow {
  HandFrame frame;
  FingerLabels labels{};
  bool all_nan = false;        // every coordinate NaN (resampled "nan,nan,nan" no-hand row)
  bool short_no_hand = false;  // raw no-hand row (ends after the timestamp)
  bool partial = false;        // some coordinates finite, some not
};

class RowParser {
 public:
  // `buffer_end`: where the text the rows are in ends (the number reader may look ahead to it).
  RowParser(const HeaderInfo& header, const char* buffer_end) : header_(header), buffer_end_(buffer_end) {}

  // Returns a failure instead of throwing so the caller can treat a cut-off last line gently.
  std::optional<RowFailure> parse(std::string_view line, ParsedRow& row) {
    row = ParsedRow{};
    line_length_ = static_cast<long>(line.size());
    if (header_.whitespace_separated) {
      text::split_whitespace(line, fields_);
    } else {
      text::split_fields(line, '\t', fields_);
      while (!fields_.empty() && text::is_blank(fields_.back().text)) fields_.pop_back();
    }
    if (auto f = parse_meta(row.frame)) return f;
    if (header_.style == ColumnStyle::kPointTriplets) return parse_triplets(row);
    return parse_split(row);
  }

 private:
  std::optional<RowFailure> count_failure(size_t expected, const char* what) const {
    const size_t n = fields_.size();
    RowFailure f;
    f.short_row = n < expected;
    // Too many: point at the first extra field; too few: at the end of the line, where the next
    // field was expected.
    f.column = n > expected ? fields_[expected].column : line_length_ + 1;
    f.message = "row has " + std::to_string(n) + " fields; expected " + what;
    return f;
  }

  std::optional<RowFailure> parse_meta(HandFrame& frame) {
    if (fields_.size() < static_cast<size_t>(kMetaColumns)) {
      return count_failure(static_cast<size_t>(kMetaColumns),
                           header_.style == ColumnStyle::kPointTriplets
                               ? "4 (no hand) or 34"
                               : "99 (4 bookkeeping, 90 coordinates, 5 visibility labels)");
    }
    const auto id = text::parse_int(fields_[0].text);
    if (!id)
      return RowFailure{fields_[0].column, "Device ID is not an integer: " + text::quoted_excerpt(fields_[0].text)};
    if (*id < 1 || *id > kMaxDeviceId) {
      return RowFailure{fields_[0].column,
                        "Device ID " + std::to_string(*id) + " is outside 1.." + std::to_string(kMaxDeviceId)};
    }
    const auto frame_id = text::parse_int(fields_[1].text);
    if (!frame_id)
      return RowFailure{fields_[1].column, "Frame ID is not an integer: " + text::quoted_excerpt(fields_[1].text)};
    const auto rate = text::parse_double(fields_[2].text);
    if (!rate || !std::isfinite(*rate) || *rate < 0.0) {
      return RowFailure{fields_[2].column,
                        "Frame Rate is not a finite non-negative number: " + text::quoted_excerpt(fields_[2].text)};
    }
    const auto ts = text::parse_int(fields_[3].text);
    if (!ts)
      return RowFailure{fields_[3].column,
                        "Time Stamp is not an integer (µs): " + text::quoted_excerpt(fields_[3].text)};
    if (*ts > kMaxAbsTimestampUs || *ts < -kMaxAbsTimestampUs) {
      return RowFailure{fields_[3].column, "Time Stamp " + text::quoted_excerpt(fields_[3].text) +
                                               " µs is implausible (beyond ±2^53 µs, about 285 years)"};
    }
    frame.device_id = static_cast<int>(*id);
    frame.frame_id = *frame_id;
    frame.frame_rate_hz = *rate;
    frame.timestamp_us = *ts;
    return std::nullopt;
  }

  std::optional<RowFailure> parse_triplets(ParsedRow& row) {
    const size_t n = fields_.size();
    if (n == static_cast<size_t>(kMetaColumns)) {
      // Raw recording: the device saw no hand, the row ends after the timestamp.
      row.short_no_hand = true;
      set_no_hand(row.frame);
      return std::nullopt;
    }
    if (n != static_cast<size_t>(kPointColumns)) return count_failure(kPointColumns, "4 (no hand) or 34");
    int finite = 0;
    for (int p = 0; p < kNumHandPoints; ++p) {
      const text::Field& field = fields_[static_cast<size_t>(kMetaColumns + p)];
      if (read_plain_triplet(field.text, buffer_end_, row.frame.points[static_cast<size_t>(p)], finite)) continue;
      std::string_view rest = field.text;
      long column = field.column;
      for (int a = 0; a < 3; ++a) {
        const size_t comma = rest.find(',');
        const bool last = a == 2;
        if (last != (comma == std::string_view::npos)) {
          return RowFailure{field.column, "point '" + std::string(hand_point_name(p)) +
                                              "' must be 3 comma-separated numbers x,y,z, found " +
                                              text::quoted_excerpt(field.text)};
        }
        const std::string_view part = last ? rest : rest.substr(0, comma);
        const auto v = text::parse_double(part);
        if (!v) {
          return RowFailure{column, "point '" + std::string(hand_point_name(p)) + "' " + kAxes[static_cast<size_t>(a)] +
                                        " is not a number: " + text::quoted_excerpt(part)};
        }
        if (is_implausible(*v)) {
          return implausible_coordinate(
              *v, column, "point '" + std::string(hand_point_name(p)) + "' " + kAxes[static_cast<size_t>(a)], part);
        }
        row.frame.points[static_cast<size_t>(p)][a] = *v;
        finite += std::isfinite(*v) ? 1 : 0;
        if (!last) {
          rest.remove_prefix(comma + 1);
          column += static_cast<long>(comma) + 1;
        }
      }
    }
    classify(row, finite);
    return std::nullopt;
  }

  // "x,y,z" of three bare numbers, none implausible, read in one pass: nearly every field of a
  // recording. Anything else (spaces, a '+', a bad or implausible value) returns false having
  // stored nothing, and the field is read again by the checks above, which name what is wrong.
  static bool read_plain_triplet(std::string_view text, const char* buffer_end, Vec3& point, int& finite) {
    const char* at = text.data();
    const char* const end = text.data() + text.size();
    double xyz[3];
    for (int a = 0; a < 3; ++a) {
      const char* ptr = read_plain_decimal(at, end, buffer_end, xyz[a]);
      if (ptr == nullptr) {
        const auto [general_end, ec] = std::from_chars(at, end, xyz[a], std::chars_format::general);
        if (ec != std::errc{} || general_end == at) return false;
        ptr = general_end;
      }
      if (is_implausible(xyz[a])) return false;
      if (a < 2) {
        if (ptr == end || *ptr != ',') return false;
        at = ptr + 1;
      } else if (ptr != end) {
        return false;
      }
    }
    for (int a = 0; a < 3; ++a) {
      point[a] = xyz[a];
      finite += std::isfinite(xyz[a]) ? 1 : 0;
    }
    return true;
  }

  std::optional<RowFailure> parse_split(ParsedRow& row) {
    if (fields_.size() != static_cast<size_t>(kSplitColumns)) {
      return count_failure(kSplitColumns, "99 (4 bookkeeping, 90 coordinates, 5 visibility labels)");
    }
    int finite = 0;
    for (int c = 0; c < 3 * kNumHandPoints; ++c) {
      const text::Field& field = fields_[static_cast<size_t>(kMetaColumns + c)];
      const auto v = text::parse_double(field.text);
      if (!v) {
        return RowFailure{field.column, "'" + std::string(hand_point_name(c / 3)) + "." +
                                            kAxes[static_cast<size_t>(c % 3)] +
                                            "' is not a number: " + text::quoted_excerpt(field.text)};
      }
      if (is_implausible(*v)) {
        return implausible_coordinate(
            *v, field.column, "'" + std::string(hand_point_name(c / 3)) + "." + kAxes[static_cast<size_t>(c % 3)] + "'",
            field.text);
      }
      row.frame.points[static_cast<size_t>(c / 3)][c % 3] = *v;
      finite += std::isfinite(*v) ? 1 : 0;
    }
    for (int d = 0; d < kNumDigits; ++d) {
      const text::Field& field = fields_[static_cast<size_t>(kMetaColumns + 3 * kNumHandPoints + d)];
      const auto v = text::parse_double(field.text);
      if (!v || (*v != 1.0 && *v != 0.0 && *v != -1.0)) {
        return RowFailure{field.column, "visibility_" + std::string(digit_name(d)) + " must be 1, 0 or -1, found " +
                                            text::quoted_excerpt(field.text)};
      }
      row.labels[static_cast<size_t>(d)] = static_cast<std::int8_t>(*v);
    }
    classify(row, finite);
    return std::nullopt;
  }

  // NaN is how the formats write "missing"; infinity and magnitudes no controller can measure are
  // refused with the value, so they cannot pass as a hand or as "missing". The test comes apart from
  // the message so that a coordinate's name is built only for a message (a trial has tens of
  // thousands of coordinates).
  static bool is_implausible(double v) {
    return std::isinf(v) || (std::isfinite(v) && std::fabs(v) > kMaxAbsCoordinateMm);
  }
  // The message for a value is_implausible() refused.
  static RowFailure implausible_coordinate(double v, long column, const std::string& what, std::string_view text) {
    if (std::isinf(v)) {
      return RowFailure{
          column, what + " is infinite: " + text::quoted_excerpt(text) + " (a missing coordinate is written nan)"};
    }
    return RowFailure{column, what + " = " + text::quoted_excerpt(text) + " mm is implausible (more than " +
                                  std::to_string(static_cast<int>(kMaxAbsCoordinateMm / 1000.0)) +
                                  " m from the controller)"};
  }

  static void classify(ParsedRow& row, int finite) {
    constexpr int kAll = 3 * kNumHandPoints;
    row.frame.hand_present = finite == kAll;
    row.all_nan = finite == 0;
    row.partial = finite > 0 && finite < kAll;
  }

  static void set_no_hand(HandFrame& frame) {
    frame.hand_present = false;
    for (auto& p : frame.points) p.setConstant(kNaN);
  }

  HeaderInfo header_;
  const char* buffer_end_ = nullptr;
  std::vector<text::Field> fields_;
  long line_length_ = 0;
};

// The authors' raytraced files pad every value with one space each side ("␠1␠␠␠0␠␠␠100␠"), and
// names with spaces are written with two ("Device␠␠ID"); we write the same so their tools and
// ours read each other's files.
void append_padded(std::string& out, std::string_view value, bool first) {
  if (!first) out += ' ';
  out += ' ';
  out += value;
  out += ' ';
}

std::string label_text(std::int8_t label) {
  // Authors' files print the labels as floats: "1.0", "0.0", "-1.0".
  return label > 0 ? "1.0" : (label < 0 ? "-1.0" : "0.0");
}

}  // namespace

std::vector<int> LmcRecording::device_ids() const {
  std::set<int> ids;
  for (const auto& r : rows) ids.insert(r.device_id);
  return {ids.begin(), ids.end()};
}

LmcRecording parse_lmc_recording(std::istream& in, const std::string& source_name) {
  return parse_lmc_recording_text(text::read_stream_bytes(in), source_name);
}

LmcRecording parse_lmc_recording_text(std::string_view content, const std::string& source_name) {
  if (text::is_blank(text::without_bom(content)))
    text::fail_at(source_name, 1, 0, "empty file: expected an LMC recording header ('Device ID …')");
  text::require_text(content, source_name);
  const auto lines = text::split_lines(content);
  const HeaderInfo header = read_header(lines.front(), source_name);

  LmcRecording rec;
  rec.source = source_name;
  RowParser parser(header, content.data() + content.size());
  ParsedRow row;
  bool any_short_no_hand = false;
  bool any_all_nan = false;
  bool all_resample_stamps = true;  // Frame ID 0 and Frame Rate 100 on every row
  long partial_rows = 0;
  long first_partial_line = 0;
  // Whether every line so far ends with the separator, as the authors' and our writers do. A
  // last line that does not, with no final newline either, was cut off mid-field.
  bool lines_end_with_separator = header.ends_with_separator;
  const char separator = header.whitespace_separated ? ' ' : '\t';
  rec.rows.reserve(lines.size());

  for (size_t i = 1; i < lines.size(); ++i) {
    const text::Line& line = lines[i];
    if (text::is_blank(line.text)) continue;
    const bool unterminated = !line.has_newline;
    const bool ends_with_sep = line.text.back() == separator;
    auto failure = parser.parse(line.text, row);
    // A write cut inside the last field (a full disk mid-point: "x,y") fails on that field.
    const size_t last_sep = line.text.rfind(separator);
    const long last_field_column = last_sep == std::string_view::npos ? 1 : static_cast<long>(last_sep) + 2;
    const bool cut_in_last_field = failure && failure->column >= last_field_column;
    if (unterminated &&
        (failure ? failure->short_row || cut_in_last_field : (lines_end_with_separator && !ends_with_sep))) {
      rec.warnings.push_back(format_error(
          ErrorLocation{source_name, line.number},
          "last line is incomplete (no final newline" +
              std::string(failure && failure->short_row ? ", too few fields" : ", cut off mid-field") +
              "); dropped it and kept the " + std::to_string(rec.rows.size()) + " complete rows before it"));
      break;
    }
    if (failure) text::fail_at(source_name, line.number, failure->column, failure->message);
    lines_end_with_separator = lines_end_with_separator && ends_with_sep;
    any_short_no_hand = any_short_no_hand || row.short_no_hand;
    any_all_nan = any_all_nan || row.all_nan;
    all_resample_stamps = all_resample_stamps && row.frame.frame_id == 0 && row.frame.frame_rate_hz == 100.0;
    if (row.partial) {
      if (partial_rows == 0) first_partial_line = line.number;
      ++partial_rows;
    }
    rec.rows.push_back(row.frame);
    rec.lines.push_back(line.number);
    if (header.style == ColumnStyle::kSplitNumbers) rec.visibility.push_back(row.labels);
  }

  if (partial_rows > 0) {
    rec.warnings.push_back(
        format_error(ErrorLocation{source_name, first_partial_line},
                     std::to_string(partial_rows) +
                         " row(s) have some coordinates missing (NaN) but not all; they are treated as 'no hand'"));
  }

  if (header.style == ColumnStyle::kSplitNumbers) {
    rec.kind = RecordingKind::kRaytraced;
  } else if (any_short_no_hand) {
    rec.kind = RecordingKind::kRaw;  // only the raw writer ends no-hand rows after the timestamp
  } else if (any_all_nan || (!rec.rows.empty() && all_resample_stamps)) {
    // The resampler writes "nan,nan,nan" for no hand and stamps Frame ID 0, Frame Rate 100.
    rec.kind = RecordingKind::kResampled;
  } else {
    rec.kind = RecordingKind::kRaw;
  }
  return rec;
}

LmcRecording read_lmc_recording(const std::filesystem::path& path) {
  const std::string source = path.string();
  const std::string bytes = text::read_text_file(path, "an LMC recording", [&](std::string_view first_line) {
    if (!text::is_blank(first_line)) (void)read_header(text::Line{first_line, 1, true}, source);
  });
  return parse_lmc_recording_text(bytes, source);
}

std::string lmc_recording_header(RecordingKind kind) {
  std::string out;
  if (kind == RecordingKind::kRaytraced) {
    bool first = true;
    for (const auto& name : split_column_names()) {
      std::string padded;
      for (const char c : name) padded += c == ' ' ? std::string("  ") : std::string(1, c);
      append_padded(out, padded, first);
      first = false;
    }
  } else {
    for (const auto& name : triplet_column_names()) {
      out += name;
      out += '\t';
    }
  }
  out += '\n';
  return out;
}

namespace {

// The longest row append_lmc_row writes for a raw or resampled recording: four integers, 90
// numbers in their shortest form, their separators.
constexpr size_t kIntChars = 24;
constexpr size_t kMaxPlainRowChars = 4 * (kIntChars + 1) + kNumHandPoints * 3 * (text::kMaxDoubleChars + 1) + 1;

// Room reserved per row. A resampled recording (a trial's grid, or a fused track of full-precision
// numbers) gets its longest row: its rows are often longer than a raw one's, and when the string
// outgrew its room it copied itself whole. A raw recording, which may be an hour long, gets a
// typical row; pages reserved and never written cost nothing, but a reservation is not free.
size_t row_chars_to_reserve(RecordingKind kind) {
  switch (kind) {
    case RecordingKind::kRaytraced:
      return 1400;
    case RecordingKind::kResampled:
      return kMaxPlainRowChars;
    case RecordingKind::kRaw:
      break;
  }
  return 1700;
}

}  // namespace

std::string format_lmc_row(const HandFrame& frame, RecordingKind kind, const FingerLabels* labels) {
  std::string out;
  out.reserve(row_chars_to_reserve(kind));
  append_lmc_row(out, frame, kind, labels);
  return out;
}

void append_lmc_row(std::string& out, const HandFrame& frame, RecordingKind kind, const FingerLabels* labels) {
  if (kind == RecordingKind::kRaytraced) {
    std::string value;
    const auto put_int = [&](std::int64_t v, bool first) {
      value.clear();
      text::append_int(value, v);
      append_padded(out, value, first);
    };
    const auto put_double = [&](double v, bool float_style) {
      value.clear();
      text::append_double(value, v);
      // The authors' coordinate columns are floats printed Python-style: 99.0, not 99.
      if (float_style && value.find_first_of(".eni") == std::string::npos) value += ".0";
      append_padded(out, value, false);
    };
    put_int(frame.device_id, true);
    put_int(frame.frame_id, false);
    put_double(frame.frame_rate_hz, false);
    put_int(frame.timestamp_us, false);
    for (const auto& p : frame.points) {
      for (int a = 0; a < 3; ++a) put_double(frame.hand_present ? p[a] : kNaN, true);
    }
    for (int d = 0; d < kNumDigits; ++d) {
      std::int8_t label = -1;
      if (labels != nullptr) {
        label = (*labels)[static_cast<size_t>(d)];
      } else if (frame.hand_present) {
        throw Error("raytraced row of device " + std::to_string(frame.device_id) + " at " +
                    std::to_string(frame.timestamp_us) + " µs has a hand but no visibility labels");
      }
      append_padded(out, label_text(label), false);
    }
    out += '\n';
    return;
  }
  // The row is built in a buffer of its own and appended once: a subject's fused files are
  // millions of numbers, and growing the string number by number costs a check and a possible
  // reallocation per number.
  std::array<char, kMaxPlainRowChars> row;
  char* at = row.data();
  const auto put_int = [&](std::int64_t v) {
    at = std::to_chars(at, at + kIntChars, v).ptr;
    *at++ = '\t';
  };
  put_int(frame.device_id);
  put_int(frame.frame_id);
  at = text::write_double(at, frame.frame_rate_hz);
  *at++ = '\t';
  put_int(frame.timestamp_us);
  if (frame.hand_present) {
    for (const auto& p : frame.points) {
      at = text::write_double(at, p.x());
      *at++ = ',';
      at = text::write_double(at, p.y());
      *at++ = ',';
      at = text::write_double(at, p.z());
      *at++ = '\t';
    }
  } else if (kind == RecordingKind::kResampled) {
    for (int i = 0; i < kNumHandPoints; ++i) {
      std::memcpy(at, "nan,nan,nan\t", 12);
      at += 12;
    }
  }
  *at++ = '\n';
  out.append(row.data(), at);
}

std::string format_lmc_recording(const LmcRecording& recording) {
  if (recording.kind == RecordingKind::kRaytraced && recording.visibility.size() != recording.rows.size()) {
    throw Error("raytraced recording has " + std::to_string(recording.rows.size()) + " rows but " +
                std::to_string(recording.visibility.size()) + " visibility label sets");
  }
  std::string out = lmc_recording_header(recording.kind);
  out.reserve(out.size() + recording.rows.size() * row_chars_to_reserve(recording.kind));
  for (size_t i = 0; i < recording.rows.size(); ++i) {
    const FingerLabels* labels = recording.kind == RecordingKind::kRaytraced ? &recording.visibility[i] : nullptr;
    append_lmc_row(out, recording.rows[i], recording.kind, labels);
  }
  return out;
}

void write_lmc_recording(std::ostream& out, const LmcRecording& recording) {
  out << format_lmc_recording(recording);
}

void save_lmc_recording(const std::filesystem::path& path, const LmcRecording& recording) {
  write_file_atomically(path, format_lmc_recording(recording));
}

}  // namespace lmc
