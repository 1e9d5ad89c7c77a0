#pragma once
#include <cstdio>
#include <functional>
#include <string>

#include <benchmark/benchmark.h>

#include <strata/gl.hpp>
#include <strata/gl/context.hpp>

namespace strata::bench {

// The main of a benchmark that renders: one headless context for every configuration (each loads its own
// engine on it), the GPU's name printed and kept in the output's context as `gpu`, then Google Benchmark
// runs what `registerAll` registers.
inline int runHeadless(int argc, char** argv, const std::function<void()>& registerAll) {
  const auto context = createHeadlessContext(false);
  const std::string renderer = currentGlInfo().renderer;
  benchmark::AddCustomContext("gpu", renderer);
  std::printf("%s; %s\n", context->description().c_str(), renderer.c_str());
  registerAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace strata::bench
