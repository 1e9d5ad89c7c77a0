#pragma once

namespace strata {

// What a geometry's deferred buffer (strata/gl/surface_buffer.hpp) holds of the shading normal: nothing where it is
// the sphere's (the bare body, whose readers compute it from the longitude and latitude), or the displaced
// surface's own. Its own header, free of GL, so that HeightInput can name it.
enum class ShadingNormal { OfTheSphere, Stored };

}  // namespace strata
