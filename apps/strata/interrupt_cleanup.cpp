#include "interrupt_cleanup.hpp"

#include <pthread.h>

#include <csignal>
#include <thread>

#include <strata/host/output_file.hpp>

namespace strata::cli {
namespace {

// The signals that end a command early: Ctrl-C, kill, and a closed terminal.
sigset_t endingSignals() {
  sigset_t signals;
  sigemptyset(&signals);
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction current {};
    // One strata was started with ignored (nohup, a shell's background job) stays ignored.
    if (sigaction(signal, nullptr, &current) == 0 && current.sa_handler != SIG_IGN) sigaddset(&signals, signal);
  }
  return signals;
}

[[noreturn]] void watch(sigset_t signals) {
  int signal = 0;
  while (sigwait(&signals, &signal) != 0) {
  }
  removeScratchDirectories();
  // Ended by the signal itself, so that the shell and any parent see what ended it.
  std::signal(signal, SIG_DFL);
  sigset_t only;
  sigemptyset(&only);
  sigaddset(&only, signal);
  pthread_sigmask(SIG_UNBLOCK, &only, nullptr);
  raise(signal);
  std::_Exit(128 + signal);  // not reached: the default action of each of these signals ends the process
}

}  // namespace

void removeUnfinishedOutputsOnSignal() {
  const sigset_t signals = endingSignals();
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::thread(watch, signals).detach();
}

void unblockSignalsInChild(posix_spawnattr_t& attributes) {
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
}

}  // namespace strata::cli
