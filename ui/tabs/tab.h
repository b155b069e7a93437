#pragma once
// A workbench tab: one area of the product (Layout, Devices, Record, Review). The shell calls
// update() on every tab every frame before any drawing (poll jobs, drain device snapshots, refresh
// caches), telling each whether it is the one on screen, then draw() for that one inside its
// region. draw() only emits ImGui calls.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace lmc::ui {

class StatusSink;

// What the shell's File menu asks of the tab that owns a document.
enum class FileCommand { kNew, kOpen, kSave, kSaveAs };

class Tab {
 public:
  virtual ~Tab() = default;
  // `shown`: this tab was the one on screen in the last frame. Work only a person looking at the
  // tab needs (the Layout heatmap) waits for it; recording, processing and the optimiser do not.
  virtual void update(bool /*shown*/) {}
  virtual void draw() = 0;
  // Text for the window title (e.g. the open layout file and an unsaved mark); empty for none.
  virtual std::string document_title() const { return {}; }
  // True when quitting would lose work; the shell then asks before closing.
  virtual bool has_unsaved_changes() const { return false; }
  // What quitting now would cut off ("Naiv_Index101 is recording"); empty when nothing records.
  // The shell then asks: stop it and keep what was recorded, or keep recording.
  virtual std::string recording_now() const { return {}; }
  // Stops it as the operator's Stop does (the rows kept); the shell quits once recording_now() is empty.
  virtual void stop_recording() {}
  // ---- the File menu (the shell forwards; the tab keeps its own dialogs and prompts) --------
  // The kind of document the tab opens and saves ("layout"); empty when it has none.
  virtual std::string document_kind() const { return {}; }
  virtual void handle_file_command(FileCommand /*command*/) {}
  // Opens a known file (a recent entry), asking first when work would be lost.
  virtual void open_document(const std::filesystem::path& /*path*/) {}
  // The file the document was last read from or written to (feeds the recent list).
  virtual std::optional<std::filesystem::path> document_path() const { return std::nullopt; }
};

// What tabs may tell the shell: one line in the status bar.
class StatusSink {
 public:
  virtual ~StatusSink() = default;
  virtual void set_status(const std::string& text, bool is_error = false) = 0;
};

}  // namespace lmc::ui
