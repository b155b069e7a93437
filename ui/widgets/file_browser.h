#pragma once
// A simple modal file browser for layout files (no native dialog in ImGui): folder listing with
// "..", a file-name field, OK / Cancel. Open it with open(), draw it every frame with draw();
// draw() returns the chosen path once.
#include <filesystem>
#include <optional>
#include <string>

#include "ui/model/file_browser_model.h"

namespace lmc::ui {

class FileBrowser {
 public:
  enum class Mode { kOpen, kSave };
  explicit FileBrowser(std::string title = "Choose file", std::string extension = ".json");

  void open(Mode mode, const std::filesystem::path& start_dir, const std::string& file_name = {});
  bool is_open() const { return open_; }
  // Draws the popup when open; returns the chosen path on the frame the user confirms.
  std::optional<std::filesystem::path> draw();

 private:
  std::string title_;
  std::string extension_;
  FileBrowserModel model_;
  Mode mode_ = Mode::kOpen;
  bool open_ = false;
  bool request_popup_ = false;
  char name_[256] = {};
};

}  // namespace lmc::ui
