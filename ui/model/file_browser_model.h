#pragma once
// What a simple file browser shows: the folders and matching files of one directory, sorted,
// folders first. Pure (std::filesystem only) so the widget stays a thin drawing layer.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lmc::ui {

struct BrowserEntry {
  std::string name;
  bool is_directory = false;
  std::uintmax_t size_bytes = 0;
};

class FileBrowserModel {
 public:
  // `extension` filters files (".json"); empty shows all files.
  explicit FileBrowserModel(std::filesystem::path start = std::filesystem::current_path(),
                            std::string extension = ".json");

  const std::filesystem::path& directory() const { return directory_; }
  const std::vector<BrowserEntry>& entries() const { return entries_; }
  const std::string& error() const { return error_; }

  // Re-reads the directory (errors are kept, not thrown: e.g. permission denied).
  void refresh();
  void enter(const std::string& name);  // a sub-folder, or ".." for the parent
  void go_to(const std::filesystem::path& dir);
  std::filesystem::path path_of(const std::string& file_name) const { return directory_ / file_name; }

 private:
  std::filesystem::path directory_;
  std::string extension_;
  std::vector<BrowserEntry> entries_;
  std::string error_;
};

}  // namespace lmc::ui
