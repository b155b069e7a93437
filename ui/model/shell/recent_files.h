#pragma once
// The File menu's recent documents: newest first, no duplicates, at most `capacity`. Each entry
// names the kind of document ("layout") so the shell can hand it back to the tab that opens that
// kind without knowing anything about it. Persisted as a small JSON file in the user's config
// folder (beside imgui.ini); a missing or damaged file is an empty list, never an error at start.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace lmc::ui {

struct RecentFile {
  std::filesystem::path path;
  std::string kind;
  bool operator==(const RecentFile&) const = default;
};

class RecentFiles {
 public:
  explicit RecentFiles(std::size_t capacity = 8) : capacity_(capacity) {}

  // Moves `path` to the front (adding it when new); true when the list changed.
  bool add(const std::filesystem::path& path, const std::string& kind);
  void remove(const std::filesystem::path& path);
  const std::vector<RecentFile>& entries() const { return entries_; }

  std::string to_json() const;
  // Unknown fields are ignored and malformed entries skipped: the list is a convenience.
  static RecentFiles from_json(const std::string& text, std::size_t capacity = 8);

  // Reads `file` (empty list when it is missing or unreadable).
  static RecentFiles load(const std::filesystem::path& file, std::size_t capacity = 8);
  // Writes atomically (a crash never leaves half a list); returns an error message or "".
  std::string save(const std::filesystem::path& file) const;

 private:
  std::size_t capacity_;
  std::vector<RecentFile> entries_;
};

}  // namespace lmc::ui
