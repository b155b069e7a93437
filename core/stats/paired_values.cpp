#include "core/stats/paired_values.h"

#include <string>

#include "core/common/error.h"

namespace lmc {

PairedValues complete_pairs(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size())
    throw Error("paired statistics need series of equal length (got " + std::to_string(a.size()) + " and " +
                std::to_string(b.size()) + " values)");
  PairedValues out;
  out.a.reserve(a.size());
  out.b.reserve(b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (is_usable(a[i]) && is_usable(b[i])) {
      out.a.push_back(a[i]);
      out.b.push_back(b[i]);
    } else {
      ++out.n_skipped;
    }
  }
  return out;
}

}  // namespace lmc
