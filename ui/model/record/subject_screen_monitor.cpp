#include "ui/model/record/subject_screen_monitor.h"

#include <sstream>

namespace lmc::ui {

std::string monitor_label(const Monitor& m) {
  return (m.name.empty() ? std::string("monitor") : m.name) + " (" + std::to_string(m.rect.width) + "x" +
         std::to_string(m.rect.height) + (m.primary ? ", primary)" : ")");
}

std::string monitor_short_label(int index, const Monitor& m) {
  return std::to_string(index + 1) + ": " + std::to_string(m.rect.width) + "x" + std::to_string(m.rect.height) +
         (m.primary ? ", primary" : "");
}

int find_monitor(const std::vector<Monitor>& monitors, const Monitor& saved) {
  int same_name = -1, named = 0;
  for (size_t i = 0; i < monitors.size(); ++i) {
    if (monitors[i].name != saved.name) continue;
    if (monitors[i].rect == saved.rect) return static_cast<int>(i);
    same_name = static_cast<int>(i);
    ++named;
  }
  return named == 1 ? same_name : -1;
}

int choose_subject_monitor(const std::vector<Monitor>& monitors, int chosen, const std::optional<Monitor>& saved) {
  const int n = static_cast<int>(monitors.size());
  if (chosen >= 0 && chosen < n) return chosen;
  if (saved) {
    if (const int i = find_monitor(monitors, *saved); i >= 0) return i;
  }
  for (int i = 0; i < n; ++i)
    if (!monitors[static_cast<size_t>(i)].primary) return i;
  return n > 0 ? 0 : -1;
}

SubjectScreenPlace place_subject_screen(const std::vector<Monitor>& monitors, int monitor, bool windowed,
                                        const ScreenRect& operator_window,
                                        const std::optional<ScreenRect>& remembered) {
  SubjectScreenPlace place;
  place.monitor = monitor >= 0 && monitor < static_cast<int>(monitors.size()) ? monitor : -1;
  if (place.monitor >= 0 && !windowed) {
    place.covers_monitor = true;
    place.rect = monitors[static_cast<size_t>(place.monitor)].rect;
    return place;
  }
  std::vector<ScreenRect> rects;
  for (const auto& m : monitors) rects.push_back(m.rect);
  place.rect = subject_window_rect(rects, place.monitor, operator_window, remembered);
  return place;
}

bool subject_monitor_gone(const std::vector<Monitor>& monitors, const Monitor& on) {
  for (const auto& m : monitors)
    if (m.name == on.name && m.rect == on.rect) return false;
  return true;
}

std::string subject_screen_settings_text(const SubjectScreenSettings& settings) {
  std::string text;
  if (settings.window) text += subject_window_rect_text(*settings.window) + "\n";
  if (settings.monitor)
    text += "monitor " + subject_window_rect_text(settings.monitor->rect) + " " + settings.monitor->name + "\n";
  return text;
}

SubjectScreenSettings parse_subject_screen_settings(const std::string& text) {
  SubjectScreenSettings settings;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // a file edited on Windows
    if (line.rfind("monitor ", 0) != 0) {
      if (const auto rect = parse_subject_window_rect(line)) settings.window = rect;
      continue;
    }
    std::istringstream in(line.substr(8));
    Monitor m;
    if (!(in >> m.rect.x >> m.rect.y >> m.rect.width >> m.rect.height)) continue;
    std::getline(in >> std::ws, m.name);
    if (m.rect.width > 0 && m.rect.height > 0 && !m.name.empty()) settings.monitor = m;
  }
  return settings;
}

}  // namespace lmc::ui
