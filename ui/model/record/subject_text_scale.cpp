#include "ui/model/record/subject_text_scale.h"

#include <algorithm>

namespace lmc::ui {

float subject_text_scale(float width_px, float height_px) {
  if (width_px <= 0.0F || height_px <= 0.0F) return 1.0F;
  const float ratio = std::min(width_px / kSubjectDesignWidthPx, height_px / kSubjectDesignHeightPx);
  return std::clamp(ratio, kSubjectMinTextScale, 1.0F);
}

float fit_subject_text_scale(float scale, float available_px, const std::function<float(float)>& height_at) {
  float s = std::max(scale, kSubjectMinTextScale);
  while (s > kSubjectMinTextScale && height_at(s) > available_px) s = std::max(kSubjectMinTextScale, s * 0.9F);
  return s;
}

}  // namespace lmc::ui
