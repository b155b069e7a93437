#pragma once
// Every reader of outside input, as one function each that takes the bytes a file or a datagram
// could hold. The libFuzzer programs (fuzz_main.cpp, built by scripts/fuzz with clang) and the
// corpus replay test of the ordinary test suite (tests/devices/fuzz_corpus_replay_test.cpp) call
// the same functions, so an input the fuzzer once broke is replayed by every `scripts/test`.
//
// The contract each target checks: bad input ends in lmc::Error (a message naming the source) or a
// warning; anything else — another exception type (a library's own text, std::bad_alloc), a
// crash, a sanitizer report, a hang — is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace lmc::fuzz {

struct Target {
  const char* name;                     // also the folder of its corpus: tests/fuzz/corpus/<name>/
  const char* what;                     // the reader it drives, for the README table and messages
  void (*run)(std::string_view bytes);  // throws only lmc::Error for bad input
};

const std::vector<Target>& targets();
const Target* find_target(std::string_view name);

// Runs one input: lmc::Error is the expected outcome of bad input and is swallowed (false); any
// other exception escapes (libFuzzer reports it as a crash, the replay test as a failure). True:
// the reader took the input.
bool run_one(const Target& target, std::string_view bytes);

}  // namespace lmc::fuzz
