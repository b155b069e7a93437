#pragma once
// How a tab that does not own the layout document changes it (the Devices tab's
// Calibrate step): through the owner's undo history, so the change is one named undo step there
// ("Apply calibration") and Ctrl+Z in either tab takes it back. The Layout tab registers its
// editor in CurrentLayout (current_layout.h); tests use DocumentLayoutEditor on a bare document.
// UI thread only.
#include <string>

#include "core/layout/layout.h"
#include "ui/model/layout/layout_actions.h"

namespace lmc::ui {

class LayoutEditor {
 public:
  virtual ~LayoutEditor() = default;
  // The committed layout (what is published to the rig).
  virtual const Layout& committed() const = 0;
  // apply_calibration (layout_actions.h) on the owner's history: one undo step, or the reason.
  virtual ActionResult apply_calibration(const Layout& calibrated) = 0;
  virtual bool can_undo() const = 0;
  virtual std::string undo_message() const = 0;  // "Apply calibration"
  virtual void undo() = 0;
};

// The editor of a plain undoable document.
class DocumentLayoutEditor final : public LayoutEditor {
 public:
  explicit DocumentLayoutEditor(UndoableLayoutDocument& doc) : doc_(doc) {}
  const Layout& committed() const override { return doc_.head().layout; }
  ActionResult apply_calibration(const Layout& calibrated) override { return ui::apply_calibration(doc_, calibrated); }
  bool can_undo() const override { return doc_.can_undo(); }
  std::string undo_message() const override { return doc_.undo_message(); }
  void undo() override { doc_.undo(); }

 private:
  UndoableLayoutDocument& doc_;
};

}  // namespace lmc::ui
