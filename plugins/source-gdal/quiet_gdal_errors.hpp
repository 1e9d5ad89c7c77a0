#pragma once
#include <optional>
#include <string>

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

// Silences GDAL as QuietGdalErrors does, and keeps the first warning or error it raised meanwhile: some
// drivers decode damaged data with only a warning (libjpeg fills a truncated JPEG with grey), which a
// reader that trusts only the return code would draw as if it were data.
class RecordedGdalErrors {
 public:
  RecordedGdalErrors() { CPLPushErrorHandlerEx(record, this); }
  ~RecordedGdalErrors() { CPLPopErrorHandler(); }
  RecordedGdalErrors(const RecordedGdalErrors&) = delete;
  RecordedGdalErrors& operator=(const RecordedGdalErrors&) = delete;

  const std::optional<std::string>& first() const { return first_; }

 private:
  static void CPL_STDCALL record(CPLErr level, CPLErrorNum, const char* message) {
    auto& self = *static_cast<RecordedGdalErrors*>(CPLGetErrorHandlerUserData());
    if (level >= CE_Warning && !self.first_) self.first_ = message ? message : "";
  }
  std::optional<std::string> first_;
};

}  // namespace strata::gdal
