#pragma once
// Every colour that means something, in one place: a panel says "an error" or "a warning", never
// which red. Text colours are ImVec4 (ImGui::TextColored, PushStyleColor); colours drawn on a
// panel's draw list are ImU32. A controller slot's colour is device_colour_u32() (imgui_colour.h),
// the same in every tab, legend and plot; a plot's series are the Okabe-Ito palette of
// ui/model/plot/series_palette.h.
#include <imgui.h>

namespace lmc::ui::palette {

// ---- text ----------------------------------------------------------------------------------
inline const ImVec4 kError{1.0F, 0.45F, 0.4F, 1.0F};    // what failed and why
inline const ImVec4 kWarning{1.0F, 0.75F, 0.2F, 1.0F};  // what to look at before going on
inline const ImVec4 kOk{0.35F, 0.85F, 0.4F, 1.0F};      // passed, better, streaming
inline const ImVec4 kFail{1.0F, 0.3F, 0.3F, 1.0F};      // a failed verdict, a controller not streaming
inline const ImVec4 kRecording{1.0F, 0.25F, 0.25F, 1.0F};
inline const ImVec4 kAttention{1.0F, 0.6F, 0.2F, 1.0F};  // interrupted, resumed, the selected controller
inline const ImVec4 kMuted{0.6F, 0.6F, 0.6F, 1.0F};      // pending, unchanged, switched off
inline const ImVec4 kInfo{0.55F, 0.8F, 1.0F, 1.0F};      // headings, names, the status bar's news
inline const ImVec4 kCue{1.0F, 0.9F, 0.5F, 1.0F};        // what the subject is asked to do
inline const ImVec4 kBlack{0.0F, 0.0F, 0.0F, 1.0F};      // text on a light cell
inline const ImVec4 kWhite{1.0F, 1.0F, 1.0F, 1.0F};      // text on a dark cell

// ---- big buttons (the Record tab's) ----------------------------------------------------------
inline const ImVec4 kButtonGo{0.15F, 0.55F, 0.25F, 1.0F};   // Start, Apply
inline const ImVec4 kButtonStop{0.7F, 0.15F, 0.15F, 1.0F};  // Stop
inline const ImVec4 kButtonAction{0.2F, 0.4F, 0.7F, 1.0F};  // Run pre-flight, Record calibration

// ---- drawn on panels -------------------------------------------------------------------------
inline constexpr ImU32 kPanelBackground = IM_COL32(24, 26, 30, 255);  // plots, pictograms, live views
inline constexpr ImU32 kPanelBorder = IM_COL32(80, 84, 92, 255);
inline constexpr ImU32 kSceneBackground = IM_COL32(27, 29, 34, 255);  // the 3D view before GL draws it
inline constexpr ImU32 kPlotTickText = IM_COL32(170, 175, 185, 255);
inline constexpr ImU32 kPlotGridLine = IM_COL32(60, 64, 72, 255);
inline constexpr ImU32 kPlotNote = IM_COL32(120, 125, 135, 255);        // a small plot's corner text
inline constexpr ImU32 kHoverLine = IM_COL32(200, 200, 200, 90);        // where the pointer is on a small plot
inline constexpr ImU32 kLegendBorder = IM_COL32(200, 200, 200, 120);    // around a colour bar
inline constexpr ImU32 kCursorLine = IM_COL32(230, 230, 230, 140);      // the shared cursor of linked plots
inline constexpr ImU32 kGapBand = IM_COL32(120, 120, 140, 28);          // missing samples under a curve
inline constexpr ImU32 kTextShadow = IM_COL32(0, 0, 0, 200);            // labels over the 3D view
inline constexpr ImU32 kOverlayBackground = IM_COL32(18, 19, 23, 200);  // a legend over the 3D view
inline constexpr ImU32 kLabelBackground = IM_COL32(20, 20, 24, 190);    // a label's box over the 3D view
inline constexpr ImU32 kOverlayText = IM_COL32(210, 212, 218, 255);
inline constexpr ImU32 kOverlayTickText = IM_COL32(200, 202, 208, 255);
inline constexpr ImU32 kRecordingCircle = IM_COL32(230, 40, 40, 255);
inline constexpr ImU32 kCountdownCircle = IM_COL32(120, 120, 120, 255);
// A table cell of frames in which no controller sees a finger: redder the more there are.
inline ImU32 unseen_cell(double share) {
  return IM_COL32(200, 50, 45, static_cast<int>(60 + 150 * (share * 3 < 1.0 ? share * 3 : 1.0)));
}
inline constexpr ImU32 kTableBar = IM_COL32(40, 42, 48, 255);  // the empty part of a bar in a table cell
// A frame's label in a strip: the hand seen (bluish green), the tracker's internal model (orange),
// no hand (the strip's background); Okabe-Ito colours, like the plots'.
inline constexpr ImU32 kLabelSeen = IM_COL32(0, 158, 115, 255);
inline constexpr ImU32 kLabelModelled = IM_COL32(230, 159, 0, 255);
inline constexpr ImU32 kLabelNoHand = IM_COL32(52, 55, 62, 255);
// The motion pictogram: where the hand starts (grey) and ends (amber), and the bones' outline.
inline constexpr ImU32 kPoseStart = IM_COL32(150, 150, 160, 110);
inline constexpr ImU32 kPoseEnd = IM_COL32(255, 190, 60, 170);
inline constexpr ImU32 kBoneOutline = IM_COL32(40, 40, 45, 255);
inline constexpr ImU32 kJointOutline = IM_COL32(40, 40, 45, 200);
// The world's axes in the live views: x red, y green, z blue; the floor grid's centre line and rest.
inline constexpr ImU32 kAxisX = IM_COL32(220, 80, 80, 255);
inline constexpr ImU32 kAxisY = IM_COL32(80, 220, 80, 255);
inline constexpr ImU32 kAxisZ = IM_COL32(80, 120, 240, 255);
inline constexpr ImU32 kGridCentre = IM_COL32(90, 90, 100, 255);
inline constexpr ImU32 kGrid = IM_COL32(55, 58, 65, 255);
inline constexpr ImU32 kViewCaption = IM_COL32(200, 200, 210, 255);  // a live view's line at its top

// ---- the subject screen (black, read from across the room) ---------------------------------
inline constexpr ImU32 kSubjectBackground = IM_COL32(0, 0, 0, 255);
inline constexpr ImU32 kSubjectText = IM_COL32(235, 235, 235, 255);
inline constexpr ImU32 kSubjectDim = IM_COL32(130, 130, 135, 255);
inline constexpr ImU32 kSubjectCircle = IM_COL32(230, 30, 30, 255);
inline constexpr ImU32 kSubjectRecordingText = IM_COL32(255, 80, 70, 255);
inline constexpr ImU32 kSubjectCue = IM_COL32(255, 230, 130, 255);

}  // namespace lmc::ui::palette
