#include "devices/record/byte_sink.h"

#include "core/common/error.h"
#include "core/platform/durable_file.h"

namespace lmc::devices {
namespace {

class FileSink final : public ByteSink {
 public:
  FileSink(platform::DurableFile file, std::filesystem::path path) : file_(std::move(file)), path_(std::move(path)) {}
  ~FileSink() override { close(); }

  bool write(std::string_view data) override { return file_.write(data) || fail("write"); }
  bool sync() override { return file_.sync() || fail("fsync"); }
  bool close() override { return file_.close() || fail("close"); }
  std::string error() const override { return error_; }
  std::uint64_t bytes_written() const override { return file_.bytes_written(); }
  std::string lost() const override {
    if (!file_.deleted_while_open()) return {};
    return path_.string() + " was deleted while recording (was its folder removed?)";
  }

 private:
  bool fail(const char* what) {
    error_ = std::string(what) + " " + path_.string() + ": " + file_.last_error();
    return false;
  }
  platform::DurableFile file_;
  std::filesystem::path path_;
  std::string error_;
};

}  // namespace

std::unique_ptr<ByteSink> open_file_sink(const std::filesystem::path& path) {
  return std::make_unique<FileSink>(platform::DurableFile(path, platform::OpenMode::truncate), path);
}

}  // namespace lmc::devices
