#include "ui/model/file_browser_model.h"

#include <algorithm>
#include <cstdint>

namespace lmc::ui {

FileBrowserModel::FileBrowserModel(std::filesystem::path start, std::string extension)
    : directory_(std::move(start)), extension_(std::move(extension)) {
  refresh();
}

void FileBrowserModel::refresh() {
  entries_.clear();
  error_.clear();
  std::error_code ec;
  std::filesystem::directory_iterator it(directory_, ec);
  if (ec) {
    error_ = "cannot list " + directory_.string() + ": " + ec.message();
    return;
  }
  for (const auto& e : it) {
    BrowserEntry b;
    b.name = e.path().filename().string();
    if (b.name.empty() || b.name[0] == '.') continue;  // hidden files
    std::error_code ec2;
    b.is_directory = e.is_directory(ec2);
    if (!b.is_directory) {
      if (!extension_.empty() && e.path().extension() != extension_) continue;
      b.size_bytes = e.file_size(ec2);
    }
    entries_.push_back(std::move(b));
  }
  std::sort(entries_.begin(), entries_.end(), [](const BrowserEntry& a, const BrowserEntry& b) {
    if (a.is_directory != b.is_directory) return a.is_directory;
    return a.name < b.name;
  });
}

void FileBrowserModel::enter(const std::string& name) {
  if (name == "..") {
    if (directory_.has_parent_path() && directory_ != directory_.root_path()) directory_ = directory_.parent_path();
  } else {
    directory_ /= name;
  }
  refresh();
}

void FileBrowserModel::go_to(const std::filesystem::path& dir) {
  directory_ = dir;
  refresh();
}

}  // namespace lmc::ui
