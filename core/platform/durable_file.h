#pragma once
// Files that must survive a crash or power loss (the journal, sidecars, recorded rows): one
// interface, with the Linux half (open/write/fsync/rename) in durable_file_posix.cpp and the Windows
// half (CreateFileW/WriteFile/FlushFileBuffers/MoveFileExW) in durable_file_windows.cpp.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

namespace lmc::platform {

enum class OpenMode {
  truncate,    // created or emptied
  append,      // must exist; every write goes to its end
  append_new,  // must not exist yet; created, then as append
};

class DurableFile {
 public:
  DurableFile() = default;
  // Throws lmc::Error naming the path when the file cannot be opened. On Windows a file held open
  // by another program (a spreadsheet, a virus scanner) is retried for a moment first, then named
  // in the message with what to close.
  DurableFile(const std::filesystem::path& path, OpenMode mode);
  ~DurableFile();
  DurableFile(DurableFile&& other) noexcept
      : handle_(other.handle_), error_(std::move(other.error_)), written_(other.written_) {
    other.handle_ = kClosed;
  }
  DurableFile& operator=(DurableFile&& other) noexcept {
    if (this != &other) {
      close();
      handle_ = other.handle_;
      error_ = std::move(other.error_);
      written_ = other.written_;
      other.handle_ = kClosed;
    }
    return *this;
  }
  DurableFile(const DurableFile&) = delete;
  DurableFile& operator=(const DurableFile&) = delete;

  bool is_open() const { return handle_ != kClosed; }
  // All of data, or false with last_error() saying why (with what the operator can do about a
  // full disk or a file-size limit). bytes_written() counts what reached the file, including the
  // part of a write that then failed.
  bool write(std::string_view data);
  std::uint64_t bytes_written() const { return written_; }
  // True once the file was deleted while open (its folder removed): writes still succeed but
  // nothing keeps them.
  bool deleted_while_open() const;
  // Data and size on the disk (fsync / FlushFileBuffers). Media that cannot sync (a pipe, a
  // read-only mount) count as synced.
  bool sync();
  bool close();
  const std::string& last_error() const { return error_; }

 private:
  static constexpr std::intptr_t kClosed = -1;
  std::intptr_t handle_ = kClosed;  // a file descriptor on Linux, a HANDLE on Windows
  std::string error_;
  std::uint64_t written_ = 0;
};

// Replaces `to` by `from` in one step that a crash cannot split (rename on Linux;
// MoveFileExW with REPLACE_EXISTING | WRITE_THROUGH on Windows, retried while another program holds
// `to` open). Throws lmc::Error naming `to`; `from` is then left in place.
void replace_file(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace lmc::platform
