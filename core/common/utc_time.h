#pragma once
// Wall-clock instants for files a person reads (sidecars, session journals): ISO 8601 in UTC
// with milliseconds, "2026-11-22T01:23:45.678Z" (contract-figure: the format's example), so they
// sort as text and mean the same in every time zone.
#include <string>

namespace lmc {

std::string utc_now_iso8601();
// The same format's compact date-time for folder names: "20261122-012345".
std::string utc_now_compact();

}  // namespace lmc
