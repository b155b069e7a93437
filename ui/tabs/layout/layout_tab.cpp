#include "ui/tabs/layout/layout_tab.h"

#include <GLFW/glfw3.h>
#include <epoxy/gl.h>
#include <imgui.h>

#include <algorithm>
#include <filesystem>

#include "core/common/paths.h"
#include "core/io/layout_json.h"
#include "ui/model/layout_editor.h"
#include "ui/model/workbench_context.h"
#include "ui/scene/gl_scene_renderer.h"
#include "ui/tabs/layout/coverage_panel.h"
#include "ui/tabs/layout/heatmap_panel.h"
#include "ui/tabs/layout/inspector_panel.h"
#include "ui/tabs/layout/optimiser_panel.h"
#include "ui/tabs/layout/scene_panel.h"
#include "ui/tabs/layout/timeline_panel.h"
#include "ui/widgets/flow_row.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {
namespace {

LayoutDocument initial_document() {
  // Open on the paper's optimized layout as the authors processed it: the first thing a lab sees is
  // a real design in which every controller sees the hand (the table's own numbers point LMC1 away
  // from it, and the Devices tab would stream a controller that never sees anything).
  try {
    return make_document(load_layout_or_preset(LayoutTab::kStartLayout));
  } catch (const std::exception&) {
    return make_document(default_new_layout());
  }
}

// Other tabs' edits (the Devices tab's Calibrate step) go through this tab's state, so selection
// and the status line follow an applied or undone calibration as they follow this tab's own edits.
class StateLayoutEditor final : public LayoutEditor {
 public:
  explicit StateLayoutEditor(LayoutState& state) : state_(state) {}
  const Layout& committed() const override { return state_.history().head().layout; }
  ActionResult apply_calibration(const Layout& calibrated) override {
    ActionResult r = ui::apply_calibration(state_.upd_history(), calibrated);
    state_.report(r, "Apply calibration");
    return r;
  }
  bool can_undo() const override { return state_.history().can_undo(); }
  std::string undo_message() const override { return state_.history().undo_message(); }
  void undo() override { state_.undo(); }

 private:
  LayoutState& state_;
};

// GLFW key codes (the 1.86 GLFW backend indexes KeysDown by them); letters are their ASCII codes.
constexpr int kKeyDelete = 261;

}  // namespace

std::unique_ptr<Tab> make_layout_tab(StatusSink& status, WorkbenchContext& context) {
  auto tab = std::make_unique<LayoutTab>(status, nullptr, &context.layout());
  tab->take_pose_requests_from(&context.layout_pose_request());
  return tab;
}

LayoutTab::LayoutTab(StatusSink& status, std::unique_ptr<SceneRenderer> renderer, CurrentLayout* shared)
    : status_(status),
      shared_layout_(shared),
      state_(std::make_shared<LayoutState>(initial_document(),
                                           [this](const std::string& t, bool e) { status_.set_status(t, e); })),
      renderer_(std::move(renderer)) {
  scene_ = std::make_unique<ScenePanel>(state_, [this] { return this->renderer(); });
  timeline_ = std::make_unique<TimelinePanel>(state_);
  inspector_ = std::make_unique<InspectorPanel>(state_);
  coverage_ = std::make_unique<CoveragePanel>(state_);
  heatmap_ = std::make_unique<HeatmapPanel>(state_);
  optimiser_ = std::make_unique<OptimiserPanel>(state_);
  state_->select(0);
  if (shared_layout_ != nullptr) {
    shared_layout_->publish(state_->history().head().layout);
    editor_ = std::make_unique<StateLayoutEditor>(*state_);
    shared_layout_->set_editor(editor_.get());
  }
}

LayoutTab::~LayoutTab() {
  if (shared_layout_ != nullptr && shared_layout_->editor() == editor_.get()) shared_layout_->set_editor(nullptr);
}

SceneRenderer* LayoutTab::renderer() {
  if (!renderer_ && !renderer_failed_) {
    if (glfwGetCurrentContext() == nullptr) {
      renderer_failed_ = true;  // headless: no GL
      return nullptr;
    }
    try {
      renderer_ = std::make_unique<GlSceneRenderer>();
    } catch (const std::exception& e) {
      renderer_failed_ = true;
      status_.set_status(std::string("3D view unavailable: ") + e.what(), true);
    }
  }
  return renderer_.get();
}

void LayoutTab::update(bool shown) {
  if (pose_requests_ != nullptr && !pose_requests_->empty()) {
    state_->use_recorded_pose_set(std::move(*pose_requests_));
    pose_requests_->clear();
    optimiser_->show_pose_set_once();
  }
  state_->update(static_cast<double>(ImGui::GetIO().DeltaTime), shown);
  // The committed layout, not the scratch copy: a drag in progress would restart the rig every frame.
  if (shared_layout_ != nullptr) shared_layout_->publish(state_->history().head().layout);
}

