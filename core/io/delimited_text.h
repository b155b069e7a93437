#pragma once
// Small, strict building blocks for the study's delimited text formats (LMC recordings, TRC).
// Strict means: a field is a number only if ALL of it is a number ("12abc" is rejected, never read
// as 12), and numbers are written in the shortest form that reads back to the same double
// (std::to_chars), so write→read round-trips exactly.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/plain_decimal.h"

namespace lmc::text {

// One line of a file: its text without the line break (a trailing '\r' is removed too), its
// 1-based number, and whether a '\n' ended it (false only for an unterminated last line).
struct Line {
  std::string_view text;
  long number = 0;
  bool has_newline = true;
};

// One field of a line with the 1-based character column where it starts.
struct Field {
  std::string_view text;
  long column = 0;
};

// Whole input as bytes; throws lmc::Error naming `path` when it cannot be opened or read.
std::string read_file_bytes(const std::filesystem::path& path);
std::string read_stream_bytes(std::istream& in);

// A text file whose first line must be a header: the first line is read (at most
// kMaxHeaderLineBytes), checked to be text and handed to `check_header` (which throws naming the
// problem) before the rest is read. So a 2 GB file of garbage, or a 200 MB file of one line, is
// refused at once, and a file that is read costs its own size in memory, once.
inline constexpr size_t kMaxHeaderLineBytes = 64 * 1024;
std::string read_text_file(const std::filesystem::path& path, const std::string& expected,
                           const std::function<void(std::string_view first_line)>& check_header);

// Throws lmc::Error (file, line, column) when `content` holds a NUL byte or is not valid UTF-8:
// such input is a binary or foreign-encoded file, and parsing it would give garbage numbers.
void require_text(std::string_view content, const std::string& source_name);

// `content` without a leading UTF-8 byte-order mark; split_lines drops it the same way.
std::string_view without_bom(std::string_view content);
std::vector<Line> split_lines(std::string_view content);

// A short, printable excerpt of a field for error messages: at most 40 characters, control
// characters shown as '?', in single quotes.
std::string quoted_excerpt(std::string_view s);

// Throws lmc::Error at file:line:column; the one way the text readers report a bad field.
[[noreturn]] void fail_at(const std::string& source, long line, long column, const std::string& what);

// Splits at every `sep` (empty fields kept).
void split_fields(std::string_view line, char sep, std::vector<Field>& out);
// Splits at runs of spaces/tabs (no empty fields).
void split_whitespace(std::string_view line, std::vector<Field>& out);

// Inline: called for every field of every row, where a call cost more than the test.
inline std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}
inline bool is_blank(std::string_view s) {
  return trim(s).empty();
}

// The whole of `s` (surrounding spaces allowed) as a double: decimal or exponent form, "nan",
// "NaN", "inf"; a leading '+' is accepted. nullopt for anything else, incl. out-of-range values.
// Inline: a plain decimal (nearly every field) is read here (plain_decimal.h); the rest goes to
// parse_double_general, which gives the same value for a plain decimal too.
std::optional<double> parse_double_general(std::string_view s);
inline std::optional<double> parse_double(std::string_view s) {
  double value = 0.0;
  if (read_plain_decimal(s.data(), s.data() + s.size(), value) == s.data() + s.size() && !s.empty()) return value;
  return parse_double_general(s);
}
// The whole of `s` as an integer; an integral decimal such as "3.0" is accepted too (some
// writers, e.g. pandas, print integer columns that way) when it is exactly representable.
std::optional<std::int64_t> parse_int(std::string_view s);

// Appends the shortest round-trip form of v ("nan" for any NaN, "inf"/"-inf").
void append_double(std::string& out, double v);
// The same characters written at `at`, which has room for kMaxDoubleChars (all of which it may
// use); returns their end. For rows built in a buffer of their own and appended once.
inline constexpr int kMaxDoubleChars = 32;
char* write_double(char* at, double v);
void append_int(std::string& out, std::int64_t v);
std::string format_double(double v);

// Lower-case with runs of white space collapsed to one space (header comparison).
std::string normalise_name(std::string_view s);

}  // namespace lmc::text
