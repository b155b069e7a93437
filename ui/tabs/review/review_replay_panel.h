#pragma once
// The 3D replay beside the Review tab's plots: the rig at the plots' cursor time —
// each controller's hand, the Vicon hand and the fused hand coloured by how many controllers saw
// each finger — with Play and a time slider that move the same cursor the plots show.
#include <memory>

#include "ui/model/review/review_state.h"
#include "ui/scene/orbit_camera.h"
#include "ui/widgets/panel.h"
#include "ui/widgets/widget_anchors.h"

namespace lmc::ui {

class ReviewReplayPanel : public Panel {
 public:
  explicit ReviewReplayPanel(std::shared_ptr<ReviewState> state) : Panel("replay"), state_(std::move(state)) {}
  void draw();
  bool playing() const { return playing_; }
  // "play" and "time" as drawn (headless tests click them).
  const WidgetAnchors& anchors() const { return anchors_; }

 private:
  std::shared_ptr<ReviewState> state_;
  OrbitCamera camera_;
  bool playing_ = false;
  WidgetAnchors anchors_;
};

}  // namespace lmc::ui
