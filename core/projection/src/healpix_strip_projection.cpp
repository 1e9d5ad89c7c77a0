// The projection of a HEALPix pyramid's strip of faces (strata/plugin/healpix_pyramid.hpp): the planar HEALPix
// projection (Calabretta & Roukema 2007), whose faces are squares turned by 45 degrees, then each face turned
// back into its column of the strip.
#include <strata/plugin/healpix.hpp>
#include <strata/plugin/healpix_pyramid.hpp>

#include <algorithm>
#include <cmath>

namespace strata::healpix {
namespace {

class StripProjection final : public Projection {
 public:
  explicit StripProjection(std::shared_ptr<const Projection> plane)
      : plane_(std::move(plane)), radius_(plane_->glslMapScale()) {}

  std::string type() const override { return kStripProjectionType; }
  // The plane's: the strip is not a CRS PROJ knows, but its faces are the plane's.
  std::string projString() const override { return plane_->projString(); }

  std::optional<glm::dvec2> forward(glm::dvec2 lonlat) const override {
    const std::optional<glm::dvec2> xy = plane_->forward(lonlat);
    if (!xy) return std::nullopt;
    const std::optional<FacePoint> point = faceOfPlane(*xy / radius_);
    if (!point) return std::nullopt;
    return glm::dvec2(point->face + point->x, point->y);
  }

  std::optional<glm::dvec2> inverse(glm::dvec2 xy) const override {
    if (!(xy.x >= 0.0 && xy.x <= 12.0 && xy.y >= 0.0 && xy.y <= 1.0)) return std::nullopt;
    const int face = std::min(int(xy.x), 11);
    return plane_->inverse(planeOf(FacePoint{face, xy.x - face, xy.y}) * radius_);
  }

  std::string glslInclude() const override { return "strata/projection/healpix_faces.glsl"; }
  std::string glslFunction() const override { return "healpixFaces"; }
  std::array<glm::dvec4, 2> glslParameters() const override { return plane_->glslParameters(); }
  double glslMapScale() const override { return 1.0; }  // strip coordinates run 0 to 12 and 0 to 1

 private:
  std::shared_ptr<const Projection> plane_;
  double radius_;  // the plane's metres per unit of the unit sphere's plane
};

}  // namespace

std::unique_ptr<Projection> stripProjection(std::shared_ptr<const Projection> plane) {
  return std::make_unique<StripProjection>(std::move(plane));
}

}  // namespace strata::healpix
