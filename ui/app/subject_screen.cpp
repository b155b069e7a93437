#include "ui/app/subject_screen.h"

#include <exception>

#include "ui/tabs/record/subject_screen_panel.h"

namespace lmc::ui {

SubjectScreen::SubjectScreen(GLFWwindow* main_window, int hidden_width, int hidden_height)
    : main_(main_window), hidden_width_(hidden_width), hidden_height_(hidden_height) {}

SubjectScreen::~SubjectScreen() = default;

void SubjectScreen::frame(SubjectScreenLink& link, const std::string& png_path) {
  link.monitors.clear();
  for (const auto& m : list_monitors()) link.monitors.push_back(m.name);
  if (window_ && window_->closed_by_user()) {
    window_.reset();
    link.open = false;
  }
  const bool hidden = hidden_width_ > 0;
  const bool windowed = subject_screen_windowed(link);
  if (window_ && (!link.open ||
                  (!hidden && (window_->options().monitor != link.monitor || window_->options().windowed != windowed))))
    window_.reset();
  if (link.open && !window_) {
    SubjectWindowOptions options;
    options.monitor = link.monitor;
    options.windowed = windowed;
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
