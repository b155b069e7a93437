#pragma once
// Ctrl-C for the commands that record: a signal handler may only set a flag, so the handler is
// installed for the lifetime of one ScopedSigint and the command polls the flag between frames,
// turning it into its own stop request. The previous handler comes back when the scope ends.
namespace lmc::cli {

class ScopedSigint {
 public:
  ScopedSigint();  // clears the flag and installs the handler
  ~ScopedSigint();
  ScopedSigint(const ScopedSigint&) = delete;
  ScopedSigint& operator=(const ScopedSigint&) = delete;

 private:
  void (*previous_)(int) = nullptr;
};

bool sigint_raised();  // Ctrl-C arrived since the handler was installed or the flag was cleared
bool take_sigint();    // sigint_raised(), and clears the flag
void clear_sigint();

}  // namespace lmc::cli
