#include "core/io/trc.h"

#include <cmath>
#include <istream>
#include <limits>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>

#include "core/common/error.h"
#include "core/common/nan.h"
#include "core/io/atomic_write.h"
#include "core/io/delimited_text.h"

namespace lmc {
namespace {

constexpr int kHeaderLines = 5;  // PathFileType, keys, values, marker names, X1 Y1 Z1 … (docs/formats.md)

bool known_units(const std::string& units) {
  return units == "mm" || units == "m";
}

// Header line 2 (keys) and 3 (values) as key → value field, keeping each value's column.
std::map<std::string, text::Field> header_values(const text::Line& keys, const text::Line& values,
                                                 const std::string& source) {
  std::vector<text::Field> k;
  std::vector<text::Field> v;
  text::split_fields(keys.text, '\t', k);
  text::split_fields(values.text, '\t', v);
  while (!k.empty() && text::is_blank(k.back().text)) k.pop_back();
  std::map<std::string, text::Field> out;
  for (size_t i = 0; i < k.size(); ++i) {
    const std::string key(text::trim(k[i].text));
    if (i >= v.size() || text::is_blank(v[i].text)) {
      text::fail_at(source, values.number, i < v.size() ? v[i].column : 0, "no value for header key '" + key + "'");
    }
    out[key] = text::Field{text::trim(v[i].text), v[i].column};
  }
  return out;
}

// A data row of plain numbers only, read in one pass: "Frame#<tab>Time<tab>X1<tab>…" with every
// cell a plain decimal (plain_decimal.h), none beyond `max_coordinate`, and nothing after the last
// but tabs or spaces. Nearly every row of a real or simulated file. Anything else (a blank cell, an
// exponent, a '+', a bad value) returns false, and the row is read again by the checks in
// parse_trc_text, which name what is wrong; the values are the same either way.
struct PlainRow {
  std::int64_t frame = 0;
  double time = 0.0;
  long zero_samples = 0;
};
bool read_plain_trc_row(std::string_view text, const char* buffer_end, int markers, double max_coordinate,
                        PlainRow& row, std::vector<Eigen::Vector3d>& positions) {
  const char* at = text.data();
  const char* const end = text.data() + text.size();
  // Frame#: digits only (parse_int reads them alike).
  const char* const digits = at;
  std::int64_t frame = 0;
  while (at != end && *at >= '0' && *at <= '9' && at - digits < 18) frame = frame * 10 + (*at++ - '0');
  if (at == digits || at == end || *at != '\t') return false;
  double time = 0.0;
  at = read_plain_decimal(at + 1, end, buffer_end, time);
  if (at == nullptr || at == end || *at != '\t') return false;
  ++at;
  long zeros = 0;
  for (int m = 0; m < markers; ++m) {
    double xyz[3];
    for (int a = 0; a < 3; ++a) {
      at = read_plain_decimal(at, end, buffer_end, xyz[a]);
      if (at == nullptr || std::fabs(xyz[a]) > max_coordinate) return false;
      const bool last = m == markers - 1 && a == 2;
      if (!last) {
        if (at == end || *at != '\t') return false;
        ++at;
      }
    }
    Eigen::Vector3d& p = positions[static_cast<size_t>(m)];
    p = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
    if (p.isZero(0.0)) {
      // Some exporters write 0 0 0 for a gap (docs/formats.md), as in parse_trc_text.
      ++zeros;
      p.setConstant(kNaN);
    }
  }
  for (; at != end; ++at) {
    if (*at != '\t' && *at != ' ') return false;
  }
  row.frame = frame;
  row.time = time;
  row.zero_samples = zeros;
  return true;
}

}  // namespace

int TrcData::marker_index(const std::string& name) const {
  for (size_t i = 0; i < marker_names.size(); ++i) {
    if (marker_names[i] == name) return static_cast<int>(i);
  }
  return -1;
}

void TrcData::to_millimetres() {
  if (units == "mm") return;
  if (units != "m") throw Error("unknown TRC units '" + units + "' (expected mm or m)");
  for (auto& frame : positions) {
    for (auto& p : frame) p *= 1000.0;
  }
  units = "mm";
}

namespace {

// The one rule for a TRC's first line, used before the rest of a file is read and by the parser.
void check_trc_first_line(std::string_view line, const std::string& source_name) {
  std::vector<text::Field> fields;
  text::split_fields(line, '\t', fields);
  if (text::trim(fields[0].text) != "PathFileType") {
    text::fail_at(
        source_name, 1, 1,
        "not a TRC file: the first line must start with 'PathFileType', found " + text::quoted_excerpt(fields[0].text));
  }
}

}  // namespace

TrcData parse_trc(std::istream& in, const std::string& source_name) {
  return parse_trc_text(text::read_stream_bytes(in), source_name);
}

namespace {

// What the header says the file holds, checked against the file once it is read.
struct TrcHeaderCounts {
  int markers = 0;
  int frames = -1;  // −1: no NumFrames in the header (a plain int: GCC 12 warns falsely on an optional here at -O1)
};

// Header lines 2 and 3 (keys and values): rates, units, counts and the first frame's number.
TrcHeaderCounts read_trc_header_values(const std::vector<text::Line>& lines, const std::string& source_name,
                                       TrcData& trc) {
  const text::Line& values_line = lines[2];
  const auto header = header_values(lines[1], values_line, source_name);
  const auto require = [&](const char* key) -> const text::Field& {
    const auto it = header.find(key);
    if (it == header.end()) text::fail_at(source_name, 2, 0, std::string("TRC header has no '") + key + "' key");
    return it->second;
  };
  const auto rate_of = [&](const text::Field& f, const char* key) {
    const auto v = text::parse_double(f.text);
    if (!v || !std::isfinite(*v) || *v <= 0.0) {
      text::fail_at(source_name, values_line.number, f.column,
                    std::string(key) + " must be a positive number, found " + text::quoted_excerpt(f.text));
    }
    return *v;
  };
  const auto int_of = [&](const text::Field& f, const char* key) {
    const auto v = text::parse_int(f.text);
    if (!v || *v < 0 || *v > std::numeric_limits<int>::max()) {
      text::fail_at(source_name, values_line.number, f.column,
                    std::string(key) + " must be a non-negative integer, found " + text::quoted_excerpt(f.text));
    }
    return static_cast<int>(*v);
  };

  trc.data_rate_hz = rate_of(require("DataRate"), "DataRate");
  const auto cam = header.find("CameraRate");
  trc.camera_rate_hz = cam == header.end() ? trc.data_rate_hz : rate_of(cam->second, "CameraRate");
  const text::Field& units = require("Units");
  trc.units = std::string(units.text);
  if (!known_units(trc.units)) {
    text::fail_at(source_name, values_line.number, units.column,
                  "unknown units " + text::quoted_excerpt(units.text) + " (expected mm or m)");
  }
  TrcHeaderCounts counts;
  counts.markers = int_of(require("NumMarkers"), "NumMarkers");
  const auto nf = header.find("NumFrames");
  counts.frames = nf == header.end() ? -1 : int_of(nf->second, "NumFrames");
  const auto start = header.find("OrigDataStartFrame");
  trc.orig_data_start_frame = start == header.end() ? 1 : int_of(start->second, "OrigDataStartFrame");
  return counts;
}

// Header lines 4 and 5: Frame#, Time, then each marker name followed by two empty cells; then two
// empty cells and X1 Y1 Z1 X2 …
void read_trc_marker_names(const std::vector<text::Line>& lines, const std::string& source_name,
                           const TrcHeaderCounts& counts, TrcData& trc) {
  std::vector<text::Field> fields;
  const text::Line& names_line = lines[3];
  text::split_fields(names_line.text, '\t', fields);
  if (fields.size() < 2 || text::normalise_name(fields[0].text) != "frame#" ||
      text::normalise_name(fields[1].text) != "time") {
    text::fail_at(source_name, names_line.number, 1, "expected the column line 'Frame#<tab>Time<tab><markers…>'");
  }
  for (size_t i = 2; i < fields.size(); ++i) {
    if (text::is_blank(fields[i].text)) continue;
    if ((i - 2) % 3 != 0) {
      text::fail_at(
          source_name, names_line.number, fields[i].column,
          "marker name " + text::quoted_excerpt(fields[i].text) + " is not at the start of an X/Y/Z column triple");
    }
    trc.marker_names.emplace_back(text::trim(fields[i].text));
  }
  const int markers = trc.marker_count();
  if (markers != counts.markers) {
    trc.warnings.push_back(format_error(ErrorLocation{source_name, lines[2].number},
                                        "header says NumMarkers " + std::to_string(counts.markers) +
                                            " but the column line names " + std::to_string(markers) +
                                            "; using the names"));
  }
  text::split_fields(lines[4].text, '\t', fields);
  if (markers > 0 && (fields.size() < 3 || text::normalise_name(fields[2].text) != "x1")) {
    text::fail_at(source_name, lines[4].number, fields.size() >= 3 ? fields[2].column : 0,
                  "expected the coordinate line '<tab><tab>X1<tab>Y1<tab>Z1…'");
  }
}

// Marker samples the data rows read as missing, for the warnings.
struct TrcGapCounts {
  long partial_samples = 0;  // only some of X/Y/Z
  long zero_samples = 0;     // 0,0,0
};

// One marker's X, Y, Z from a checked row's cells from `first`: a blank or NaN cell makes the
// sample missing, 0,0,0 too; anything else that is not a plausible finite number is an error
// naming the cell.
Eigen::Vector3d read_trc_sample(const std::vector<text::Field>& fields, size_t first, int m, const text::Line& line,
                                double max_coordinate, const std::string& source_name, const TrcData& trc,
                                TrcGapCounts& gaps) {
  Eigen::Vector3d p;
  int missing = 0;
  for (int a = 0; a < 3; ++a) {
    const text::Field& cell = fields[first + static_cast<size_t>(a)];
    if (text::is_blank(cell.text)) {
      p[a] = kNaN;
      ++missing;
      continue;
    }
    const auto v = text::parse_double(cell.text);
    // The cell's name is built only for a message: a trial's file holds tens of thousands of cells.
    const auto what = [&] {
      return "marker '" + trc.marker_names[static_cast<size_t>(m)] + "' " + static_cast<char>('X' + a);
    };
    if (!v)
      text::fail_at(source_name, line.number, cell.column,
                    what() + " is not a number: " + text::quoted_excerpt(cell.text));
    // Infinity is no gap (a gap is blank or NaN), and a magnitude no capture volume holds
    // (1e308) would turn every later computation into NaN or overflow.
    if (std::isinf(*v))
      text::fail_at(source_name, line.number, cell.column, what() + " is infinite: " + text::quoted_excerpt(cell.text));
    if (std::fabs(*v) > max_coordinate) {
      text::fail_at(source_name, line.number, cell.column,
                    what() + " = " + text::quoted_excerpt(cell.text) + " " + trc.units +
                        " is implausible (more than 100 m from the lab origin)");
    }
    p[a] = *v;
    missing += std::isnan(*v) ? 1 : 0;
  }
  if (missing > 0) {
    gaps.partial_samples += missing < 3 ? 1 : 0;
    p.setConstant(kNaN);
  } else if (p.isZero(0.0)) {
    // Some exporters write 0 0 0 for a gap (docs/formats.md).
    ++gaps.zero_samples;
    p.setConstant(kNaN);
  }
  return p;
}

// A data row that is not all plain numbers, read field by field with checks that name what is
// wrong. False when it is an incomplete last line (dropped, with a warning): reading ends there.
bool read_checked_trc_row(const text::Line& line, std::vector<text::Field>& fields, double max_coordinate,
                          const std::string& source_name, TrcData& trc, TrcGapCounts& gaps) {
  const int markers = trc.marker_count();
  const size_t expected = 2 + 3 * static_cast<size_t>(markers);
  text::split_fields(line.text, '\t', fields);
  while (fields.size() > expected && text::is_blank(fields.back().text)) fields.pop_back();
  if (fields.size() != expected) {
    if (!line.has_newline && fields.size() < expected) {
      trc.warnings.push_back(format_error(ErrorLocation{source_name, line.number},
                                          "last line is incomplete (no final newline, " +
                                              std::to_string(fields.size()) + " of " + std::to_string(expected) +
                                              " fields); dropped it and kept the " +
                                              std::to_string(trc.positions.size()) + " complete rows before it"));
      return false;
    }
    text::fail_at(source_name, line.number,
                  fields.size() > expected ? fields[expected].column : static_cast<long>(line.text.size()) + 1,
                  "row has " + std::to_string(fields.size()) + " fields; expected " + std::to_string(expected) +
                      " (Frame#, Time and 3 per marker for " + std::to_string(markers) + " markers)");
  }
  const auto frame = text::parse_int(fields[0].text);
  if (!frame)
    text::fail_at(source_name, line.number, fields[0].column,
                  "Frame# is not an integer: " + text::quoted_excerpt(fields[0].text));
  const auto time = text::parse_double(fields[1].text);
  if (!time || !std::isfinite(*time)) {
    text::fail_at(source_name, line.number, fields[1].column,
                  "Time is not a finite number: " + text::quoted_excerpt(fields[1].text));
  }
  std::vector<Eigen::Vector3d> row(static_cast<size_t>(markers));
  for (int m = 0; m < markers; ++m) {
    row[static_cast<size_t>(m)] =
        read_trc_sample(fields, static_cast<size_t>(2 + 3 * m), m, line, max_coordinate, source_name, trc, gaps);
  }
  trc.frame_numbers.push_back(static_cast<int>(*frame));
  trc.times_s.push_back(*time);
  trc.positions.push_back(std::move(row));
  return true;
}

// The data rows after the header: plain rows in one pass, any other row with its checks.
// OpenSim expects a blank line after the X1/Y1 line; the study's file has none. Both are read.
TrcGapCounts read_trc_rows(const std::vector<text::Line>& lines, std::string_view content,
                           const std::string& source_name, TrcData& trc) {
  const int markers = trc.marker_count();
  TrcGapCounts gaps;
  std::vector<text::Field> fields;
  const double max_coordinate = trc.units == "m" ? 100.0 : 100000.0;
  for (size_t i = kHeaderLines; i < lines.size(); ++i) {
    const text::Line& line = lines[i];
    if (text::is_blank(line.text)) continue;
    if (markers > 0) {
      std::vector<Eigen::Vector3d> row(static_cast<size_t>(markers));
      PlainRow plain;
      if (read_plain_trc_row(line.text, content.data() + content.size(), markers, max_coordinate, plain, row)) {
        gaps.zero_samples += plain.zero_samples;
        trc.frame_numbers.push_back(static_cast<int>(plain.frame));
        trc.times_s.push_back(plain.time);
        trc.positions.push_back(std::move(row));
        continue;
      }
    }
    if (!read_checked_trc_row(line, fields, max_coordinate, source_name, trc, gaps)) break;
  }
  return gaps;
}

// Warnings for what the header said and the rows did not hold, and for samples read as missing.
void warn_trc_counts(const TrcHeaderCounts& counts, const TrcGapCounts& gaps, long values_line,
                     const std::string& source_name, TrcData& trc) {
  if (counts.frames >= 0 && counts.frames != trc.frame_count()) {
    trc.warnings.push_back(format_error(ErrorLocation{source_name, values_line},
                                        "header says NumFrames " + std::to_string(counts.frames) +
                                            " but the file holds " + std::to_string(trc.frame_count()) +
                                            " rows; using the rows"));
  }
  if (gaps.partial_samples > 0) {
    trc.warnings.push_back(format_error(
        ErrorLocation{source_name},
        std::to_string(gaps.partial_samples) + " marker sample(s) had only some of X/Y/Z; read as missing"));
  }
  if (gaps.zero_samples > 0) {
    trc.warnings.push_back(format_error(
        ErrorLocation{source_name},
        std::to_string(gaps.zero_samples) + " marker sample(s) were 0,0,0 (an exporter's gap); read as missing"));
  }
}

}  // namespace

TrcData parse_trc_text(std::string_view content, const std::string& source_name) {
  if (text::is_blank(text::without_bom(content)))
    text::fail_at(source_name, 1, 0, "empty file: expected a TRC header ('PathFileType …')");
  text::require_text(content, source_name);
  const auto lines = text::split_lines(content);
  check_trc_first_line(lines[0].text, source_name);
  if (lines.size() < static_cast<size_t>(kHeaderLines)) {
    text::fail_at(source_name, static_cast<long>(lines.size()), 0,
                  "TRC header is incomplete: expected " + std::to_string(kHeaderLines) + " header lines, found " +
                      std::to_string(lines.size()));
  }
  TrcData trc;
  const TrcHeaderCounts counts = read_trc_header_values(lines, source_name, trc);
  read_trc_marker_names(lines, source_name, counts, trc);
  const TrcGapCounts gaps = read_trc_rows(lines, content, source_name, trc);
  warn_trc_counts(counts, gaps, lines[2].number, source_name, trc);
  return trc;
}

TrcData read_trc(const std::filesystem::path& path) {
  const std::string source = path.string();
  const std::string bytes = text::read_text_file(
      path, "a TRC file", [&](std::string_view first_line) { check_trc_first_line(first_line, source); });
  return parse_trc_text(bytes, source);
}

void write_trc(std::ostream& out, const TrcData& trc, const std::string& path_field) {
  if (!known_units(trc.units))
    throw Error("cannot write TRC with unknown units '" + trc.units + "' (expected mm or m)");
  const int frames = trc.frame_count();
  const int markers = trc.marker_count();
  for (int f = 0; f < frames; ++f) {
    if (trc.positions[static_cast<size_t>(f)].size() != static_cast<size_t>(markers)) {
      throw Error("TRC frame " + std::to_string(f) + " has " +
                  std::to_string(trc.positions[static_cast<size_t>(f)].size()) + " positions for " +
                  std::to_string(markers) + " markers");
    }
  }
  const bool have_numbers = trc.frame_numbers.size() == static_cast<size_t>(frames);
  const bool have_times = trc.times_s.size() == static_cast<size_t>(frames);

  std::string s;
  s += "PathFileType\t4\t(X/Y/Z)\t" + path_field + "\n";
  s += "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n";
  text::append_double(s, trc.data_rate_hz);
  s += '\t';
  text::append_double(s, trc.camera_rate_hz);
  s += '\t' + std::to_string(frames) + '\t' + std::to_string(markers) + '\t' + trc.units + '\t';
  text::append_double(s, trc.data_rate_hz);
  s += '\t' + std::to_string(trc.orig_data_start_frame) + '\t' + std::to_string(frames) + "\t\n";
  s += "Frame#\tTime\t";
  for (const auto& name : trc.marker_names) s += name + "\t\t\t";
  s += "\n\t\t";
  for (int m = 1; m <= markers; ++m) {
    const std::string k = std::to_string(m);
    s += "X" + k + "\tY" + k + "\tZ" + k + "\t";
  }
  // The blank line OpenSim expects (docs/formats.md); our reader accepts files with or without it.
  s += "\n\n";
  for (int f = 0; f < frames; ++f) {
    const int number = have_numbers ? trc.frame_numbers[static_cast<size_t>(f)] : trc.orig_data_start_frame + f;
    s += std::to_string(number);
    s += '\t';
    // Time of frame f = (f − OrigDataStartFrame)/DataRate when the caller gave none (docs/formats.md).
    text::append_double(
        s, have_times ? trc.times_s[static_cast<size_t>(f)] : (number - trc.orig_data_start_frame) / trc.data_rate_hz);
    for (const auto& p : trc.positions[static_cast<size_t>(f)]) {
      for (int a = 0; a < 3; ++a) {
        s += '\t';
        if (!std::isnan(p[a])) text::append_double(s, p[a]);  // missing marker: empty cell
      }
    }
    s += '\n';
  }
  out << s;
}

void save_trc(const std::filesystem::path& path, const TrcData& trc) {
  std::ostringstream out;
  write_trc(out, trc, path.string());
  write_file_atomically(path, out.str());
}

}  // namespace lmc
