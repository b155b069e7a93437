#pragma once
// While a trial records: frames written, the Vicon trigger's state (packets sent, or in listen
// mode whether CaptureStart / CaptureStop came) and a strip per controller (rate, hand present,
// frame age), from the session model's latest trial snapshot. Draws only; nothing before the
// first snapshot.
#include <memory>

#include "ui/model/record/record_state.h"
#include "ui/widgets/panel.h"

namespace lmc::ui {

class RecordDeviceStripsPanel : public Panel {
 public:
  explicit RecordDeviceStripsPanel(std::shared_ptr<const RecordState> model)
      : Panel("##device_strips"), model_(std::move(model)) {}
  void draw();

 private:
  std::shared_ptr<const RecordState> model_;
};

}  // namespace lmc::ui
