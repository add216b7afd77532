#pragma once
// Ctrl-C (SIGINT), docs/cli.md "Memory, streaming and Ctrl-C". By default the process ends at
// once (exit 130), keeping the rows already written. While a JSON document is being built (a
// curve's points wait in a spool for its boundaries; a list is open) the interrupt is deferred
// to the next point, so that the command closes the document with what it has: valid JSON.

namespace bounce::cli {

/// Thrown by check_interrupt() where a deferred Ctrl-C arrived: the command ends its document.
struct Interrupted {};

/// Installs the handler (main() does; the in-process fuzz target does not).
void install_interrupt_handler();

/// While one is alive, Ctrl-C is deferred to check_interrupt(); a second Ctrl-C ends the
/// process at once, saying that the document was left unfinished.
class DeferredInterrupt {
 public:
  DeferredInterrupt();
  ~DeferredInterrupt();
  DeferredInterrupt(const DeferredInterrupt&) = delete;
  DeferredInterrupt& operator=(const DeferredInterrupt&) = delete;
};

/// Throws Interrupted when a deferred Ctrl-C is waiting.
void check_interrupt();

}  // namespace bounce::cli
