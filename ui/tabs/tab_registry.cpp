#include "ui/tabs/tab_registry.h"

#include "ui/tabs/devices/devices_tab.h"
#include "ui/tabs/layout/layout_tab.h"
#include "ui/tabs/record/record_tab.h"
#include "ui/tabs/review/review_tab.h"

namespace lmc::ui {

const std::vector<TabInfo>& tab_registry() {
  static const std::vector<TabInfo> tabs = {
      {"layout", "Layout", [](StatusSink& s, WorkbenchContext& c) { return make_layout_tab(s, c); }},
      {"devices", "Devices", [](StatusSink& s, WorkbenchContext& c) { return make_devices_tab(s, c); }},
      {"record", "Record", [](StatusSink& s, WorkbenchContext& c) { return make_record_tab(s, c); }},
      {"review", "Review", [](StatusSink& s, WorkbenchContext& c) { return make_review_tab(s, c); }},
  };
  return tabs;
}

}  // namespace lmc::ui
