#pragma once
// The workbench's one layout: the Layout tab publishes its committed document here and
// every other client (the live rig of the Devices and Record tabs) reads it, so the whole
// workbench streams, realigns and records with the layout the operator has open. A version number
// tells readers that it changed without comparing layouts every frame. The document's owner also
// registers its editor (layout_editor.h), through which another tab changes the layout as an
// undo step of the owner's history. UI thread only.
#include <cstdint>
#include <utility>

#include "core/layout/layout.h"
#include "ui/model/layout_editor.h"

namespace lmc::ui {

class CurrentLayout {
 public:
  explicit CurrentLayout(Layout initial = {}) : layout_(std::move(initial)) {}

  const Layout& get() const { return layout_; }
  // Bumped by every publish that changes the layout; 0 until the first change.
  std::uint64_t version() const { return version_; }
  // Called by the layout's owner (every frame is fine: an equal layout changes nothing).
  void publish(const Layout& layout) {
    if (layout == layout_) return;
    layout_ = layout;
    ++version_;
  }
  // The document owner's editor; null while no tab owns the document (then edits are refused).
  LayoutEditor* editor() const { return editor_; }
  void set_editor(LayoutEditor* editor) { editor_ = editor; }

 private:
  Layout layout_;
  std::uint64_t version_ = 0;
  LayoutEditor* editor_ = nullptr;
};

}  // namespace lmc::ui
