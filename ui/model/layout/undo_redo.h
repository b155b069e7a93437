#pragma once
// Snapshot-based undo/redo (docs/architecture.md). The whole document is copied per commit: our layout
// documents are a few hundred bytes, and snapshots need no inverse per command — the usual source
// of undo bugs.
//
// There is always a *head* (the last committed state) and a *scratch* copy that edits go into.
// commit() makes scratch the new head and pushes the old head onto the undo list; rollback()
// throws the scratch edits away. A drag edits scratch every frame and commits once on release,
// so a drag is one undo step.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <utility>

namespace lmc::ui {

// The type-erased face: enough for menu labels ("Undo Move LMC2") and a history list.
class UndoRedoBase {
 public:
  virtual ~UndoRedoBase() = default;
  virtual bool can_undo() const = 0;
  virtual bool can_redo() const = 0;
  virtual void undo() = 0;
  virtual void redo() = 0;
  virtual std::string undo_message() const = 0;  // message of the commit undo() would revert
  virtual std::string redo_message() const = 0;
  virtual std::uint64_t head_id() const = 0;  // changes on every commit, undo and redo
  virtual size_t undo_size() const = 0;
  virtual size_t redo_size() const = 0;
};

template <class T>
class UndoRedo final : public UndoRedoBase {
 public:
  explicit UndoRedo(T initial = T{}, size_t max_history = 500)
      : head_{next_id_++, "Initial state", std::move(initial)}, scratch_(head_.value), max_history_(max_history) {}

  const T& head() const { return head_.value; }
  const T& scratch() const { return scratch_; }
  // care: writes here are invisible to undo until commit(); call rollback() to drop them.
  T& upd_scratch() { return scratch_; }
  bool scratch_differs() const { return !(scratch_ == head_.value); }

  // Makes scratch the new head. Does nothing (returns false) when scratch equals head, so an
  // action that changed nothing leaves no history entry.
  bool commit(std::string message) {
    if (!scratch_differs()) return false;
    undo_.push_back(std::move(head_));
    if (undo_.size() > max_history_) undo_.pop_front();
    head_ = Entry{next_id_++, std::move(message), scratch_};
    redo_.clear();
    return true;
  }
  void rollback() { scratch_ = head_.value; }

  bool can_undo() const override { return !undo_.empty(); }
  bool can_redo() const override { return !redo_.empty(); }
  void undo() override {
    if (undo_.empty()) return;
    redo_.push_back(std::move(head_));
    head_ = std::move(undo_.back());
    undo_.pop_back();
    scratch_ = head_.value;
  }
  void redo() override {
    if (redo_.empty()) return;
    undo_.push_back(std::move(head_));
    head_ = std::move(redo_.back());
    redo_.pop_back();
    scratch_ = head_.value;
  }
  std::string undo_message() const override { return undo_.empty() ? std::string() : head_.message; }
  std::string redo_message() const override { return redo_.empty() ? std::string() : redo_.back().message; }
  std::uint64_t head_id() const override { return head_.id; }
  size_t undo_size() const override { return undo_.size(); }
  size_t redo_size() const override { return redo_.size(); }
  const std::string& head_message() const { return head_.message; }

 private:
  struct Entry {
    std::uint64_t id = 0;
    std::string message;
    T value;
  };
  // Ids come from a counter so undo-then-redo returns to the same id (the "saved" mark survives).
  std::uint64_t next_id_ = 1;
  Entry head_;
  T scratch_;
  std::deque<Entry> undo_;
  std::deque<Entry> redo_;
  size_t max_history_;
};

}  // namespace lmc::ui
