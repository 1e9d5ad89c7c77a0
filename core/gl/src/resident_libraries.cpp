#include <strata/gl/context.hpp>

#include <dlfcn.h>
#include <link.h>

#include <cstddef>

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define STRATA_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define STRATA_SANITIZED 1
#endif

namespace strata {

#if defined(STRATA_SANITIZED)
void keepLoadedLibrariesResident() {
  dl_iterate_phdr(
      [](dl_phdr_info* library, std::size_t, void*) {
        // RTLD_NOLOAD: only a library loaded already, whose count this raises, never to be unloaded.
        if (library->dlpi_name && *library->dlpi_name)
          dlopen(library->dlpi_name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
      },
      nullptr);
}
#else
void keepLoadedLibrariesResident() {}
#endif

}  // namespace strata
