#pragma once
// Folders a capture script records demo sessions into while `--capture` takes its pictures. They
// are scratch (the pictures are the output), so they go with the script and never stay behind in
// /tmp. The capture destroys its scripts after the shell, so a folder is removed only once the
// tab writing into it has stopped.
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "core/platform/process.h"

namespace lmc::ui {

class CaptureScratch {
 public:
  CaptureScratch() = default;
  CaptureScratch(const CaptureScratch&) = delete;
  CaptureScratch& operator=(const CaptureScratch&) = delete;
  ~CaptureScratch() {
    for (const auto& dir : dirs_) {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  }

  // A path that does not exist yet, unique to this process and `what`; removed with this object.
  std::filesystem::path fresh(const std::string& what) {
    auto dir = std::filesystem::temp_directory_path() /
               ("lmc-capture-" + what + "-" + std::to_string(platform::current_process_id()));
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
    dirs_.push_back(dir);
    return dir;
  }

 private:
  std::vector<std::filesystem::path> dirs_;
};

}  // namespace lmc::ui
