#pragma once
// What libstrata_core exports: libstrata_core is built with hidden visibility (core/CMakeLists.txt), and
// each SDK header declares its namespace between these two marks, so that exactly what the SDK's headers
// declare is exported and everything else of the library (its internals, and its instantiations of the
// templates of yaml-cpp, GDAL, PROJ and OpenColorIO) stays inside it. (The standard library's templates,
// instantiated weakly in every module that uses them, keep the default visibility libstdc++ gives them.)
// Plugins built with strata_add_plugin hide all but their entry point the same way.
#define STRATA_EXPORTS_BEGIN _Pragma("GCC visibility push(default)")
#define STRATA_EXPORTS_END _Pragma("GCC visibility pop")
