#pragma once
// The Layout tab: design where the controllers stand, see which fingers each can see,
// and let the optimiser search for a better layout. This class is the composition root: it builds
// the shared LayoutState and one object per panel, arranges them (ImGui 1.86 has no docking:
// child regions with a splitter), and owns the tab-level commands (file dialogs, shortcuts,
// confirmations).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/model/layout/layout_state.h"
#include "ui/scene/scene_renderer.h"
#include "ui/tabs/tab.h"
#include "ui/widgets/file_browser.h"
#include "ui/widgets/split_panels.h"

namespace lmc::ui {

class ScenePanel;
class TimelinePanel;
class InspectorPanel;
class CoveragePanel;
class HeatmapPanel;
class OptimiserPanel;

class CurrentLayout;
class LayoutEditor;
class WorkbenchContext;

std::unique_ptr<Tab> make_layout_tab(StatusSink& status, WorkbenchContext& context);

class LayoutTab final : public Tab {
 public:
  // `renderer` null: a GL renderer is created on first draw when a GL context is current (none in
  // headless tests: the scene then draws a flat background).
  // `shared` (the workbench's one layout; null in tests) receives every committed document, so
  // the live rig streams with what this tab has open.
  LayoutTab(StatusSink& status, std::unique_ptr<SceneRenderer> renderer = nullptr, CurrentLayout* shared = nullptr);
  ~LayoutTab() override;

  void update(bool shown) override;
  void draw() override;
  std::string document_title() const override;
  bool has_unsaved_changes() const override;
  std::string document_kind() const override { return "layout"; }
  void handle_file_command(FileCommand command) override;
  void open_document(const std::filesystem::path& path) override;
  std::optional<std::filesystem::path> document_path() const override;

  // Where Review leaves trials to design for (WorkbenchContext::layout_pose_request); null in tests.
  void take_pose_requests_from(std::vector<std::string>* requests) { pose_requests_ = requests; }

  // The preset the tab opens on.
  static constexpr const char* kStartLayout = "paper-optimized-as-processed";

  LayoutState& state() { return *state_; }
  ScenePanel& scene_panel() { return *scene_; }
  InspectorPanel& inspector_panel() { return *inspector_; }
  OptimiserPanel& optimiser_panel() { return *optimiser_; }
  // Brings a right-hand panel to the front on the next draws: "inspector", "heatmap" or "optimiser".
  void show_panel(const std::string& id) {
    front_panel_ = id;
    front_panel_frames_ = 2;
  }
  // Modal dialogs off (tests): errors go to the status line only.
  void set_modals_enabled(bool on) { modals_enabled_ = on; }

 private:
  enum class Pending { kNone, kNew, kOpen, kOpenPath, kPreset };
  void draw_toolbar();
  void draw_scene_side();  // view buttons, the 3D scene and the timeline
  void draw_panel_side();  // Inspector / Heatmap / Optimiser above Coverage
  void handle_shortcuts();
  void draw_dialogs();
  void request(Pending action, std::string preset = {});
  void run(Pending action);
  void save(bool save_as);
  SceneRenderer* renderer();

  std::string front_panel_;  // show_panel()'s, for its next draws
  int front_panel_frames_ = 0;

  StatusSink& status_;
  CurrentLayout* shared_layout_ = nullptr;
  std::vector<std::string>* pose_requests_ = nullptr;
  std::shared_ptr<LayoutState> state_;
  std::unique_ptr<LayoutEditor> editor_;  // registered in shared_layout_ for the other tabs' edits
  std::unique_ptr<SceneRenderer> renderer_;
  bool renderer_failed_ = false;
  std::unique_ptr<ScenePanel> scene_;
  std::unique_ptr<TimelinePanel> timeline_;
  std::unique_ptr<InspectorPanel> inspector_;
  std::unique_ptr<CoveragePanel> coverage_;
  std::unique_ptr<HeatmapPanel> heatmap_;
  std::unique_ptr<OptimiserPanel> optimiser_;
  FileBrowser browser_{"Layout file"};
  bool browser_saving_ = false;
  SplitPanels split_{470.0f};
  Pending pending_ = Pending::kNone;
  std::string pending_preset_;
  std::filesystem::path pending_path_;
  bool confirm_open_ = false;
  std::string error_message_;
  bool error_open_ = false;
  bool modals_enabled_ = true;
};

}  // namespace lmc::ui
