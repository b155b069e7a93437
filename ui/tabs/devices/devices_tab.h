#pragma once
#include <memory>

#include "ui/model/workbench_context.h"
#include "ui/tabs/tab.h"

namespace lmc::ui {

// `context` (the workbench's one layout and live rig) must outlive the tab.
std::unique_ptr<Tab> make_devices_tab(StatusSink& status, WorkbenchContext& context);

}  // namespace lmc::ui
