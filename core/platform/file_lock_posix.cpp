#ifndef _WIN32
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/common/error.h"
#include "core/platform/file_lock.h"

namespace lmc::platform {

void FileLock::release() {
  if (handle_ == kNone) return;
  ::close(static_cast<int>(handle_));  // closing releases the flock
  handle_ = kNone;
}

FileLock FileLock::take(const std::filesystem::path& path, const std::string& owner, std::string* holder) {
  // The holder may remove the file while holding it (a clean close does): a lock taken on a file
  // removed since it was opened locks nothing, so it is taken again on the file now at the path.
  for (int tries = 0;; ++tries) {
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw Error(ErrorLocation{path.string()}, std::string("cannot create the lock: ") + std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      char buf[32] = {};
      const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
      ::close(fd);
      *holder = n > 0 ? std::string(buf, static_cast<size_t>(n)) : std::string("unknown");
      return {};
    }
    struct stat held {};
    struct stat at_path {};
    if (::fstat(fd, &held) == 0 && ::stat(path.c_str(), &at_path) == 0 && held.st_ino == at_path.st_ino &&
        held.st_dev == at_path.st_dev) {
      if (::ftruncate(fd, 0) == 0) {
        [[maybe_unused]] const ssize_t w = ::pwrite(fd, owner.data(), owner.size(), 0);
      }
      FileLock lock;
      lock.handle_ = fd;
      return lock;
    }
    ::close(fd);
    if (tries >= 10) throw Error(ErrorLocation{path.string()}, "the lock file keeps changing; try again");
  }
}

bool file_lock_is_held(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0;
  ::close(fd);
  return held;
}

LockedFile::~LockedFile() {
  if (handle_ != kNone) ::close(static_cast<int>(handle_));
}

LockedFile& LockedFile::operator=(LockedFile&& other) noexcept {
  if (this != &other) {
    if (handle_ != kNone) ::close(static_cast<int>(handle_));
    handle_ = other.handle_;
    other.handle_ = kNone;
  }
  return *this;
}

LockedFile LockedFile::open(const std::filesystem::path& path, std::string* text) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw Error(ErrorLocation{path.string()}, std::strerror(errno));
  while (::flock(fd, LOCK_EX) != 0 && errno == EINTR) {
  }
  char buf[64] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf, 0);
  text->assign(buf, n > 0 ? static_cast<size_t>(n) : 0);
  LockedFile file;
  file.handle_ = fd;
  return file;
}

bool LockedFile::replace_text(const std::string& text, std::string* error) {
  const int fd = static_cast<int>(handle_);
  if (::ftruncate(fd, 0) == 0 && ::pwrite(fd, text.data(), text.size(), 0) == static_cast<ssize_t>(text.size()))
    return true;
  *error = std::strerror(errno);
  return false;
}

}  // namespace lmc::platform
#endif