std::string LayoutTab::document_title() const {
  return state_->title();
}
bool LayoutTab::has_unsaved_changes() const {
  return state_->unsaved();
}
std::optional<std::filesystem::path> LayoutTab::document_path() const {
  return state_->file_path();
}

// The File menu runs exactly what the toolbar and the shortcuts run.
void LayoutTab::handle_file_command(FileCommand command) {
  switch (command) {
    case FileCommand::kNew:
      request(Pending::kNew);
      break;
    case FileCommand::kOpen:
      request(Pending::kOpen);
      break;
    case FileCommand::kSave:
      save(false);
      break;
    case FileCommand::kSaveAs:
      save(true);
      break;
  }
}

void LayoutTab::open_document(const std::filesystem::path& path) {
  pending_path_ = path;
  request(Pending::kOpenPath);
}

void LayoutTab::request(Pending action, std::string preset) {
  pending_preset_ = std::move(preset);
  if (state_->unsaved() && modals_enabled_) {
    pending_ = action;
    confirm_open_ = true;
  } else {
    run(action);
  }
}

void LayoutTab::run(Pending action) {
  switch (action) {
    case Pending::kNew:
      state_->new_layout();
      state_->set_status("New layout");
      break;
    case Pending::kOpen: {
      const auto dir = state_->file_path() ? state_->file_path()->parent_path() : std::filesystem::current_path();
      browser_saving_ = false;
      browser_.open(FileBrowser::Mode::kOpen, dir);
      break;
    }
    case Pending::kOpenPath:
      if (std::string err = state_->open_file(pending_path_); !err.empty()) {
        error_message_ = err;
        error_open_ = modals_enabled_;
      }
      break;
    case Pending::kPreset:
      if (std::string err = state_->load_preset(pending_preset_); !err.empty()) {
        error_message_ = err;
        error_open_ = modals_enabled_;
      }
      break;
    case Pending::kNone:
      break;
  }
  pending_ = Pending::kNone;
}

void LayoutTab::save(bool save_as) {
  if (!save_as && state_->file_path()) {
    if (std::string err = state_->save_to(*state_->file_path()); !err.empty()) {
      error_message_ = err;
      error_open_ = modals_enabled_;
    }
    return;
  }
  browser_saving_ = true;
  const auto dir = state_->file_path() ? state_->file_path()->parent_path() : std::filesystem::current_path();
  const std::string name = state_->file_path()
                               ? state_->file_path()->filename().string()
                               : (state_->layout().name.empty() ? "layout" : state_->layout().name) + ".json";
  browser_.open(FileBrowser::Mode::kSave, dir, name);
}

void LayoutTab::handle_shortcuts() {
  ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return;
  if (io.KeyCtrl) {
    if (ImGui::IsKeyPressed('Z', true)) io.KeyShift ? state_->redo() : state_->undo();
    if (ImGui::IsKeyPressed('Y', true)) state_->redo();
    if (ImGui::IsKeyPressed('S', false)) save(io.KeyShift);
    if (ImGui::IsKeyPressed('O', false)) request(Pending::kOpen);
    if (ImGui::IsKeyPressed('N', false)) request(Pending::kNew);
    return;
  }
  if (ImGui::IsKeyPressed('F', false)) scene_->frame_all();
  if (ImGui::IsKeyPressed(kKeyDelete, false) && state_->selected() >= 0) {
    state_->report(remove_device(state_->upd_history(), state_->selected()), "Remove controller");
  }
}

