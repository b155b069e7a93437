#pragma once
// A progress bar with the job's stage name, elapsed time and ETA, and a Cancel button.
#include <optional>
#include <string>

namespace lmc::ui {

class WidgetAnchors;

// Returns true when Cancel was pressed this frame. With `anchors`, the Cancel button is recorded
// as "<id>.cancel" and the elapsed / remaining line as "<id>.elapsed". The row is two lines high.
bool draw_progress_row(const char* id, double fraction, const std::string& stage, double elapsed_s,
                       std::optional<double> eta_s, bool cancellable = true, WidgetAnchors* anchors = nullptr);

// "2 min 05 s", "12.3 s".
std::string format_duration(double seconds);

}  // namespace lmc::ui
