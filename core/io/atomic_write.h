#pragma once
// Session state is never half-written: write to a temporary file beside the target, flush and
// fsync it, then rename over the target (rename is atomic on one filesystem).
#include <filesystem>
#include <string_view>

namespace lmc {

// Throws lmc::Error naming the path when any step fails; the old file is then untouched.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace lmc
