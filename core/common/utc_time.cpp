#include "core/common/utc_time.h"

#include <chrono>
#include <cstdio>
#include <ctime>

namespace lmc {
namespace {

std::tm utc_now(int* ms) {
  const auto now = std::chrono::system_clock::now();
  const std::time_t secs = std::chrono::system_clock::to_time_t(now);
  *ms = static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000);
  std::tm utc{};
#ifdef _WIN32
  gmtime_s(&utc, &secs);  // thread-safe like gmtime_r; Microsoft's order: the result first
#else
  gmtime_r(&secs, &utc);
#endif
  return utc;
}

}  // namespace

std::string utc_now_iso8601() {
  int ms = 0;
  const std::tm utc = utc_now(&ms);
  char buf[96];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900, utc.tm_mon + 1, utc.tm_mday,
                utc.tm_hour, utc.tm_min, utc.tm_sec, ms);
  return buf;
}

std::string utc_now_compact() {
  int ms = 0;
  const std::tm utc = utc_now(&ms);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%04d%02d%02d-%02d%02d%02d", utc.tm_year + 1900, utc.tm_mon + 1, utc.tm_mday,
                utc.tm_hour, utc.tm_min, utc.tm_sec);
  return buf;
}

}  // namespace lmc
