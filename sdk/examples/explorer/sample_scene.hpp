#pragma once
#include <strata/host/pipeline_builder.hpp>

namespace explorer {

// The explorer's sample scene built in code: the pipeline mars_explorer.yaml writes as a file, node for
// node, so that the explorer runs with no file at all. The test checks that the two show the same planet.
strata::PipelineBuilder sampleScene();

}  // namespace explorer
