#pragma once
#include <spawn.h>

namespace strata::cli {

// From here on, SIGINT, SIGTERM and SIGHUP (those not ignored when strata started) are taken by one thread of
// their own, which removes every scratch folder of unfinished outputs (strata/host/output_file.hpp) and then ends
// the process as the signal would have: an interrupted command leaves either its finished files or nothing.
// Call first in main, before any thread starts, so that every thread leaves these signals to that one.
void removeUnfinishedOutputsOnSignal();

// The signal mask strata's own threads run with has these signals blocked; a program strata runs (ffmpeg)
// must start with none blocked, so that Ctrl-C reaches it too.
void unblockSignalsInChild(posix_spawnattr_t& attributes);

}  // namespace strata::cli
