#pragma once
#include <memory>

#include "ui/tabs/tab.h"

namespace lmc::ui {

std::unique_ptr<Tab> make_layout_tab(StatusSink& status);

}  // namespace lmc::ui
