#pragma once
// One error type for every bad input the engine meets. It always names where the problem is
// (file, line, column or JSON path) so a lab member can open the file and fix it.
#include <stdexcept>
#include <string>
#include <utility>

namespace lmc {

struct ErrorLocation {
  ErrorLocation() = default;
  explicit ErrorLocation(std::string file_, long line_ = 0, long column_ = 0, std::string json_path_ = {})
      : file(std::move(file_)), line(line_), column(column_), json_path(std::move(json_path_)) {}

  std::string file;       // path or a name such as "<stdin>"
  long line = 0;          // 1-based; 0 when unknown
  long column = 0;        // 1-based field/column; 0 when unknown
  std::string json_path;  // e.g. "/devices/2/pose/rx"; empty when not JSON
};

class Error : public std::runtime_error {
 public:
  Error(ErrorLocation where, const std::string& what);
  explicit Error(const std::string& what) : std::runtime_error(what) {}

  const ErrorLocation& where() const { return where_; }

 private:
  ErrorLocation where_;
};

// "file:line:column: message" (parts that are unknown are left out).
std::string format_error(const ErrorLocation& where, const std::string& what);

}  // namespace lmc
