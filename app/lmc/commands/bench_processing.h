#pragma once
// `lmc bench --processing DIR`: a recorded subject processed as `lmc process` does, default method
// and both methods, timed.
#include <string>

namespace lmc::cli {

// Processes `input` (a session or trial folder) `runs` times with the default method and `runs`
// times with --compare-methods, into a scratch folder removed afterwards, and prints the median
// wall and CPU seconds of each (JSON keys in bench.cpp's header comment).
void run_processing_bench(const std::string& input, int runs, bool json);

}  // namespace lmc::cli
