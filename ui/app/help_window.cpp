#include "ui/app/help_window.h"

#include <imgui.h>

namespace lmc::ui {
namespace {

// The README's "Design a layout" walkthrough, condensed to what fits a window.
constexpr const char* kWalkthrough[] = {
    "The Layout tab opens on the paper's optimized layout as the authors processed it and a 2,000-frame "
    "Monte Carlo pose set. Presets switches to the paper's initial square or to the optimized layout as "
    "printed (its LMC1 looks away from the hand); New starts from four controllers at ±60 mm.",
    "Look around: left-drag on empty space orbits, right- or middle-drag pans, the wheel zooms. "
    "F frames everything; 3D / Top / Front / Side give fixed views.",
    "Click a controller to select it. Drag its box to move it, the green ring to turn it, the red "
    "ring to tilt it; Esc puts it back. The Inspector holds every parameter with a lock the handles "
    "and the optimiser honour (drag a pose value, or click it to type one).",
    "Scrub or Play the timeline. Fingers are coloured by how many controllers see them: red none, "
    "orange 1, yellow 2, green 3+. Tick Rays and hover a red line to read what blocks it.",
    "The Coverage panel shows controllers x fingers, frames seen by nobody and the metric M "
    "(lower is better); it follows your drag live.",
    "With a controller selected, the table heatmap shows where it would see the chosen finger best.",
    "In Optimiser, pick the pose set and which controllers may move, then Start. Cyan ghosts show "
    "the best layout so far; Cancel never touches yours; Apply is one undo step.",
    "File > Save (Ctrl+S) writes layout JSON, File > Open (Ctrl+O) reads it. The title shows * "
    "while changes are unsaved.",
    "No controllers attached? The Devices and Record tabs run a simulated rig: open Record to run a "
    "quick session from the keyboard.",
};

void draw_walkthrough() {
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextUnformatted("Design a layout");
  ImGui::Separator();
  int step = 1;
  for (const char* text : kWalkthrough) {
    ImGui::Text("%d.", step++);
    ImGui::SameLine();
    ImGui::TextUnformatted(text);
  }
  ImGui::PopTextWrapPos();
}

void draw_shortcuts() {
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("##shortcuts", 3, flags)) return;
  ImGui::TableSetupColumn("Where");
  ImGui::TableSetupColumn("Keys");
  ImGui::TableSetupColumn("Does", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableHeadersRow();
  for (const auto& row : shortcut_rows()) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextDisabled("%s", row.where.c_str());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(row.keys.c_str());
    ImGui::TableNextColumn();
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(row.does.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::EndTable();
  ImGui::Spacing();
  ImGui::TextDisabled("Shortcuts act in the tab that is showing, and not while you type in a field.");
}

void draw_about() {
  ImGui::Text("LMC Workbench %s", LMC_VERSION);
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextUnformatted(
      "Design, record and analyse hand measurements with several Ultraleap Leap Motion "
      "Controllers. The same engine runs headless as the `lmc` command (`lmc --help`).");
  ImGui::PopTextWrapPos();
}

}  // namespace

const std::vector<ShortcutRow>& shortcut_rows() {
  static const std::vector<ShortcutRow> rows = {
      {"Everywhere", "F1", "Open this help"},
      {"Everywhere", "Ctrl+Q", "Quit (asks first when work is unsaved)"},
      {"Layout", "Ctrl+N", "New layout"},
      {"Layout", "Ctrl+O", "Open a layout file"},
      {"Layout", "Ctrl+S", "Save (asks for a name the first time)"},
      {"Layout", "Ctrl+Shift+S", "Save as"},
      {"Layout", "Ctrl+Z", "Undo"},
      {"Layout", "Ctrl+Shift+Z, Ctrl+Y", "Redo"},
      {"Layout", "F", "Frame everything in the 3D view"},
      {"Layout", "Esc", "During a drag: put the controller back"},
      {"Layout", "Delete", "Remove the selected controller"},
      {"Layout", "Click a pose field", "Type a value (sensor fields: double-click); drag to change it live"},
      {"Devices", "Ctrl+Z", "Undo an applied calibration"},
      {"Record", "Space", "Start the trial (pre-flight first when needed); stop it while recording"},
      {"Record", "Enter", "Accept a trial whose verdict is fail"},
      {"Record", "R", "Redo the last trial"},
      {"Record", "F2", "Open or close the subject screen (cue, countdown, red circle, pictogram)"},
  };
  return rows;
}

void HelpWindow::draw() {
  if (!open_) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowSize(ImVec2(640, 520), ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.5f),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (select_pending_) ImGui::SetNextWindowFocus();
  ImGui::SetNextWindowBgAlpha(1.0f);  // text to read: the tab underneath must not show through
  if (ImGui::Begin("Help###lmc_help", &open_, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
    if (ImGui::BeginTabBar("##help_sections")) {
      const auto flags_for = [this](Section s) {
        return select_pending_ && select_ == s ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
      };
      if (ImGui::BeginTabItem("Getting started", nullptr, flags_for(Section::kWalkthrough))) {
        draw_walkthrough();
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Shortcuts", nullptr, flags_for(Section::kShortcuts))) {
        draw_shortcuts();
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("About", nullptr, flags_for(Section::kAbout))) {
        draw_about();
        ImGui::EndTabItem();
      }
      ImGui::EndTabBar();
    }
    select_pending_ = false;
  }
  ImGui::End();
}

}  // namespace lmc::ui
