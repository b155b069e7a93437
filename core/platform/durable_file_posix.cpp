#ifndef _WIN32
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/common/error.h"
#include "core/platform/durable_file.h"
#include "core/platform/system_error.h"

namespace lmc::platform {

namespace {

// The error text with what the operator can do about the two everyday causes.
std::string write_error_text() {
  const int err = errno;
  std::string text = std::strerror(err);
  if (err == EFBIG) text += "; the file size limit (ulimit -f) was reached";
  if (err == ENOSPC) text += "; the disk is full: free space or record to another disk";
  return text;
}

}  // namespace

DurableFile::DurableFile(const std::filesystem::path& path, OpenMode mode) {
  int flags = O_WRONLY | O_CLOEXEC;
  switch (mode) {
    case OpenMode::truncate:
      flags |= O_CREAT | O_TRUNC;
      break;
    case OpenMode::append:
      flags |= O_APPEND;
      break;
    case OpenMode::append_new:
      flags |= O_APPEND | O_CREAT | O_EXCL;
      break;
  }
  const int fd = ::open(path.c_str(), flags, 0644);
  if (fd < 0) throw Error(ErrorLocation{path.string()}, "cannot open for writing: " + last_system_error());
  handle_ = fd;
}

DurableFile::~DurableFile() {
  if (is_open()) ::close(static_cast<int>(handle_));
}

bool DurableFile::write(std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = ::write(static_cast<int>(handle_), data.data(), data.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      error_ = write_error_text();
      return false;
    }
    data.remove_prefix(static_cast<size_t>(n));
    written_ += static_cast<std::uint64_t>(n);
  }
  return true;
}

bool DurableFile::deleted_while_open() const {
  // An unlinked file keeps accepting writes into an inode no folder holds; only the link count of
  // the open descriptor shows it.
  struct stat st {};
  return is_open() && ::fstat(static_cast<int>(handle_), &st) == 0 && st.st_nlink == 0;
}

bool DurableFile::sync() {
  if (::fsync(static_cast<int>(handle_)) == 0 || errno == EINVAL || errno == EROFS) return true;
  error_ = last_system_error();
  return false;
}

bool DurableFile::close() {
  if (!is_open()) return true;
  const int rc = ::close(static_cast<int>(handle_));
  handle_ = kClosed;
  if (rc == 0) return true;
  error_ = last_system_error();
  return false;
}

void replace_file(const std::filesystem::path& from, const std::filesystem::path& to) {
  // rename() is atomic on one filesystem: a reader sees the old file or the new one, never a mix.
  if (std::rename(from.c_str(), to.c_str()) != 0)
    throw Error(ErrorLocation{to.string()}, "rename failed: " + last_system_error());
}

}  // namespace lmc::platform
#endif
