#include "ui/model/shell/ui_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace lmc::ui {
namespace {

constexpr float kMinScale = 1.0F;
constexpr float kMaxScale = 3.0F;
constexpr float kBuiltInFontPx = 13.0F;

}  // namespace

UiScale choose_ui_scale(float content_scale, std::optional<float> override_scale) {
  float s = override_scale.value_or(content_scale);
  if (!std::isfinite(s) || s <= 0.0F) s = 1.0F;
  s = std::clamp(std::round(s * 4.0F) / 4.0F, kMinScale, kMaxScale);
  return UiScale{s, kBuiltInFontPx * s};
}

bool parse_ui_scale(const std::string& text, std::optional<float>& scale, std::string& error) {
  if (text.empty() || text == "auto") {
    scale.reset();
    return true;
  }
  const bool percent = text.back() == '%';
  const std::string number = percent ? text.substr(0, text.size() - 1) : text;
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  const double s = percent ? value / 100.0 : value;
  if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(s) || s < kMinScale || s > kMaxScale) {
    error = "--ui-scale: '" + text + "' is not a scale from 1 to 3 (1.5 or 150% for a 150 % screen, or auto)";
    return false;
  }
  scale = static_cast<float>(s);
  return true;
}

int scaled_pixels(int logical, const UiScale& scale) {
  return static_cast<int>(std::lround(static_cast<double>(logical) * scale.scale));
}

}  // namespace lmc::ui
