#include "core/common/safe_name.h"

#include "core/common/error.h"

namespace lmc {

std::string safe_name_problem(const std::string& name, const std::string& what) {
  if (name.empty()) return what + " is empty";
  if (name.size() > kMaxSafeNameLength)
    return what + " is longer than " + std::to_string(kMaxSafeNameLength) + " characters";
  if (name.front() == '-') return what + " must not start with '-'";
  for (size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    if (!ok)
      return what + " has a character other than letters, digits, '_' or '-' at position " + std::to_string(i + 1);
  }
  return {};
}

void require_safe_name(const std::string& name, const std::string& what) {
  if (auto why = safe_name_problem(name, what); !why.empty()) throw Error(why);
}

}  // namespace lmc
