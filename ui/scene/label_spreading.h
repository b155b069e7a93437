#pragma once
// Keeps scene labels from printing over each other ("LMC1" and "LMC2" overlapped in the
// default view when two controllers stand close). Screen-space only: the labels' 3-D anchors are
// projected first; this moves a label up to just above the label in its way, step by step,
// until it clears every label placed before it. Earlier labels keep their place, so the order of the list is the
// priority.
#include <vector>

namespace lmc::ui {

struct LabelBox {
  float x = 0, y = 0;  // top-left, pixels
  float width = 0, height = 0;
};

// Returns the boxes moved so that no two overlap (each moved only upwards, each step to `gap`
// pixels above the label it overlapped). At most `max_steps` steps per label: a label that still
// overlaps after that stays where the last step put it.
std::vector<LabelBox> spread_labels(std::vector<LabelBox> boxes, float gap = 1.0f, int max_steps = 6);

}  // namespace lmc::ui
