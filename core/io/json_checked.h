#pragma once
// Typed access to JSON values that reports the JSON path of anything missing or mistyped, so
// every loader names the file and the exact field a user must fix.
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>

#include "core/common/error.h"

namespace lmc {

class JsonReader {
 public:
  JsonReader(const nlohmann::json& j, std::string source, std::string path = "")
      : j_(j), source_(std::move(source)), path_(std::move(path)) {}

  const nlohmann::json& json() const { return j_; }
  const std::string& path() const { return path_; }
  bool has(const char* key) const { return j_.is_object() && j_.contains(key) && !j_.at(key).is_null(); }

  JsonReader at(const char* key) const;
  JsonReader at(size_t index) const;
  size_t array_size() const;  // throws unless an array

  double number() const;  // finite numbers only
  int integer() const;
  std::string string() const;
  bool boolean() const;

  double number(const char* key) const { return at(key).number(); }
  double number_or(const char* key, double fallback) const { return has(key) ? number(key) : fallback; }
  std::string string(const char* key) const { return at(key).string(); }
  std::string string_or(const char* key, std::string fallback) const { return has(key) ? string(key) : fallback; }

  [[noreturn]] void fail(const std::string& what) const;
  void require_object() const;
  // Rejects keys outside `allowed`, naming the first one: a misspelt key ("rnage_mm") must not be
  // dropped in silence while its default takes effect.
  void only_keys(std::initializer_list<const char*> allowed) const;

 private:
  const nlohmann::json& j_;
  std::string source_;
  std::string path_;
};

// Limits of every JSON file this program reads (layouts, sidecars, protocols, manifests are
// kilobytes; journals are read line by line).
inline constexpr int kMaxJsonDepth = 256;
inline constexpr std::uintmax_t kMaxJsonFileBytes = 64u << 20;

// Parses text as JSON; a syntax error is reported with the file, line and column, nesting deeper
// than kMaxJsonDepth is refused, and a number beyond a double (1e400) or a key repeated in one
// object is an lmc::Error naming the file and the JSON pointer (never the library's own text).
nlohmann::json parse_json_text(const std::string& text, const std::string& source);
nlohmann::json read_json_file(const std::filesystem::path& path);

}  // namespace lmc
