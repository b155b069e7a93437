#include "ui/tabs/record/record_tab.h"

#include "ui/widgets/placeholder_panel.h"

namespace lmc::ui {
namespace {

class RecordTab final : public Tab {
 public:
  void draw() override {
    draw_placeholder_panel("Record", "Run the study's 16-trial protocol with cues for the subject, trigger Vicon, and never lose a frame.", {"Subject and session set-up", "Trial list with cues (a large red circle at start)", "Vicon UDP trigger status", "Per-device rates and frames written"});
  }
};

}  // namespace

std::unique_ptr<Tab> make_record_tab(StatusSink&) { return std::make_unique<RecordTab>(); }

}  // namespace lmc::ui
