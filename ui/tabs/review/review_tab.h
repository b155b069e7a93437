#pragma once
#include <memory>

#include "ui/tabs/tab.h"

namespace lmc::ui {

class WorkbenchContext;

std::unique_ptr<Tab> make_review_tab(StatusSink& status, WorkbenchContext& context);

}  // namespace lmc::ui
