#include "interrupt.hpp"

#include <unistd.h>

#include <csignal>

namespace {

volatile std::sig_atomic_t deferred = 0;  // a DeferredInterrupt is alive
volatile std::sig_atomic_t pending = 0;   // a deferred Ctrl-C waits for check_interrupt()

// Async-signal-safe: write(2) and _exit(2) only. The rows already flushed stay where they went.
extern "C" void on_interrupt(int /*signal*/) {
  if (deferred != 0 && pending == 0) {
    pending = 1;
    return;
  }
  static const char kept[] = "bounce: interrupted (SIGINT): the output written so far is kept\n";
  static const char unfinished[] =
      "bounce: interrupted (SIGINT) twice: the JSON document was left unfinished (a curve's prints nothing before "
      "its end)\n";
  const bool held = deferred != 0;
  [[maybe_unused]] const auto written =
      held ? ::write(STDERR_FILENO, unfinished, sizeof unfinished - 1) : ::write(STDERR_FILENO, kept, sizeof kept - 1);
  ::_exit(130);
}

}  // namespace

namespace bounce::cli {

void install_interrupt_handler() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGINT, &action, nullptr);
}

DeferredInterrupt::DeferredInterrupt() {
  pending = 0;
  deferred = 1;
}

DeferredInterrupt::~DeferredInterrupt() { deferred = 0; }

void check_interrupt() {
  if (pending != 0) throw Interrupted{};
}

}  // namespace bounce::cli
