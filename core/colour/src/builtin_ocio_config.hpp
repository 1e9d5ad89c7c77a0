#pragma once
#include <string_view>

namespace strata {

// The text of ocio/strata.ocio, compiled in (core/CMakeLists.txt), so that Strata's own config needs no file.
extern const std::string_view kBuiltinOcioConfig;

}  // namespace strata
