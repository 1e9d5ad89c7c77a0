#pragma once
#include <glm/glm.hpp>
#include <strata/export.hpp>
#include <string>

#include <strata/body.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// Where a view looks from, as a user says it: above a point of the surface, turned and tilted.
struct Camera {
  double lon = 0.0;         // deg, east positive: the point below the eye
  double lat = 0.0;         // deg, north positive
  double altitude = 2.0e7;  // m above the body's radius
  double heading = 0.0;     // deg clockwise from north: the direction the view faces
  double tilt = 0.0;        // deg: 0 looks straight down, 90 at the horizon
  double fov = 45.0;        // deg, vertical field of view
  // In a scene of several bodies (`bodies:`): the id of the body the eye is placed over; empty: the first.
  std::string body;

  bool operator==(const Camera&) const = default;
};

// A camera resolved for one frame. Planet-scale quantities stay in double; what the GPU gets is
// relative to the eye (docs/architecture.md, "Precision").
struct View {
  int width = 0;
  int height = 0;
  glm::dvec3 eye{0.0};          // planet-fixed position of the eye, m
  glm::dmat3 planetToEye{1.0};  // rotation from planet-fixed axes to eye axes (x right, y up, -z forward)
  glm::mat4 projection{1.0f};   // infinite far plane, reversed depth (1 at the near plane, 0 at infinity)
  double near = 1.0;            // m
  double verticalFov = 0.0;     // rad
  // Longitude and latitude (rad) of the point below the eye. The GPU gets longitudes and latitudes
  // measured from it, which float resolves finely near the eye (docs/architecture.md, "Precision").
  glm::dvec2 reference{0.0};

  // Eye-space position of a planet-fixed point, computed in double.
  glm::dvec3 toEye(const glm::dvec3& planetFixed) const { return planetToEye * (planetFixed - eye); }
  // The tangents of half the field of view across (x) and up (y): where the frame's edges lie at unit distance
  // ahead, in eye space. The rays through the frame's corners are (+-x, +-y, -1).
  glm::dvec2 halfFrameTangents() const;
  // Pixels per radian at the frame's centre: the focal length in pixels.
  double pixelsPerRadian() const { return 0.5 * double(height) / halfFrameTangents().y; }
};

// Resolves a camera over a body for a viewport of width x height pixels. `terrain`: the heights the drawn
// surfaces keep within, which place the near plane a thousandth of the way to the ground nearest the eye
// (groundLevelNear), so that a view 2 m above a plateau 3 km high does not clip the plateau.
View makeView(const Body& body, const Camera& camera, int width, int height, const HeightRange& terrain = {});

// The view `seen`, resolved over a body placed at `from` in a scene of several bodies (`bodies:`), as it sees the
// body placed at `to`: the same eye and axes in that body's planet-fixed axes, measured from the point below the
// eye on it, and the near plane fitted to its `terrain` as makeView fits it.
View viewOfBody(const View& seen, const BodyPlacement& from, const BodyPlacement& to, const Body& body,
                const HeightRange& terrain = {});

// The camera `frames` frames on: its eye moved on in a straight line as it moved from `before` to `now`, looking as
// `now` does [Cignoni et al. 2003, §4.4: "linear extrapolation of the camera position"]. The eye stays at least a
// tenth of `now`'s altitude above the body, so that a descent extrapolated into the ground still looks from above it.
Camera cameraAhead(const Body& body, const Camera& before, const Camera& now, double frames);

// Planet-fixed unit normal at geographic longitude and latitude (radians).
glm::dvec3 unitNormal(double lonRad, double latRad);

// (sin lon, cos lon, sin lat, cos lat) of a longitude and latitude (radians), computed in double: what
// strata/surface_buffer.glsl's sphereNormalFromReference takes for View::reference.
glm::vec4 sinesAndCosines(glm::dvec2 lonlat);

// The rotation from planet-fixed axes to the east-north-up frame at a longitude and latitude (radians): its
// rows are east, north and up. At View::reference it is the frame in which the point below the eye is
// (0, 0, 1) exactly, which the geometry generators place and measure points in (see
// shaders/strata/lonlat_from_reference.glsl).
glm::dmat3 planetToLocal(glm::dvec2 lonlat);

}  // namespace strata
STRATA_EXPORTS_END
