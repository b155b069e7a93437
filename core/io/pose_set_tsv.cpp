#include "core/io/pose_set_tsv.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>
#include <vector>

#include "core/common/error.h"
#include "core/io/atomic_write.h"
#include "core/io/delimited_text.h"

namespace lmc {
namespace {

constexpr std::string_view kMagic = "# lmc-poses 1";
constexpr int kFixedColumns = 4;  // frame, orientation, motion, progress

void append_number(std::string& out, double v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, res.ptr);
}

std::vector<std::string_view> split_tabs(std::string_view line) {
  std::vector<std::string_view> out;
  size_t start = 0;
  while (true) {
    const size_t tab = line.find('\t', start);
    if (tab == std::string_view::npos) {
      out.push_back(line.substr(start));
      break;
    }
    out.push_back(line.substr(start, tab - start));
    start = tab + 1;
  }
  return out;
}

std::string header_line() {
  std::string h = "frame\torientation\tmotion\tprogress";
  for (int i = 0; i < kNumHandPoints; ++i) {
    for (const char* axis : {".x", ".y", ".z"}) {
      h += '\t';
      h += hand_point_name(i);
      h += axis;
    }
  }
  return h;
}

}  // namespace

void write_pose_set(std::ostream& out, const PoseSet& set) {
  std::string text;
  text.reserve(64 + set.frames.size() * 1800);
  text += kMagic;
  text += '\n';
  if (!set.description.empty()) {
    std::string desc = set.description;
    for (char& c : desc) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    text += "# description: " + desc + "\n";
  }
  for (std::string line : set.provenance) {
    for (char& c : line) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    text += "# provenance: " + line + "\n";
  }
  text += header_line();
  text += '\n';
  for (size_t j = 0; j < set.frames.size(); ++j) {
    const PoseLabel label = j < set.labels.size() ? set.labels[j] : PoseLabel{};
    text += std::to_string(j);
    text += '\t';
    text += orientation_name(label.orientation);
    text += '\t';
    text += motion_name(label.motion);
    text += '\t';
    append_number(text, label.progress);
    for (const auto& p : set.frames[j].points) {
      for (int a = 0; a < 3; ++a) {
        text += '\t';
        append_number(text, p[a]);
      }
    }
    text += '\n';
  }
  out << text;
}

void save_pose_set(const std::filesystem::path& path, const PoseSet& set) {
  std::ostringstream os;
  write_pose_set(os, set);
  write_file_atomically(path, os.str());
}

namespace {

// The one rule for a pose set's first line, used before a file is read and by the parser.
void check_pose_set_first_line(std::string_view line, const std::string& source) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line != kMagic)
    throw Error(ErrorLocation(source, 1, 1), "not a pose set: the first line must be \"" + std::string(kMagic) + "\"");
}

// A header line other than the expected one: the error names its first wrong column.
[[noreturn]] void refuse_pose_set_header(const std::string& line, const std::string& expected,
                                         const std::string& source, long line_no) {
  const auto got = split_tabs(line);
  const auto want = split_tabs(expected);
  for (size_t c = 0; c < want.size(); ++c) {
    if (c >= got.size())
      throw Error(ErrorLocation(source, line_no, static_cast<long>(c + 1)),
                  "header ends early; expected column \"" + std::string(want[c]) + "\"");
    if (got[c] != want[c]) {
      throw Error(
          ErrorLocation(source, line_no, static_cast<long>(c + 1)),
          "unexpected header column \"" + std::string(got[c]) + "\", expected \"" + std::string(want[c]) + "\"");
    }
  }
  throw Error(ErrorLocation(source, line_no, static_cast<long>(want.size() + 1)), "extra header columns");
}

// One data row's fields: frame `index` (checked against the column), its label and its points.
void parse_pose_set_row(const std::vector<std::string_view>& fields, size_t index, const std::string& source,
                        long line_no, PoseSet& set) {
  auto fail = [&](long column, const std::string& what) -> Error {
    return Error(ErrorLocation(source, line_no, column), what);
  };
  auto number = [&](size_t c) {
    double v = 0;
    const std::string_view f = fields[c];
    const auto res = std::from_chars(f.data(), f.data() + f.size(), v);
    if (res.ec != std::errc() || res.ptr != f.data() + f.size()) {
      throw fail(static_cast<long>(c + 1), "not a number: \"" + std::string(f) + "\"");
    }
    return v;
  };
  if (number(0) != static_cast<double>(index)) {
    throw fail(1, "frame index " + std::string(fields[0]) + " out of sequence; expected " + std::to_string(index));
  }
  PoseLabel label;
  const auto o = orientation_from_name(fields[1]);
  if (!o) throw fail(2, "unknown orientation \"" + std::string(fields[1]) + "\" (horizontal or vertical)");
  const auto m = motion_from_name(fields[2]);
  if (!m)
    throw fail(
        3, "unknown motion \"" + std::string(fields[2]) + "\" (open, index, thumb, wrist-flexion, wrist-extension)");
  label.orientation = *o;
  label.motion = *m;
  label.progress = number(3);
  HandFrame f;
  f.hand_present = true;
  f.frame_id = static_cast<std::int64_t>(index);
  for (int i = 0; i < kNumHandPoints; ++i) {
    for (int a = 0; a < 3; ++a) {
      const size_t c = static_cast<size_t>(kFixedColumns + 3 * i + a);
      const double v = number(c);
      if (!std::isfinite(v)) throw fail(static_cast<long>(c + 1), "coordinates must be finite");
      f.point(i)[a] = v;
    }
  }
  set.frames.push_back(f);
  set.labels.push_back(label);
}

}  // namespace

PoseSet parse_pose_set(std::istream& in, const std::string& source) {
  PoseSet set;
  std::string line;
  long line_no = 0;
  auto fail = [&](long column, const std::string& what) -> Error {
    return Error(ErrorLocation(source, line_no, column), what);
  };
  if (!std::getline(in, line)) {
    line_no = 1;
    throw fail(0, "empty file; expected a pose set starting with \"" + std::string(kMagic) + "\"");
  }
  ++line_no;
  check_pose_set_first_line(line, source);
  // Comments, then the header.
  const std::string expected_header = header_line();
  while (true) {
    if (!std::getline(in, line)) throw fail(0, "missing the column header line");
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty() && line[0] == '#') {
      constexpr std::string_view kDesc = "# description: ";
      constexpr std::string_view kProvenance = "# provenance: ";
      if (line.rfind(kDesc, 0) == 0) set.description = line.substr(kDesc.size());
      if (line.rfind(kProvenance, 0) == 0) set.provenance.push_back(line.substr(kProvenance.size()));
      continue;
    }
    if (line != expected_header) refuse_pose_set_header(line, expected_header, source, line_no);
    break;
  }
  const size_t ncols = static_cast<size_t>(kFixedColumns + 3 * kNumHandPoints);
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const auto fields = split_tabs(line);
    if (fields.size() != ncols) {
      throw fail(static_cast<long>(std::min(fields.size(), ncols) + 1),
                 "expected " + std::to_string(ncols) + " tab-separated fields, found " + std::to_string(fields.size()));
    }
    parse_pose_set_row(fields, set.frames.size(), source, line_no, set);
  }
  return set;
}

PoseSet load_pose_set(const std::filesystem::path& path) {
  const std::string source = path.string();
  std::istringstream in(text::read_text_file(
      path, "a pose set", [&](std::string_view first_line) { check_pose_set_first_line(first_line, source); }));
  return parse_pose_set(in, source);
}

}  // namespace lmc
