#include "core/common/error.h"

#include <utility>

namespace lmc {

std::string format_error(const ErrorLocation& where, const std::string& what) {
  std::string out = where.file.empty() ? std::string("<input>") : where.file;
  if (where.line > 0) out += ":" + std::to_string(where.line);
  if (where.column > 0) out += ":" + std::to_string(where.column);
  if (!where.json_path.empty()) out += ": at " + where.json_path;
  out += ": " + what;
  return out;
}

Error::Error(ErrorLocation where, const std::string& what)
    : std::runtime_error(format_error(where, what)), where_(std::move(where)) {}

}  // namespace lmc