void LayoutTab::draw_toolbar() {
  LayoutState& s = *state_;
  if (ImGui::Button("New")) request(Pending::kNew);
  ImGui::SameLine();
  if (ImGui::Button("Open...")) request(Pending::kOpen);
  ImGui::SameLine();
  if (ImGui::Button("Save")) save(false);
  ImGui::SameLine();
  if (ImGui::Button("Save as...")) save(true);
  ImGui::SameLine();
  if (ImGui::Button("Presets v")) ImGui::OpenPopup("##presets");
  if (ImGui::BeginPopup("##presets")) {
    if (ImGui::MenuItem("Paper: initial layout (2 × 2 square, ±60 mm)")) request(Pending::kPreset, "paper-initial");
    if (ImGui::MenuItem("Paper: optimized layout (PSO result, as the authors processed it)")) {
      request(Pending::kPreset, "paper-optimized-as-processed");
    }
    if (ImGui::MenuItem("Paper: optimized layout as printed (LMC1 looks away from the hand)")) {
      request(Pending::kPreset, "paper-optimized");
    }
    ImGui::EndPopup();
  }
  ImGui::SameLine(0, 20);
  ImGui::BeginDisabled(!s.history().can_undo());
  const std::string undo_label = s.history().can_undo() ? "Undo " + s.history().undo_message() : std::string("Undo");
  if (ImGui::Button((undo_label + "###undo").c_str())) s.undo();
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("Ctrl+Z");
  ImGui::SameLine();
  ImGui::BeginDisabled(!s.history().can_redo());
  const std::string redo_label = s.history().can_redo() ? "Redo " + s.history().redo_message() : std::string("Redo");
  if (ImGui::Button((redo_label + "###redo").c_str())) s.redo();
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("Ctrl+Shift+Z or Ctrl+Y");
  ImGui::SameLine(0, 20);
  ImGui::TextDisabled("%s", s.title().c_str());
  // The layout's own description (a preset's says what it is and what is wrong with it).
  if (!s.layout().description.empty() && ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
    ImGui::TextUnformatted(s.layout().description.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

void LayoutTab::draw_dialogs() {
  if (auto chosen = browser_.draw()) {
    const std::string err = browser_saving_ ? state_->save_to(*chosen) : state_->open_file(*chosen);
    if (!err.empty()) {
      error_message_ = err;
      error_open_ = modals_enabled_;
    }
  }
  if (confirm_open_) {
    ImGui::OpenPopup("Discard unsaved changes?");
    confirm_open_ = false;
  }
  if (ImGui::BeginPopupModal("Discard unsaved changes?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextUnformatted("The layout has changes that are not saved. Continue and lose them?");
    if (ImGui::Button("Discard changes")) {
      ImGui::CloseCurrentPopup();
      run(pending_);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      pending_ = Pending::kNone;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
  if (error_open_) {
    ImGui::OpenPopup("Layout file problem");
    error_open_ = false;
  }
  if (ImGui::BeginPopupModal("Layout file problem", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushTextWrapPos(560.0f);
    ImGui::TextColored(palette::kError, "%s", error_message_.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::Button("OK", ImVec2(100, 0))) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
}

void LayoutTab::draw_scene_side() {
  LayoutState& s = *state_;
  // View row above the scene.
  if (ImGui::SmallButton("3D")) s.camera.set_named_view(NamedView::kPerspective);
  ImGui::SameLine();
  if (ImGui::SmallButton("Top")) s.camera.set_named_view(NamedView::kTop);
  ImGui::SameLine();
  if (ImGui::SmallButton("Front")) s.camera.set_named_view(NamedView::kFront);
  ImGui::SameLine();
  if (ImGui::SmallButton("Side")) s.camera.set_named_view(NamedView::kSide);
  ImGui::SameLine();
  if (ImGui::SmallButton("Frame all (F)")) scene_->frame_all();
  same_line_or_wrap(checkbox_width("Pyramids"), 16);
  ImGui::Checkbox("Pyramids", &s.display.show_pyramids);
  same_line_or_wrap(checkbox_width("Rays"));
  ImGui::Checkbox("Rays", &s.display.show_rays);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Lines from the selected controller to every finger marker:\ngreen clear, red blocked (hover one for the "
        "reason)");
  same_line_or_wrap(checkbox_width("Heatmap"));
  ImGui::Checkbox("Heatmap", &s.display.show_heatmap);
  same_line_or_wrap(checkbox_width("Ghost"));
  ImGui::Checkbox("Ghost", &s.display.show_ghost);
  const float timeline_h = timeline_->height(ImGui::GetContentRegionAvail().x) + 6.0f;
  const ImVec2 scene_size(ImGui::GetContentRegionAvail().x, ImGui::GetContentRegionAvail().y - timeline_h);
  scene_->draw(scene_size);
  ImGui::Spacing();
  timeline_->draw();
}

void LayoutTab::draw_panel_side() {
  const float avail_y = ImGui::GetContentRegionAvail().y;
  const float coverage_h = std::min(300.0f, avail_y * 0.45f);
  ImGui::BeginChild("##right_tabs", ImVec2(0, avail_y - coverage_h - 4), true);
  if (ImGui::BeginTabBar("##layout_panels")) {
    const auto flags_for = [this](const char* id) {
      if (front_panel_frames_ > 0 && front_panel_ == id) return ImGuiTabItemFlags_SetSelected;
      return ImGuiTabItemFlags_None;
    };
    // Each panel scrolls inside its own child so the tab strip above it stays in view.
    if (ImGui::BeginTabItem("Inspector", nullptr, flags_for("inspector"))) {
      if (const auto window = inspector_->window()) inspector_->draw();
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Heatmap", nullptr, flags_for("heatmap"))) {
      if (const auto window = heatmap_->window()) heatmap_->draw();
      ImGui::EndTabItem();
    }
    bool optimiser_open = false;
    if (ImGui::BeginTabItem("Optimiser", nullptr, flags_for("optimiser"))) {
      optimiser_open = true;
      optimiser_->draw();
      ImGui::EndTabItem();
    }
    // While the Optimiser panel is open the scene shows where the search may put controllers.
    state_->display.show_search_box = optimiser_open;
    ImGui::EndTabBar();
    if (front_panel_frames_ > 0) --front_panel_frames_;
  }
  ImGui::EndChild();
  if (const auto window = coverage_->window(ImVec2(0, 0), true)) coverage_->draw();
}

void LayoutTab::draw() {
  handle_shortcuts();
  draw_toolbar();
  split_.draw([this] { draw_scene_side(); }, [this] { draw_panel_side(); });
  draw_dialogs();
}

}  // namespace lmc::ui
