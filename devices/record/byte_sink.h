#pragma once
// Where the recorder's bytes go. The file implementation (core/platform/durable_file.h) surfaces a full disk or an
// I/O error as the system's text; tests inject a sink that fails after N bytes.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace lmc::devices {

class ByteSink {
 public:
  virtual ~ByteSink() = default;
  // All of `data` or false (then error() says why; some bytes may have been written).
  virtual bool write(std::string_view data) = 0;
  virtual bool sync() = 0;  // to stable storage
  virtual bool close() = 0;
  virtual std::string error() const = 0;
  // Bytes that reached the file so far, including those of a write that then failed; lets the
  // recorder count exactly the complete rows a cut file holds. 0 when the sink cannot tell.
  virtual std::uint64_t bytes_written() const { return 0; }
  // Why bytes written now would not be kept, though writes still succeed: the file was deleted
  // (its folder removed) while open. Empty while all is well or when the sink cannot tell.
  virtual std::string lost() const { return {}; }
};

// Creates (truncates) the file. Throws lmc::Error naming the path when it cannot be opened.
std::unique_ptr<ByteSink> open_file_sink(const std::filesystem::path& path);

}  // namespace lmc::devices
