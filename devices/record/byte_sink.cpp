#include "devices/record/byte_sink.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/common/error.h"

namespace lmc::devices {
namespace {

class FileSink final : public ByteSink {
 public:
  FileSink(int fd, std::filesystem::path path) : fd_(fd), path_(std::move(path)) {}
  ~FileSink() override { close(); }

  bool write(std::string_view data) override {
    while (!data.empty()) {
      const ssize_t n = ::write(fd_, data.data(), data.size());
      if (n < 0) {
        if (errno == EINTR) continue;
        return fail("write");
      }
      data.remove_prefix(static_cast<size_t>(n));
      written_ += static_cast<std::uint64_t>(n);
    }
    return true;
  }
  bool sync() override { return ::fsync(fd_) == 0 || errno == EINVAL || errno == EROFS ? true : fail("fsync"); }
  bool close() override {
    if (fd_ < 0) return true;
    const int rc = ::close(fd_);
    fd_ = -1;
    return rc == 0 ? true : fail("close");
  }
  std::string error() const override { return error_; }
  std::uint64_t bytes_written() const override { return written_; }
  // An unlinked file keeps accepting writes into an inode no folder holds; only the link count
  // of the open descriptor shows it (a trial ran on into a deleted folder).
  std::string lost() const override {
    struct stat st {};
    if (fd_ < 0 || ::fstat(fd_, &st) != 0 || st.st_nlink > 0) return {};
    return path_.string() + " was deleted while recording (was its folder removed?)";
  }

 private:
  bool fail(const char* what) {
    const int err = errno;
    error_ = std::string(what) + " " + path_.string() + ": " + std::strerror(err);
    // Say what the operator can do about the two everyday causes.
    if (err == EFBIG) error_ += "; the file size limit (ulimit -f) was reached";
    if (err == ENOSPC) error_ += "; the disk is full: free space or record to another disk";
    return false;
  }
  int fd_;
  std::filesystem::path path_;
  std::string error_;
  std::uint64_t written_ = 0;
};

}  // namespace

std::unique_ptr<ByteSink> open_file_sink(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw Error(ErrorLocation(path.string()), std::string("cannot create file: ") + std::strerror(errno));
  return std::make_unique<FileSink>(fd, path);
}

}  // namespace lmc::devices
