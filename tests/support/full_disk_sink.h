#pragma once
// A byte sink that runs out of room after `limit` bytes, as a full disk does: the write that
// crosses the limit is cut where the room ends and fails with ENOSPC's message; nothing after it
// reaches the file. For the recorder's and the soak's full-disk tests.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "devices/record/byte_sink.h"

namespace lmc::test {

class FullDiskSink final : public devices::ByteSink {
 public:
  FullDiskSink(std::unique_ptr<devices::ByteSink> inner, size_t limit) : inner_(std::move(inner)), left_(limit) {}
  bool write(std::string_view data) override {
    if (data.size() > left_) {
      inner_->write(data.substr(0, left_));
      left_ = 0;
      error_ = "write: No space left on device";
      return false;
    }
    left_ -= data.size();
    return inner_->write(data);
  }
  bool sync() override { return inner_->sync(); }
  bool close() override { return inner_->close(); }
  std::string error() const override { return error_; }
  std::uint64_t bytes_written() const override { return inner_->bytes_written(); }

 private:
  std::unique_ptr<devices::ByteSink> inner_;
  size_t left_;
  std::string error_;
};

}  // namespace lmc::test
