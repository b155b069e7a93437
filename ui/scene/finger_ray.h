#pragma once
// One line from a controller to a finger marker with the engine's verdict (scene rays, tooltips).
#include <Eigen/Core>
#include <string>

namespace lmc::ui {

struct FingerRay {
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero();
  bool clear = false;
  int digit = 0;
  int marker = 0;      // hand-frame point index
  std::string reason;  // "clear", "hand out of view (…)", "behind the palm", "behind the index finger", ...
};

}  // namespace lmc::ui
