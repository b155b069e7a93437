#include "ui/app/subject_screen.h"

#include <exception>
#include <fstream>
#include <sstream>

#include "ui/model/record/subject_window_placement.h"
#include "ui/platform/user_config.h"
#include "ui/tabs/record/subject_screen_panel.h"

namespace lmc::ui {

SubjectScreen::SubjectScreen(GLFWwindow* main_window, int hidden_width, int hidden_height)
    : main_(main_window), hidden_width_(hidden_width), hidden_height_(hidden_height) {}

namespace {

std::filesystem::path placement_file() {
  const std::filesystem::path dir = user_config_dir();
  return dir.empty() ? dir : dir / "subject_window.txt";
}

std::optional<ScreenRect> remembered_placement() {
  const std::filesystem::path file = placement_file();
  if (file.empty()) return std::nullopt;
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line)) return std::nullopt;
  return parse_subject_window_rect(line);
}

}  // namespace

SubjectScreen::~SubjectScreen() {
  remember_placement();
}

void SubjectScreen::remember_placement() {
  if (!window_ || hidden_width_ > 0 || !window_->options().windowed) return;
  const std::filesystem::path file = placement_file();
  if (file.empty()) return;
  ScreenRect r;
  window_->placement(r.x, r.y, r.width, r.height);
  std::ofstream(file, std::ios::trunc) << subject_window_rect_text(r) << "\n";
}

void SubjectScreen::frame(SubjectScreenLink& link, const std::string& png_path) {
  link.monitors.clear();
  for (const auto& m : list_monitors()) link.monitors.push_back(m.name);
  if (window_ && window_->closed_by_user()) {
    remember_placement();
    window_.reset();
    link.open = false;
  }
  const bool hidden = hidden_width_ > 0;
  const bool windowed = subject_screen_windowed(link);
  if (window_ && (!link.open || (!hidden && (window_->options().monitor != link.monitor ||
                                             window_->options().windowed != windowed)))) {
    remember_placement();
    window_.reset();
  }
  if (link.open && !window_) {
    SubjectWindowOptions options;
    options.monitor = link.monitor;
    options.windowed = windowed;
    if (windowed && !hidden) {
      std::vector<ScreenRect> monitors;
      for (const auto& m : list_monitors()) monitors.push_back({m.x, m.y, m.width, m.height});
      ScreenRect operator_window;
      window_placement(main_, operator_window.x, operator_window.y, operator_window.width, operator_window.height);
      const ScreenRect r = subject_window_rect(monitors, link.monitor, operator_window, remembered_placement());
      options.window_x = r.x;
      options.window_y = r.y;
      options.window_width = r.width;
      options.window_height = r.height;
    }
    options.visible = !hidden;
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
  link.shown = window_ != nullptr;
  if (window_) window_->frame([&link](const SubjectFonts& fonts) { SubjectScreenPanel(link).draw(fonts); }, png_path);
}

}  // namespace lmc::ui
