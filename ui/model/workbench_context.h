#pragma once
// What the workbench's tabs share, owned by the shell and handed to every tab it
// builds: the one layout (published by the Layout tab) and the one live rig (the device hub the
// Devices and Record tabs both drive). Declared before the tabs in the shell, so it outlives them.
// UI thread only.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ui/model/current_layout.h"
#include "ui/model/devices/live_rig.h"
#include "ui/model/picture_renderer.h"
#include "ui/model/record/subject_screen_link.h"

namespace lmc::ui {

// `lmc-workbench --session DIR [--backend B] [--fast]`: the Record tab opens (resumes) this
// session at start-up.
struct RecordStartup {
  std::filesystem::path session;
  std::string backend = "sim";
  bool fast = false;
};

class WorkbenchContext {
 public:
  WorkbenchContext() : rig_(layout_) {}
  WorkbenchContext(const WorkbenchContext&) = delete;
  WorkbenchContext& operator=(const WorkbenchContext&) = delete;

  CurrentLayout& layout() { return layout_; }
  const CurrentLayout& layout() const { return layout_; }
  LiveRig& rig() { return rig_; }
  // Set by the shell before the tabs are built; the Record tab takes it once.
  std::optional<RecordStartup>& record_startup() { return record_startup_; }
  // Folders for the Review tab to open: `lmc-workbench --review DIR…` at start-up, the Record tab's
  // "Review this session" later. The Review tab takes them (and clears the list) every frame.
  std::vector<std::filesystem::path>& review_requests() { return review_requests_; }
  // The folders the Review tab has open, as it publishes them each frame (the Record tab asks
  // before a new session reuses a subject id found there).
  std::vector<std::filesystem::path>& review_folders() { return review_folders_; }
  // Trials the Layout tab should design for (Review's "Design a layout for these trials"): their
  // LMC files, read as a recorded pose set (fused hand). The Layout tab takes them every frame.
  std::vector<std::string>& layout_pose_request() { return layout_pose_request_; }
  // A tab the shell should show next ("review"); the shell takes it after the tabs' updates.
  std::string& tab_request() { return tab_request_; }
  // Renders ImGui drawing off screen at width × height into a PNG (ui/platform/offscreen_png.h); set
  // by the program that owns the window, empty without one (model tests). Throws on failure.
  PictureRenderer& picture_renderer() { return picture_renderer_; }
  // The Record tab's subject screen: what it shows and whether it is open (subject_screen_link.h).
  SubjectScreenLink& subject_screen() { return subject_screen_; }

 private:
  CurrentLayout layout_;
  LiveRig rig_;  // after layout_: it reads it until destroyed
  std::optional<RecordStartup> record_startup_;
  std::vector<std::filesystem::path> review_requests_;
  std::vector<std::filesystem::path> review_folders_;
  std::vector<std::string> layout_pose_request_;
  std::string tab_request_;
  SubjectScreenLink subject_screen_;
  PictureRenderer picture_renderer_;
};

}  // namespace lmc::ui
