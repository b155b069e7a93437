#include "ui/model/shell/recent_files.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <exception>
#include <fstream>
#include <sstream>

#include "core/io/atomic_write.h"

namespace lmc::ui {
namespace {

// Two spellings of one file ("a/../b.json", "b.json") are one entry.
std::filesystem::path normalised(const std::filesystem::path& p) {
  std::error_code ec;
  auto abs = std::filesystem::absolute(p, ec);
  return ec ? p.lexically_normal() : abs.lexically_normal();
}

}  // namespace

bool RecentFiles::add(const std::filesystem::path& path, const std::string& kind) {
  const RecentFile entry{normalised(path), kind};
  if (!entries_.empty() && entries_.front() == entry) return false;
  remove(entry.path);
  entries_.insert(entries_.begin(), entry);
  if (entries_.size() > capacity_) entries_.resize(capacity_);
  return true;
}

void RecentFiles::remove(const std::filesystem::path& path) {
  const auto p = normalised(path);
  std::erase_if(entries_, [&](const RecentFile& e) { return e.path == p; });
}

std::string RecentFiles::to_json() const {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& e : entries_) list.push_back({{"path", e.path.string()}, {"kind", e.kind}});
  return nlohmann::json{{"recent_files", list}}.dump(2) + "\n";
}

RecentFiles RecentFiles::from_json(const std::string& text, std::size_t capacity) {
  RecentFiles out(capacity);
  const auto j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object() || !j.contains("recent_files") || !j["recent_files"].is_array()) return out;
  for (const auto& e : j["recent_files"]) {
    if (!e.is_object() || !e.contains("path") || !e["path"].is_string()) continue;
    const std::string kind = e.contains("kind") && e["kind"].is_string() ? e["kind"].get<std::string>() : "";
    const std::filesystem::path p = normalised(e["path"].get<std::string>());
    if (std::none_of(out.entries_.begin(), out.entries_.end(), [&](const RecentFile& r) { return r.path == p; }) &&
        out.entries_.size() < capacity) {
      out.entries_.push_back({p, kind});
    }
  }
  return out;
}

RecentFiles RecentFiles::load(const std::filesystem::path& file, std::size_t capacity) {
  std::ifstream in(file);
  if (!in) return RecentFiles(capacity);
  std::stringstream ss;
  ss << in.rdbuf();
  return from_json(ss.str(), capacity);
}

std::string RecentFiles::save(const std::filesystem::path& file) const {
  try {
    write_file_atomically(file, to_json());
    return {};
  } catch (const std::exception& e) {
    return e.what();
  }
}

}  // namespace lmc::ui
