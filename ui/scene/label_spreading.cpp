#include "ui/scene/label_spreading.h"

namespace lmc::ui {
namespace {

bool label_boxes_overlap(const LabelBox& a, const LabelBox& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

}  // namespace

std::vector<LabelBox> spread_labels(std::vector<LabelBox> boxes, float gap, int max_steps) {
  for (size_t i = 1; i < boxes.size(); ++i) {
    for (int step = 0; step < max_steps; ++step) {
      const LabelBox* blocker = nullptr;
      for (size_t j = 0; j < i && blocker == nullptr; ++j) {
        if (label_boxes_overlap(boxes[i], boxes[j])) blocker = &boxes[j];
      }
      if (blocker == nullptr) break;
      boxes[i].y = blocker->y - boxes[i].height - gap;  // just above the label in the way
    }
  }
  return boxes;
}

}  // namespace lmc::ui
