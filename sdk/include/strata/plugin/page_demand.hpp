#pragma once
#include <strata/export.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// How much a layer's pages are wanted (composite.temporal_blend steps a series through its layers):
//   Shown       the pages the view needs are loaded, as for every layer by default;
//   Prefetched  they are loaded too, but after every shown layer's and only into room those leave;
//   Idle        none beyond its pinned coarsest level; what it had is evicted as others need the room.
enum class PageDemand { Shown, Prefetched, Idle };

}  // namespace strata
STRATA_EXPORTS_END
