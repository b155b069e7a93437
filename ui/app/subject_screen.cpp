#include "ui/app/subject_screen.h"

#include <exception>
#include <fstream>
#include <sstream>

#include "core/io/atomic_write.h"
#include "ui/platform/user_config.h"
#include "ui/tabs/record/subject_screen_panel.h"

namespace lmc::ui {

namespace {

std::filesystem::path settings_file() {
  const std::filesystem::path dir = user_config_dir();
  return dir.empty() ? dir : dir / "subject_window.txt";
}

SubjectScreenSettings read_settings() {
  const std::filesystem::path file = settings_file();
  if (file.empty()) return {};
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return parse_subject_screen_settings(text.str());
}

}  // namespace

SubjectScreen::SubjectScreen(GLFWwindow* main_window, int hidden_width, int hidden_height)
    : main_(main_window), hidden_width_(hidden_width), hidden_height_(hidden_height) {
  // A capture pictures the bench's defaults, never the user's own choices.
  if (hidden_width_ <= 0) settings_ = read_settings();
  monitor_changes_seen_ = monitor_changes();
}

SubjectScreen::~SubjectScreen() {
  remember_placement();
}

void SubjectScreen::save_settings() const {
  const std::filesystem::path file = settings_file();
  if (file.empty() || hidden_width_ > 0) return;
  try {
    write_file_atomically(file, subject_screen_settings_text(settings_));
  } catch (const std::exception&) {
    // The choice is kept for this session; only the next one starts without it.
  }
}

void SubjectScreen::remember_placement() {
  if (!window_ || hidden_width_ > 0 || !window_->options().windowed) return;
  ScreenRect r;
  window_->placement(r.x, r.y, r.width, r.height);
  settings_.window = r;
  save_settings();
}

void SubjectScreen::remember_monitor_choice(const SubjectScreenLink& link, const std::vector<Monitor>& monitors) {
  if (link.monitor == monitor_choice_seen_) return;
  monitor_choice_seen_ = link.monitor;
  if (link.monitor < 0 || link.monitor >= static_cast<int>(monitors.size())) return;
  settings_.monitor = monitors[static_cast<size_t>(link.monitor)];
  save_settings();
}

bool SubjectScreen::must_reopen(const SubjectScreenLink& link, const std::vector<Monitor>& monitors, int monitor,
                                bool windowed) {
  const int changes = monitor_changes();
  const bool monitors_changed = changes != monitor_changes_seen_;
  monitor_changes_seen_ = changes;
  if (!link.open) return true;
  if (hidden_width_ > 0) return false;  // --capture: one hidden window whatever the monitors
  const SubjectWindowOptions& now = window_->options();
  // Unplugged (or moved): the monitor it was placed on is not where it was.
  if (monitors_changed && !now.on.name.empty() && subject_monitor_gone(monitors, now.on)) return true;
  const Monitor target = monitor >= 0 ? monitors[static_cast<size_t>(monitor)] : Monitor{};
  return !(target == now.on) || now.windowed != windowed;
}

void SubjectScreen::open(SubjectScreenLink& link, const std::vector<Monitor>& monitors, int monitor, bool windowed) {
  SubjectWindowOptions options;
  options.windowed = windowed;
  if (monitor >= 0) options.on = monitors[static_cast<size_t>(monitor)];
  if (hidden_width_ <= 0) {
    ScreenRect operator_window;
    window_placement(main_, operator_window.x, operator_window.y, operator_window.width, operator_window.height);
    const SubjectScreenPlace place =
        place_subject_screen(monitors, monitor, windowed, operator_window, settings_.window);
    options.place = place.rect;
    options.windowed = !place.covers_monitor;
  }
  options.visible = hidden_width_ <= 0;
  options.width = hidden_width_;
  options.height = hidden_height_;
  try {
    window_ = std::make_unique<SubjectWindow>(main_, options);
    link.problem.clear();
  } catch (const std::exception& e) {
    link.problem = e.what();
    link.open = false;
  }
}

void SubjectScreen::frame(SubjectScreenLink& link, const std::string& png_path) {
  const std::vector<Monitor> monitors = list_monitors();
  link.monitors.clear();
  link.monitor_shorts.clear();
  for (size_t i = 0; i < monitors.size(); ++i) {
    link.monitors.push_back(monitor_label(monitors[i]));
    link.monitor_shorts.push_back(monitor_short_label(static_cast<int>(i), monitors[i]));
  }
  remember_monitor_choice(link, monitors);
  if (window_ && window_->closed_by_user()) {
    remember_placement();
    window_.reset();
    link.open = false;
  }
  const bool windowed = subject_screen_windowed(link);
  const int monitor = choose_subject_monitor(monitors, link.monitor, settings_.monitor);
  link.placed_monitor = monitor;
  if (window_ && must_reopen(link, monitors, monitor, windowed)) {
    remember_placement();
    window_.reset();
  }
  if (link.open && !window_) open(link, monitors, monitor, windowed);
  link.shown = window_ != nullptr;
  if (window_) window_->frame([&link](const SubjectFonts& fonts) { SubjectScreenPanel(link).draw(fonts); }, png_path);
}

}  // namespace lmc::ui
