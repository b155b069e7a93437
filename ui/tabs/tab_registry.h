#pragma once
// The single list of tabs: it feeds the tab bar, `--capture --tab NAME` and the smoke tests.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ui/model/workbench_context.h"
#include "ui/tabs/tab.h"

namespace lmc::ui {

struct TabInfo {
  std::string id;     // "layout", "devices", "record", "review" (used by --tab)
  std::string title;  // shown in the tab bar
  // The shell's context (one layout, one live rig) outlives every tab it is given to.
  std::function<std::unique_ptr<Tab>(StatusSink&, WorkbenchContext&)> make;
};

const std::vector<TabInfo>& tab_registry();

}  // namespace lmc::ui
