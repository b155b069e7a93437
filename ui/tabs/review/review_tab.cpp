#include "ui/tabs/review/review_tab.h"

#include "ui/widgets/placeholder_panel.h"

namespace lmc::ui {
namespace {

class ReviewTab final : public Tab {
 public:
  void draw() override {
    draw_placeholder_panel("Review", "Process recorded trials and compare them with Vicon: finger lengths, joint angles, range of motion, visibility rates.", {"Resample, realign and fuse recordings", "Plots against Vicon ground truth", "Tables and figures to export"});
  }
};

}  // namespace

std::unique_ptr<Tab> make_review_tab(StatusSink&) { return std::make_unique<ReviewTab>(); }

}  // namespace lmc::ui
