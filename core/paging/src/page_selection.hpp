#pragma once
#include <vector>

#include <strata/body.hpp>
#include <strata/camera.hpp>
#include <strata/plugin/page_pyramid.hpp>
#include <strata/plugin/raster_georeference.hpp>

#include "page_loader.hpp"

namespace strata::paging {

// What the selection needs to know of a layer.
struct SelectableLayer {
  const PagePyramid* pyramid = nullptr;
  const RasterGeoreference* georeference = nullptr;
  bool wrapX = false;  // the raster spans one period: its east and west edges meet
};

// A page the view needs, with what orders it: coarser pages first (they stand in for the finer ones),
// then nearer ones.
struct WantedPage {
  LayerPage page;
  int depth = 0;           // levels below the layer's coarsest
  double distance = 0.0;   // m from the eye to the nearest sampled point of the page
  bool onlyAhead = false;  // wanted by the view ahead (PageCache::update), not by the view itself
};

// The pages each layer needs for `view`, chosen from their bounds as in [Kooima 2008, §4.3.2]: a page
// is wanted when some of it lies above the horizon and inside the view frustum, and its children are
// wanted too while its texels, at its nearest point, look larger than a pixel. Every level from the
// coarsest down is listed, so proxies exist for everything wanted. Sorted most wanted first. Distances are
// measured to the sphere of the ground level of `terrain` nearest the eye (groundLevelNear), so that a view
// just above a plateau gets the fine pages it needs.
std::vector<WantedPage> selectPages(const std::vector<SelectableLayer>& layers, const Body& body, const View& view,
                                    const HeightRange& terrain);

}  // namespace strata::paging
