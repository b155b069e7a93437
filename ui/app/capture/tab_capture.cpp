#include "ui/app/capture/tab_capture.h"

#include "ui/tabs/devices/devices_tab.h"
#include "ui/tabs/layout/layout_tab.h"
#include "ui/tabs/record/record_tab.h"
#include "ui/tabs/review/review_tab.h"

namespace lmc::ui {

std::unique_ptr<TabCapture> make_tab_capture(Tab& tab, WorkbenchContext& context) {
  if (auto* layout = dynamic_cast<LayoutTab*>(&tab)) return make_layout_capture(*layout);
  if (auto* devices = dynamic_cast<DevicesTab*>(&tab)) return make_devices_capture(*devices);
  if (auto* record = dynamic_cast<RecordTab*>(&tab)) return make_record_capture(*record, context);
  if (auto* review = dynamic_cast<ReviewTab*>(&tab)) return make_review_capture(*review, context);
  return std::make_unique<TabCapture>();
}

}  // namespace lmc::ui
