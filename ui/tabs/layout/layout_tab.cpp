#include "ui/tabs/layout/layout_tab.h"

#include "ui/widgets/placeholder_panel.h"

namespace lmc::ui {
namespace {

class LayoutTab final : public Tab {
 public:
  void draw() override {
    draw_placeholder_panel("Layout", "Design where the controllers stand around the hand, see which fingers each one can see, and let the optimiser search for a better layout.", {"3D scene: table, controllers with their viewing pyramids, the hand from a pose set", "Drag and rotate controllers; inspector with locks; undo/redo", "Live per-finger visibility, coverage table and table heatmaps", "Particle-swarm optimiser in the background with progress, cancel and apply"});
  }
};

}  // namespace

std::unique_ptr<Tab> make_layout_tab(StatusSink&) { return std::make_unique<LayoutTab>(); }

}  // namespace lmc::ui
