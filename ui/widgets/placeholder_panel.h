#pragma once
// A centred card that says what a tab will hold, for tabs whose tools have not landed yet.
#include <string>
#include <vector>

namespace lmc::ui {

void draw_placeholder_panel(const char* heading, const std::string& purpose, const std::vector<std::string>& planned);

}  // namespace lmc::ui
