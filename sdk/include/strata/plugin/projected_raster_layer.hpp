#pragma once
#include <array>
#include <memory>
#include <optional>
#include <strata/export.hpp>
#include <string>

#include <glm/glm.hpp>

#include <strata/plugin/layer.hpp>
#include <strata/plugin/layer_capabilities.hpp>
#include <strata/plugin/raster_georeference.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class BlockCaps;
class BlockRanges;
class ShaderProgram;

// What every raster sampled through a projection shares, whether its texels sit in one texture
// (RasterLayer) or in the page cache (PagedRasterLayer): per sample the projection's GLSL maps
// longitude/latitude to map coordinates, the geotransform maps those to texture coordinates, and a
// footprint step through the projection picks the level of detail (docs/architecture.md, "Projections").
class ProjectedRasterLayer : public Layer, public TexelledLayer, public ProjectedLayer, public RegionalValueLayer {
 public:
  ProjectedRasterLayer(std::string nodeId, LayerKind kind);

  // One-channel kinds: the value a shader sees is raw x scale + offset (e.g. int16 counts to metres).
  void setValueTransform(double scale, double offset);
  // One-channel kinds: the least and greatest raw values, where the source knows them exactly.
  void setRawRange(ValueRange raw) { rawRange_ = raw; }
  std::optional<ValueRange> valueRange() const override;
  // One-channel kinds: the raw ranges of the raster's blocks, where the source counted them (before place()),
  // which valuesWithin() bounds regions by; without them it knows none.
  void setBlockRanges(std::shared_ptr<const BlockRanges> blocks) { blockRanges_ = std::move(blocks); }
  std::optional<ValueRange> valuesWithin(const SphericalCap& cap) const override;

  LayerKind kind() const override { return kind_; }
  std::string samplingFunction() const override { return prefix_; }
  std::string texelStepsFunction() const override { return prefix_ + "_texelSteps"; }
  std::string edgeDistanceFunction() const override { return prefix_ + "_edgeDistance"; }
  ProjectionAspect aspect() const override;
  // Follows the frame's reference (View::reference, the point below the eye; rad): near it the layer is
  // sampled from each point's offset to the reference (SurfacePoint::fromReference), through the raster's
  // texture coordinates about the reference computed in double on the CPU, so that a centimetre texel is
  // addressed exactly anywhere on the body; farther away, through absolute longitude and latitude as
  // before. A projection affine in longitude and latitude (Projection::affineInLonLat) is sampled from the
  // offsets everywhere, exactly. Nodes call it each frame, from prepare(); a layer never told samples
  // absolutely everywhere.
  void setReference(glm::dvec2 referenceLonlat);

 protected:
  // Fixes where the raster of width x height texels lies; on the GL thread, before glsl() is asked for.
  void place(RasterGeoreference georeference, int width, int height);
  // The layer's GLSL: the projection's, then `declarations` (the layer's textures and uniforms), then
  // the sampling function. It evaluates `filtered`, a GLSL expression of vec2 uv (texture coordinates),
  // stepX, stepY (their change to the next sample), bool repeatX, vec3 at (uv and whether the projection is
  // defined there) and SurfacePoint p, giving the filtered texel: value x coverage and coverage (.rgb and .a
  // for colour kinds, .r and .g for the others), which <prefix>_value(vec4) turns into what the sampling
  // function returns. <prefix>_texel(at, p) gives the point's level-0 texel as a TexelAddress
  // (strata/texel_address.glsl), exact near the reference however wide the raster. Where `filtered` gives the
  // value's slopes per level-0 texel in .b and .a (a value page's), `sloped` adds for one-channel kinds
  // vec4 <prefix>_sloped(SurfacePoint p), the value with its slopes along the ground (SlopedLayer).
  std::string samplingGlsl(const std::string& declarations, const std::string& filtered, bool sloped = false) const;
  // Sets the uniforms samplingGlsl() declares.
  void bindSampling(ShaderProgram& program) const;
  const std::string& prefix() const { return prefix_; }
  // Raw values, least and greatest, as the layer returns them (after scale and offset).
  ValueRange transformed(double rawLeast, double rawGreatest) const;
  // Bounds regions by `caps` (which valuesWithin() asks), where the source knows its values otherwise than
  // by BlockRanges; after place().
  void setBlockCaps(std::shared_ptr<const BlockCaps> caps) { blockCaps_ = std::move(caps); }
  // Whether the raster is a HEALPix pyramid's whole strip of faces (strata/plugin/healpix_pyramid.hpp), not a
  // window of one face.
  bool onHealpixFaces() const;
  bool repeatX() const { return repeatX_; }
  // Heights, luminance, masks and scalars: a value and its coverage, not colour.
  bool oneChannel() const;

 private:
  std::string texelGlsl() const;
  std::string filteredAt() const;
  std::string slopedGlsl(const std::string& filtered) const;
  std::string absoluteGlsl() const;
  std::string referenceGlsl() const;
  std::string relativeGlsl() const;
  std::string affineGlsl() const;
  // The raster's texture coordinates (u, v) at `lonlat`, in double; empty where the projection is undefined.
  std::optional<glm::dvec2> textureCoordinates(glm::dvec2 lonlat) const;
  void setReferenceTexel(glm::dvec2 uv);
  glm::dmat2 affineJacobian() const;
  void setAffineReference(glm::dvec2 referenceLonlat);

  std::string prefix_;  // GLSL identifier prefix unique to the node
  LayerKind kind_;
  double scale_ = 1.0;
  double offset_ = 0.0;
  std::optional<ValueRange> rawRange_;
  std::shared_ptr<const BlockRanges> blockRanges_;
  std::shared_ptr<const BlockCaps> blockCaps_;  // made by place() from blockRanges_
  RasterGeoreference georeference_;
  // Fixed by place():
  std::array<glm::vec4, 2> projection_{};  // Projection::glslParameters()
  glm::vec4 mapToTexture_{0.0f};           // u = x * .x + .y, v = y * .z + .w (GLSL map units)
  glm::ivec2 size_{0};                     // the raster's width and height
  bool repeatX_ = false;                   // the raster spans one period of a periodic projection
  bool affine_ = false;                    // Projection::affineInLonLat()
  // Set by setReference(): the reference they were fitted for (a still camera keeps its fit), and the
  // texture coordinates about it, as uniforms.
  std::optional<glm::dvec2> reference_;
  glm::vec2 referenceUv_{0.0f};
  glm::ivec2 referenceTexel_{0};             // the level-0 texel position there: whole texels
  glm::vec2 referenceFraction_{0.0f};        // and the fraction beyond them
  std::array<glm::vec4, 3> localTerms_{};    // the jacobian, then the second derivatives of u and of v
  float reach_ = 0.0f;                       // rad; 0: sampled absolutely
  bool tangent_ = false;                     // offsets in the tangent plane, else in longitude/latitude
  glm::vec2 referenceLatitude_{0.0f, 1.0f};  // sin and cos
  // Affine projections: the longitude of the map's centre less the reference's (rad, within half a turn); until
  // a reference is told, offsets are taken from longitude and latitude 0.
  float centreFromReference_ = 0.0f;
};

}  // namespace strata
STRATA_EXPORTS_END
