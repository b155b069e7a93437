#pragma once
// Review → Export…: the selected trial or the trials the table shows as C3D or TRC, or the opened
// sessions as a BIDS-motion dataset, written in the background (ReviewState's motion export) with
// progress and Cancel. A finished export names its folder, lists its notes and offers to open the
// folder in the desktop's file manager.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "ui/model/review/review_state.h"
#include "ui/widgets/file_browser.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class ReviewExportPanel : public Panel {
 public:
  // Shows a folder to the person (tests pass a recorder instead of the file manager).
  using FolderOpener = std::function<bool(const std::filesystem::path& folder, std::string* error)>;
  explicit ReviewExportPanel(std::shared_ptr<ReviewState> state, FolderOpener opener = {});

  // The Export... button of the sources bar; while an export runs it says how far it is.
  void draw_button();
  // The Export window when open (drawn after the rest of the tab so it stays on top).
  void draw_window();

  enum class What { kSelected, kShown, kBids };
  // What the button and the window's controls do, for tests and captures.
  void open();
  bool is_open() const { return open_; }
  void choose(What what);
  void set_folder(const std::filesystem::path& folder);
  std::filesystem::path folder() const { return folder_; }  // where Export writes, as the field shows it
  void start();                                             // the Export button
  // Export, progress.cancel, result, open_folder, error and the choices, as last drawn.
  const WidgetAnchors& anchors() const { return anchors_; }

 private:
  void draw_what(const ReviewState& state);
  void draw_options(const ReviewState& state);
  void draw_folder();
  void draw_run(ReviewState& state);
  void draw_outcome(const ReviewState& state);
  void suggest_paths();  // the default folder (and key) for what is chosen, until one is typed

  std::shared_ptr<ReviewState> state_;
  FolderOpener opener_;
  bool open_ = false;
  What what_ = What::kShown;
  int format_ = 0;  // 0 C3D, 1 TRC
  int axes_ = 0;    // 0 world, 1 OpenSim
  bool anonymise_ = false;
  bool replace_ = false;
  bool folder_typed_ = false, key_typed_ = false;  // chosen by the person: no longer suggested
  char folder_[1024] = {};
  std::string other_kind_folder_;  // the folder of the other kind (BIDS or per-trial) while this one is chosen
  bool other_kind_folder_typed_ = false;
  char key_[1024] = {};
  bool started_ = false;  // an export was started from this window (its outcome is shown)
  std::string open_error_;
  FileBrowser folder_browser_{"Export into a new folder", ""};
  FileBrowser key_browser_{"Where to write the subject key", ".tsv"};
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
