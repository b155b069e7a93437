#include "core/io/atomic_write.h"

#include <random>
#include <string>
#include <system_error>

#include "core/common/error.h"
#include "core/platform/durable_file.h"

namespace lmc {

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  std::random_device rd;
  const auto tmp = path.parent_path() / ("." + path.filename().string() + ".tmp" + std::to_string(rd() % 1000000));
  auto discard_tmp = [&] {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
  };
  platform::DurableFile file;
  try {
    file = platform::DurableFile(tmp, platform::OpenMode::truncate);
  } catch (const Error& e) {
    throw Error(ErrorLocation{path.string()}, "cannot create temporary file " + tmp.string() + ": " + e.what());
  }
  if (!file.write(contents)) {
    const std::string why = file.last_error();
    file.close();
    discard_tmp();
    throw Error(ErrorLocation{path.string()}, "write failed: " + why);
  }
  if (!file.sync() || !file.close()) {
    const std::string why = file.last_error();
    file.close();
    discard_tmp();
    throw Error(ErrorLocation{path.string()}, "sync failed: " + why);
  }
  try {
    platform::replace_file(tmp, path);
  } catch (...) {
    discard_tmp();
    throw;
  }
}

}  // namespace lmc
