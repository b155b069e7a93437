#include "core/io/json_checked.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

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

nlohmann::json parse_json_text(const std::string& text, const std::string& source) {
  // The parser itself is iterative, but copying and destroying a value recurse once per level:
  // a few kilobytes of "[[[[…" would overflow the stack later, far from the file. Stop at the
  // depth no file of ours comes near.
  const auto depth_guard = [&](int depth, nlohmann::json::parse_event_t event, nlohmann::json&) {
    if (depth > kMaxJsonDepth &&
        (event == nlohmann::json::parse_event_t::object_start || event == nlohmann::json::parse_event_t::array_start))
      throw Error(ErrorLocation{source}, "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return true;
  };
  try {
    return nlohmann::json::parse(text, depth_guard);
  } catch (const nlohmann::json::parse_error& e) {
    throw Error(ErrorLocation{source}, std::string("not valid JSON: ") + e.what());
  }
}

nlohmann::json read_json_file(const std::filesystem::path& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxJsonFileBytes)
    throw Error(ErrorLocation{path.string()}, "file is " + std::to_string(size >> 20) + " MB; JSON files of this program are at most " +
                                                  std::to_string(kMaxJsonFileBytes >> 20) + " MB");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorLocation{path.string()}, "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_json_text(ss.str(), path.string());
}

}  // namespace lmc
