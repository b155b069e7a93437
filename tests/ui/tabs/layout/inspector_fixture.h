#pragma once
// The Layout tab's Inspector on its own, on a new layout, in a headless ImGui frame `Width` pixels
// wide: the set-up every Inspector test starts from (the panel tests at the tab's width, the model
// tests at the width the tab gives its right-hand panels).
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>

#include "tests/ui/headless_imgui.h"
#include "ui/model/layout/layout_actions.h"
#include "ui/model/layout/layout_state.h"
#include "ui/tabs/layout/inspector_panel.h"

namespace lmc::test {

template <int Width>
struct InspectorAt : ::testing::Test {
  ui::testing::HeadlessImGui gui{Width, 900};
  std::shared_ptr<ui::LayoutState> state =
      std::make_shared<ui::LayoutState>(ui::make_document(ui::default_new_layout()));
  ui::InspectorPanel inspector{state};
  std::function<void()> body() {
    return [this] { inspector.draw(); };
  }
  // One frame to lay the panel out, then a click on the anchor's centre.
  void click(const std::string& anchor) {
    gui.frame(body());
    const auto c = inspector.anchors().centre(anchor);
    ASSERT_TRUE(c.has_value()) << anchor << " is not on screen";
    gui.click(c->x, c->y, body());
  }
};

}  // namespace lmc::test
