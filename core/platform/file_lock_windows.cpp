#ifdef _WIN32
#include <windows.h>

#include "core/common/error.h"
#include "core/platform/file_lock.h"
#include "core/platform/system_error.h"

namespace lmc::platform {
namespace {

// Windows byte-range locks are mandatory: a locked byte cannot be read by anyone else. The lock
// sits far past the owner's text so that text stays readable for the message of the one refused.
constexpr DWORD kLockOffsetHigh = 1;  // byte 4 GiB

HANDLE lock_handle(std::intptr_t h) {
  return reinterpret_cast<HANDLE>(h);
}

HANDLE open_shared(const std::filesystem::path& path, DWORD access, DWORD disposition) {
  // Shared for reading, writing and deleting: the lock, not the sharing mode, is what excludes.
  return CreateFileW(path.c_str(), access, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr, disposition,
                     FILE_ATTRIBUTE_NORMAL, nullptr);
}

bool lock_range(HANDLE h, DWORD flags) {
  OVERLAPPED where{};
  where.OffsetHigh = kLockOffsetHigh;
  return LockFileEx(h, flags | LOCKFILE_FAIL_IMMEDIATELY, 0, 1, 0, &where) != 0;
}

void unlock_range(HANDLE h) {
  OVERLAPPED where{};
  where.OffsetHigh = kLockOffsetHigh;
  UnlockFileEx(h, 0, 1, 0, &where);
}

}  // namespace

void FileLock::release() {
  if (handle_ == kNone) return;
  unlock_range(lock_handle(handle_));
  CloseHandle(lock_handle(handle_));  // Windows also drops a lock whose process ends
  handle_ = kNone;
}

FileLock FileLock::take(const std::filesystem::path& path, const std::string& owner, std::string* holder) {
  // A file deleted while open stays "delete pending" until its last handle closes and cannot be
  // opened again meanwhile: a holder closing cleanly is retried for a moment.
  HANDLE h = INVALID_HANDLE_VALUE;
  for (int tries = 0; h == INVALID_HANDLE_VALUE; ++tries) {
    h = open_shared(path, GENERIC_READ | GENERIC_WRITE, OPEN_ALWAYS);
    if (h == INVALID_HANDLE_VALUE) {
      if (GetLastError() != ERROR_ACCESS_DENIED || tries >= 20)
        throw Error(ErrorLocation{path.string()}, "cannot create the lock: " + last_system_error());
      Sleep(50);
    }
  }
  if (!lock_range(h, LOCKFILE_EXCLUSIVE_LOCK)) {
    char buf[32] = {};
    DWORD n = 0;
    const BOOL read = ReadFile(h, buf, sizeof buf - 1, &n, nullptr);
    CloseHandle(h);
    *holder = read && n > 0 ? std::string(buf, n) : std::string("unknown");
    return {};
  }
  DWORD written = 0;
  if (SetEndOfFile(h)) WriteFile(h, owner.data(), static_cast<DWORD>(owner.size()), &written, nullptr);
  FileLock lock;
  lock.handle_ = reinterpret_cast<std::intptr_t>(h);
  return lock;
}

bool file_lock_is_held(const std::filesystem::path& path) {
  const HANDLE h = open_shared(path, GENERIC_READ, OPEN_EXISTING);
  if (h == INVALID_HANDLE_VALUE) return GetLastError() == ERROR_ACCESS_DENIED;  // delete pending: its holder is closing
  const bool held = !lock_range(h, 0);
  if (!held) unlock_range(h);
  CloseHandle(h);
  return held;
}

LockedFile::~LockedFile() {
  if (handle_ != kNone) CloseHandle(lock_handle(handle_));  // closing drops the lock
}

LockedFile& LockedFile::operator=(LockedFile&& other) noexcept {
  if (this != &other) {
    if (handle_ != kNone) CloseHandle(lock_handle(handle_));
    handle_ = other.handle_;
    other.handle_ = kNone;
  }
  return *this;
}

LockedFile LockedFile::open(const std::filesystem::path& path, std::string* text) {
  const HANDLE h = open_shared(path, GENERIC_READ | GENERIC_WRITE, OPEN_ALWAYS);
  if (h == INVALID_HANDLE_VALUE) throw Error(ErrorLocation{path.string()}, last_system_error());
  OVERLAPPED where{};
  where.OffsetHigh = kLockOffsetHigh;
  LockFileEx(h, LOCKFILE_EXCLUSIVE_LOCK, 0, 1, 0, &where);  // waits for the holder
  char buf[64] = {};
  DWORD n = 0;
  if (!ReadFile(h, buf, sizeof buf, &n, nullptr)) n = 0;
  text->assign(buf, n);
  LockedFile file;
  file.handle_ = reinterpret_cast<std::intptr_t>(h);
  return file;
}

bool LockedFile::replace_text(const std::string& text, std::string* error) {
  const HANDLE h = lock_handle(handle_);
  DWORD written = 0;
  if (SetFilePointer(h, 0, nullptr, FILE_BEGIN) != INVALID_SET_FILE_POINTER && SetEndOfFile(h) &&
      WriteFile(h, text.data(), static_cast<DWORD>(text.size()), &written, nullptr) && written == text.size())
    return true;
  *error = last_system_error();
  return false;
}

}  // namespace lmc::platform
#endif
