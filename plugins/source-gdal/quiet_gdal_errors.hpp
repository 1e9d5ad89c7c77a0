#pragma once
#include <cpl_error.h>

namespace strata::gdal {

// Silences GDAL's own printing while it lives, where Strata reports the failure itself (once, naming the
// file) or where a failure only means "not known". Handlers are per thread, so this quiets only the thread
// it runs on.
struct QuietGdalErrors {
  QuietGdalErrors() { CPLPushErrorHandler(CPLQuietErrorHandler); }
  ~QuietGdalErrors() { CPLPopErrorHandler(); }
  QuietGdalErrors(const QuietGdalErrors&) = delete;
  QuietGdalErrors& operator=(const QuietGdalErrors&) = delete;
};

}  // namespace strata::gdal
