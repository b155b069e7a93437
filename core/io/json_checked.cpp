#include "core/io/json_checked.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

namespace lmc {

void JsonReader::fail(const std::string& what) const {
  throw Error(ErrorLocation{source_, 0, 0, path_.empty() ? "/" : path_}, what);
}

void JsonReader::require_object() const {
  if (!j_.is_object()) fail("expected an object");
}

void JsonReader::only_keys(std::initializer_list<const char*> allowed) const {
  require_object();
  for (const auto& [key, value] : j_.items()) {
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (known) continue;
    std::string list;
    for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    throw Error(ErrorLocation{source_, 0, 0, path_ + "/" + key}, "unknown field (expected one of: " + list + ")");
  }
}

JsonReader JsonReader::at(const char* key) const {
  require_object();
  const std::string child = path_ + "/" + key;
  if (!j_.contains(key)) {
    throw Error(ErrorLocation{source_, 0, 0, child}, "missing required field");
  }
  return JsonReader(j_.at(key), source_, child);
}

JsonReader JsonReader::at(size_t index) const {
  if (!j_.is_array() || index >= j_.size()) fail("expected an array with an element " + std::to_string(index));
  return JsonReader(j_.at(index), source_, path_ + "/" + std::to_string(index));
}

size_t JsonReader::array_size() const {
  if (!j_.is_array()) fail("expected an array");
  return j_.size();
}

double JsonReader::number() const {
  if (!j_.is_number()) fail("expected a number");
  const double v = j_.get<double>();
  if (!std::isfinite(v)) fail("not a finite number");
  return v;
}

int JsonReader::integer() const {
  if (!j_.is_number_integer()) fail("expected an integer");
  const auto v = j_.get<long long>();
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) fail("integer out of range");
  return static_cast<int>(v);
}

std::string JsonReader::string() const {
  if (!j_.is_string()) fail("expected a string");
  return j_.get<std::string>();
}

bool JsonReader::boolean() const {
  if (!j_.is_boolean()) fail("expected true or false");
  return j_.get<bool>();
}

namespace {

// Where the parser is, kept from its callback events, so that an error raised while reading a
// value (a number that overflows a double, a duplicate key) can name the JSON pointer of it.
class ParsePosition {
 public:
  void object_start() { frames_.push_back(Frame{true, {}, {}, 0}); }
  void array_start() { frames_.push_back(Frame{false, {}, {}, 0}); }
  // Returns false when the object already has this key.
  bool key(const std::string& k) {
    Frame& f = frames_.back();
    f.key = k;
    return f.keys.insert(k).second;
  }
  void value_done() {
    if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().index;
  }
  void container_end() {
    if (!frames_.empty()) frames_.pop_back();
    value_done();
  }
  // RFC 6901 pointer of the value being read ("" for the top level).
  std::string pointer() const {
    std::string out;
    for (const Frame& f : frames_) {
      out += '/';
      if (!f.is_object) {
        out += std::to_string(f.index);
        continue;
      }
      for (const char c : f.key) {
        if (c == '~') {
          out += "~0";
        } else if (c == '/') {
          out += "~1";
        } else {
          out += c;
        }
      }
    }
    return out;
  }

 private:
  struct Frame {
    bool is_object;
    std::string key;             // object: the member being read
    std::set<std::string> keys;  // object: keys seen so far
    size_t index;                // array: the element being read
  };
  std::vector<Frame> frames_;
};

// 1-based line and column of a 1-based byte position (as nlohmann's parse_error::byte gives it).
std::pair<long, long> line_and_column(const std::string& text, std::size_t byte) {
  long line = 1, column = 1;
  const std::size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

// The library's messages start "[json.exception.parse_error.101] parse error at line 1, column 5: ";
// the location is ours to give, so keep only what went wrong.
std::string library_reason(const std::string& what) {
  const std::size_t column = what.find("column ");
  const std::size_t colon = column == std::string::npos ? what.find("] ") : what.find(": ", column);
  if (colon == std::string::npos) return what;
  return what.substr(colon + 2);
}

}  // namespace

nlohmann::json parse_json_text(const std::string& text, const std::string& source) {
  ParsePosition at;
  // The parser itself is iterative, but copying and destroying a value recurse once per level:
  // a few kilobytes of "[[[[…" would overflow the stack later, far from the file. Stop at the
  // depth no file of ours comes near. The same callback tracks where the parser is, and refuses
  // a key repeated in one object: the library would keep the last in silence, so one of two
  // conflicting settings would be ignored without a word.
  const auto guard = [&](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    if (depth > kMaxJsonDepth && (event == E::object_start || event == E::array_start))
      throw Error(ErrorLocation{source}, "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    switch (event) {
      case E::object_start:
        at.object_start();
        break;
      case E::array_start:
        at.array_start();
        break;
      case E::key: {
        const std::string k = parsed.is_string() ? parsed.get<std::string>() : std::string();
        if (!at.key(k))
          throw Error(ErrorLocation{source, 0, 0, at.pointer()}, "duplicate key '" + k + "' in one object");
        break;
      }
      case E::value:
        at.value_done();
        break;
      case E::object_end:
      case E::array_end:
        at.container_end();
        break;
    }
    return true;
  };
  try {
    return nlohmann::json::parse(text, guard);
  } catch (const nlohmann::json::parse_error& e) {
    const auto [line, column] = line_and_column(text, e.byte);
    throw Error(ErrorLocation{source, line, column}, "not valid JSON: " + library_reason(e.what()));
  } catch (const nlohmann::json::out_of_range& e) {
    // Number overflow ("1e400") is reported by the library as out_of_range.406, without a place.
    throw Error(ErrorLocation{source, 0, 0, at.pointer().empty() ? "/" : at.pointer()},
                "a number beyond the range of a double (" + library_reason(e.what()) + ")");
  } catch (const nlohmann::json::exception& e) {
    throw Error(ErrorLocation{source, 0, 0, at.pointer().empty() ? "/" : at.pointer()},
                "not valid JSON: " + library_reason(e.what()));
  }
}

nlohmann::json read_json_file(const std::filesystem::path& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxJsonFileBytes)
    throw Error(ErrorLocation{path.string()}, "file is " + std::to_string(size >> 20) +
                                                  " MB; JSON files of this program are at most " +
                                                  std::to_string(kMaxJsonFileBytes >> 20) + " MB");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorLocation{path.string()}, "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_json_text(ss.str(), path.string());
}

}  // namespace lmc
