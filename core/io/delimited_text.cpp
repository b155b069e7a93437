#include "core/io/delimited_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <iterator>
#include <sstream>
#include <system_error>
#include <vector>

#include "core/common/error.h"
#include "core/common/shortest_double.h"

namespace lmc::text {

std::string read_file_bytes(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw Error(ErrorLocation{path.string()}, "is a folder, not a file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorLocation{path.string()}, "cannot open file for reading");
  std::string bytes = read_stream_bytes(in);
  if (in.bad()) throw Error(ErrorLocation{path.string()}, "read error");
  return bytes;
}

std::string read_text_file(const std::filesystem::path& path, const std::string& expected,
                           const std::function<void(std::string_view first_line)>& check_header) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Error(ErrorLocation{path.string()}, "is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorLocation{path.string()}, "cannot open file for reading");
  const auto size = std::filesystem::file_size(path, ec);
  std::string bytes(ec ? kMaxHeaderLineBytes : std::min<std::uintmax_t>(size, kMaxHeaderLineBytes), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<size_t>(in.gcount()));
  if (in.bad()) throw Error(ErrorLocation{path.string()}, "read error");
  const size_t newline = bytes.find('\n');
  const bool more = !in.eof() && in.peek() != std::char_traits<char>::eof();
  // What was read must be text before anything else is said about it (a binary file is named as
  // one); when the file goes on, the check stops short of a UTF-8 sequence the chunk may have cut.
  const size_t last_newline = bytes.rfind('\n');
  const size_t checked = !more                               ? bytes.size()
                         : last_newline != std::string::npos ? last_newline
                                                             : bytes.size() - std::min<size_t>(bytes.size(), 3);
  require_text(std::string_view(bytes).substr(0, checked), path.string());
  if (newline == std::string::npos && more)
    throw Error(ErrorLocation{path.string(), 1},
                "the first line is longer than " + std::to_string(kMaxHeaderLineBytes / 1024) + " KB: not " + expected);
  // A blank file is left to the parser, which names what it expected.
  if (!more && is_blank(without_bom(bytes))) return bytes;
  check_header(without_bom(std::string_view(bytes).substr(0, newline)));
  if (more) {
    // Read the rest into the same buffer, straight to its place: one copy of the file in memory,
    // and no second pass over it through a chunk.
    if (!ec && size > bytes.size()) {
      const size_t have = bytes.size();
      bytes.resize(static_cast<size_t>(size));
      in.read(bytes.data() + have, static_cast<std::streamsize>(bytes.size() - have));
      bytes.resize(have + static_cast<size_t>(in.gcount()));
    }
    // Whatever the file holds beyond the size it had when opened (one still being written).
    std::vector<char> chunk(1 << 16);
    while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0)
      bytes.append(chunk.data(), static_cast<size_t>(in.gcount()));
    if (in.bad()) throw Error(ErrorLocation{path.string()}, "read error");
  }
  return bytes;
}

std::string read_stream_bytes(std::istream& in) {
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return std::move(buffer).str();
}

namespace {

// Length of the UTF-8 sequence starting at s[i], or 0 when it is invalid (overlong forms,
// surrogates and code points above U+10FFFF count as invalid, per RFC 3629).
size_t utf8_sequence_length(std::string_view s, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = byte(i);
  if (c < 0x80) return 1;
  size_t len = 0;
  unsigned char lo = 0x80;
  unsigned char hi = 0xBF;
  if (c >= 0xC2 && c <= 0xDF) {
    len = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    len = 3;
    if (c == 0xE0) lo = 0xA0;
    if (c == 0xED) hi = 0x9F;
  } else if (c >= 0xF0 && c <= 0xF4) {
    len = 4;
    if (c == 0xF0) lo = 0x90;
    if (c == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (i + len > s.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (size_t k = 2; k < len; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return len;
}

}  // namespace

void require_text(std::string_view content, const std::string& source_name) {
  // Where a bad byte is, as an editor counts: line and column (in bytes) from 1.
  const auto location = [&](size_t i) {
    const std::string_view before = content.substr(0, i);
    const size_t line_start = before.rfind('\n') == std::string_view::npos ? 0 : before.rfind('\n') + 1;
    return ErrorLocation{source_name, 1 + static_cast<long>(std::count(before.begin(), before.end(), '\n')),
                         static_cast<long>(i - line_start) + 1};
  };
  constexpr std::uint64_t kOnes = 0x0101010101010101ULL;
  constexpr std::uint64_t kHighBits = 0x8080808080808080ULL;
  const size_t n = content.size();
  for (size_t i = 0; i < n;) {
    // ASCII without NUL is nearly every byte of a recording: skip it eight bytes at a time (a word
    // with no high bit and no zero byte), and look byte by byte only at what is left.
    while (i + 8 <= n) {
      std::uint64_t w = 0;
      std::memcpy(&w, content.data() + i, 8);
      if (((w | ((w - kOnes) & ~w)) & kHighBits) != 0) break;
      i += 8;
    }
    if (i >= n) break;
    const char c = content[i];
    if (c == '\0') {
      throw Error(location(i), "contains a NUL byte: this looks like a binary file, not a text recording");
    }
    const size_t len = utf8_sequence_length(content, i);
    if (len == 0) {
      throw Error(location(i), "invalid UTF-8 byte: this looks like a binary or non-UTF-8 file, not a text recording");
    }
    i += len;
  }
}

std::string_view without_bom(std::string_view content) {
  // A UTF-8 byte-order mark (some Windows editors add one) is not part of the first field.
  if (content.substr(0, 3) == "\xEF\xBB\xBF") content.remove_prefix(3);
  return content;
}

std::vector<Line> split_lines(std::string_view content) {
  std::vector<Line> lines;
  content = without_bom(content);
  size_t start = 0;
  long number = 1;
  while (start < content.size()) {
    const size_t end = content.find('\n', start);
    const bool has_newline = end != std::string_view::npos;
    std::string_view text = content.substr(start, has_newline ? end - start : std::string_view::npos);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    lines.push_back(Line{text, number, has_newline});
    if (!has_newline) break;
    start = end + 1;
    ++number;
  }
  return lines;
}

void split_fields(std::string_view line, char sep, std::vector<Field>& out) {
  out.clear();
  size_t start = 0;
  while (true) {
    const size_t end = line.find(sep, start);
    const size_t len = end == std::string_view::npos ? std::string_view::npos : end - start;
    out.push_back(Field{line.substr(start, len), static_cast<long>(start) + 1});
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
}

void split_whitespace(std::string_view line, std::vector<Field>& out) {
  out.clear();
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i >= line.size()) break;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    out.push_back(Field{line.substr(start, i - start), static_cast<long>(start) + 1});
  }
}

std::optional<double> parse_double_general(std::string_view s) {
  s = trim(s);
  // from_chars rejects a leading '+'; accept exactly one before a digit or '.'.
  if (s.size() > 1 && s.front() == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;
  double value = 0.0;
  const char* first = s.data();
  const char* last = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(first, last, value, std::chars_format::general);
  if (ec != std::errc{} || ptr != last) return std::nullopt;
  return value;
}

std::optional<std::int64_t> parse_int(std::string_view s) {
  s = trim(s);
  if (s.size() > 1 && s.front() == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;
  std::int64_t value = 0;
  const char* last = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), last, value);
  if (ec == std::errc{} && ptr == last) return value;
  const auto d = parse_double(s);
  constexpr double kExactLimit = 9007199254740992.0;  // 2^53: beyond it doubles skip integers
  if (!d || !std::isfinite(*d) || std::fabs(*d) > kExactLimit || std::trunc(*d) != *d) return std::nullopt;
  return static_cast<std::int64_t>(*d);
}

char* write_double(char* at, double v) {
  static_assert(kMaxDoubleChars >= kShortestDoubleMaxChars);
  if (std::isnan(v)) {
    std::memcpy(at, "nan", 3);  // never "-nan": every reader we care about spells it this way
    return at + 3;
  }
  return write_shortest(at, v);
}

void append_double(std::string& out, double v) {
  char buf[kMaxDoubleChars];
  out.append(buf, write_double(buf, v));
}

void append_int(std::string& out, std::int64_t v) {
  char buf[32];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof(buf), v);
  (void)ec;
  out.append(buf, ptr);
}

std::string format_double(double v) {
  std::string s;
  append_double(s, v);
  return s;
}

std::string normalise_name(std::string_view s) {
  std::string out;
  bool pending_space = false;
  for (const char c : trim(s)) {
    if (c == ' ' || c == '\t') {
      pending_space = true;
      continue;
    }
    if (pending_space && !out.empty()) out += ' ';
    pending_space = false;
    out += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  }
  return out;
}

std::string quoted_excerpt(std::string_view s) {
  std::string out = "'";
  const size_t n = std::min<size_t>(s.size(), 40);
  for (size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    out += (c < 0x20 || c == 0x7F) ? '?' : static_cast<char>(c);
  }
  if (s.size() > n) out += "...";
  return out + "'";
}

void fail_at(const std::string& source, long line, long column, const std::string& what) {
  throw Error(ErrorLocation{source, line, column}, what);
}

}  // namespace lmc::text
