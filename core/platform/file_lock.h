#pragma once
// A lock one process at a time holds on a file (a session folder's .lock), released when the
// process ends however it ends. Linux: flock on the file; Windows: LockFileEx on a byte far past
// the file's text, so another process can still read who holds it.
#include <cstdint>
#include <filesystem>
#include <string>

namespace lmc::platform {

class FileLock {
 public:
  FileLock() = default;
  ~FileLock() { release(); }
  FileLock(FileLock&& other) noexcept : handle_(other.handle_) { other.handle_ = kNone; }
  FileLock& operator=(FileLock&& other) noexcept {
    if (this != &other) {
      release();
      handle_ = other.handle_;
      other.handle_ = kNone;
    }
    return *this;
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

  // Takes the lock on `path` (created when absent) and writes `owner` into the file. When another
  // process holds it, returns an unheld lock and sets *holder to the text that process wrote.
  // Throws lmc::Error naming the path when the file cannot be created.
  static FileLock take(const std::filesystem::path& path, const std::string& owner, std::string* holder);
  bool held() const { return handle_ != kNone; }
  void release();

 private:
  static constexpr std::intptr_t kNone = -1;
  std::intptr_t handle_ = kNone;  // a file descriptor on Linux, a HANDLE on Windows
};

// A small state file (the Vicon PacketID counter) that one process at a time reads and rewrites:
// open() waits for the lock. Released when destroyed.
class LockedFile {
 public:
  LockedFile() = default;
  ~LockedFile();
  LockedFile(LockedFile&& other) noexcept : handle_(other.handle_) { other.handle_ = kNone; }
  LockedFile& operator=(LockedFile&& other) noexcept;
  LockedFile(const LockedFile&) = delete;
  LockedFile& operator=(const LockedFile&) = delete;

  // Creates the file when absent; *text gets its first 64 bytes. Throws lmc::Error naming the path.
  static LockedFile open(const std::filesystem::path& path, std::string* text);
  // The file then holds exactly `text`; false with *error set when that failed.
  bool replace_text(const std::string& text, std::string* error);

 private:
  static constexpr std::intptr_t kNone = -1;
  std::intptr_t handle_ = kNone;
};

// Whether some process holds the lock on `path` (false when there is no such file).
bool file_lock_is_held(const std::filesystem::path& path);

}  // namespace lmc::platform
