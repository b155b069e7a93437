#include "app/lmc/sigint_flag.h"

#include <atomic>
#include <csignal>

namespace lmc::cli {
namespace {
std::atomic<bool> g_sigint_raised{false};
extern "C" void on_sigint(int) {
  g_sigint_raised = true;
}
}  // namespace

ScopedSigint::ScopedSigint() {
  g_sigint_raised = false;
  previous_ = std::signal(SIGINT, on_sigint);
}

ScopedSigint::~ScopedSigint() {
  std::signal(SIGINT, previous_);
}

bool sigint_raised() {
  return g_sigint_raised;
}
bool take_sigint() {
  return g_sigint_raised.exchange(false);
}
void clear_sigint() {
  g_sigint_raised = false;
}

}  // namespace lmc::cli
