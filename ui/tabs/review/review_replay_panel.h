#pragma once
// The 3D replay beside the Review tab's plots: the rig at the plots' cursor time —
// each controller's hand, the Vicon hand and the fused hand coloured by how many controllers saw
// each finger — with Play and a time slider that move the same cursor the plots show.
#include "ui/model/review/review_state.h"
#include "ui/scene/orbit_camera.h"

namespace lmc::ui {

class ReviewReplayPanel {
 public:
  void draw(ReviewState& state);

 private:
  OrbitCamera camera_;
  bool playing_ = false;
};

}  // namespace lmc::ui
