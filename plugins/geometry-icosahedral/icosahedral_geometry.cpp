// geometry.icosahedral: the icosahedron subdivided uniformly and displaced by a height layer, rasterised
// into the deferred texturing buffer. The view-dependent patch tree of seed 000 chapter 3 replaces the
// uniform split in its own issue; the buffer and the eye-relative positions already follow it.
#include <memory>
#include <optional>

#include <strata/geometry.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>
#include <strata/layer.hpp>
#include <strata/plugin.hpp>

#include "icosphere_mesh.hpp"

namespace strata::icosahedral {
namespace {

// 20 x 4^9 = 5.2 million triangles (170 MB of vertices): beyond that a uniform split wastes the GPU on
// what the view cannot show; the view-dependent patch tree is the way to more detail.
constexpr int kMaxLevelPlusDepth = 9;

class IcosahedralGeometry : public Node, public SurfaceGeometry {
 public:
  explicit IcosahedralGeometry(const NodeSetup& setup)
      : height_(setup.input("height") ? setup.input("height")->layer() : nullptr),
        radius_(setup.body->radius),
        level_(int(setup.parameters.integer("level"))),
        depth_(int(setup.parameters.integer("depth"))) {
    if (level_ + depth_ > kMaxLevelPlusDepth)
      throw Error(setup.where,
                  "level " + std::to_string(level_) + " with depth " + std::to_string(depth_) + " makes " +
                      std::to_string(20LL << (2 * (level_ + depth_))) + " triangles, more than this generator draws",
                  "keep level + depth at most " + std::to_string(kMaxLevelPlusDepth));
  }

  ~IcosahedralGeometry() override {
    glDeleteBuffers(3, buffers_.data());
    glDeleteVertexArrays(1, &vertexArray_);
  }

  void open() override { mesh_ = buildIcosphereMesh(radius_, level_, depth_); }

  void createResources(GpuContext& gpu) override {
    program_ = ShaderProgram({{GL_VERTEX_SHADER, "geometry/icosahedral.vert",
                               gpu.shaders->expand("geometry/icosahedral.vert", heightSubstitutions())},
                              {GL_FRAGMENT_SHADER, "geometry/surface_buffer.frag",
                               gpu.shaders->expand("geometry/surface_buffer.frag")}});
    createBuffers();
  }

  void prepare(const FrameState& frame) override {
    centres_.resize(mesh_.patchCentres.size());
    for (std::size_t i = 0; i < centres_.size(); ++i)
      centres_[i] = glm::vec4(frame.view.toEye(mesh_.patchCentres[i]), 0.0f);  // double until here
  }

  void render(const FrameState& frame) override;

  SurfaceGeometry* geometry() override { return this; }
  const Framebuffer& gbuffer() const override { return gbuffer_; }

 private:
  std::map<std::string, std::string> heightSubstitutions() const {
    if (!height_) return {{"STRATA_PROGRAM_DEFINES", ""}, {"STRATA_HEIGHT_LAYER_GLSL", ""}};
    return {{"STRATA_PROGRAM_DEFINES",
             "#define STRATA_HAS_HEIGHT\n#define STRATA_HEIGHT_FUNCTION " + height_->samplingFunction()},
            {"STRATA_HEIGHT_LAYER_GLSL", height_->glsl()}};
  }
  void createBuffers();

  Layer* height_;
  double radius_;
  int level_;
  int depth_;
  IcosphereMesh mesh_;
  std::vector<glm::vec4> centres_;
  ShaderProgram program_;
  Framebuffer gbuffer_;
  std::array<GLuint, 3> buffers_{};  // vertices, indices, patch centres
  GLuint vertexArray_ = 0;
  GLsizei indexCount_ = 0;
};

void IcosahedralGeometry::createBuffers() {
  glCreateBuffers(3, buffers_.data());
  glNamedBufferStorage(buffers_[0], GLsizeiptr(mesh_.vertices.size() * sizeof(MeshVertex)), mesh_.vertices.data(), 0);
  glNamedBufferStorage(buffers_[1], GLsizeiptr(mesh_.indices.size() * sizeof(std::uint32_t)), mesh_.indices.data(), 0);
  glNamedBufferStorage(buffers_[2], GLsizeiptr(mesh_.patchCentres.size() * sizeof(glm::vec4)), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  glCreateVertexArrays(1, &vertexArray_);
  glVertexArrayVertexBuffer(vertexArray_, 0, buffers_[0], 0, sizeof(MeshVertex));
  glVertexArrayElementBuffer(vertexArray_, buffers_[1]);
  const GLuint offsets[] = {offsetof(MeshVertex, offsetFromCentre), offsetof(MeshVertex, sphereNormal),
                            offsetof(MeshVertex, lonlat)};
  const GLint sizes[] = {3, 3, 2};
  for (GLuint attribute = 0; attribute < 3; ++attribute) {
    glEnableVertexArrayAttrib(vertexArray_, attribute);
    glVertexArrayAttribFormat(vertexArray_, attribute, sizes[attribute], GL_FLOAT, GL_FALSE, offsets[attribute]);
    glVertexArrayAttribBinding(vertexArray_, attribute, 0);
  }
  indexCount_ = GLsizei(mesh_.indices.size());
  mesh_.vertices = {};  // the GPU holds them now; centres stay for every frame
  mesh_.indices = {};
}

void IcosahedralGeometry::render(const FrameState& frame) {
  if (gbuffer_.width() != frame.view.width || gbuffer_.height() != frame.view.height)
    gbuffer_ = Framebuffer(frame.view.width, frame.view.height, {GL_RGBA32F, GL_RGBA16F}, GL_DEPTH_COMPONENT32F);
  glNamedBufferSubData(buffers_[2], 0, GLsizeiptr(centres_.size() * sizeof(glm::vec4)), centres_.data());
  gbuffer_.bind();
  const float clearColour[4] = {0, 0, 0, 0}, farDepth = 0.0f;  // reversed depth: 0 is infinitely far
  glClearNamedFramebufferfv(gbuffer_.id(), GL_COLOR, 0, clearColour);
  glClearNamedFramebufferfv(gbuffer_.id(), GL_COLOR, 1, clearColour);
  glClearNamedFramebufferfv(gbuffer_.id(), GL_DEPTH, 0, &farDepth);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glEnable(GL_CULL_FACE);  // the far side of the body faces away: half the triangles need no fragments
  program_.use();
  program_.set("planetToEye", glm::mat3(frame.view.planetToEye));
  program_.set("projection", frame.view.projection);
  program_.set("verticesPerPatch", mesh_.verticesPerPatch);
  program_.set("vertexSpacing", float(mesh_.vertexSpacing));
  program_.set("radius", float(radius_));
  TextureUnits units;
  if (height_) height_->bind(program_, units);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers_[2]);
  glBindVertexArray(vertexArray_);
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
}

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.type = "geometry.icosahedral";
  type.category = NodeCategory::Geometry;
  type.summary = "The icosahedron subdivided uniformly and displaced by a height layer";
  type.inputs = {{.name = "height", .type = PortType::Layer, .kinds = {LayerKind::Height}, .optional = true,
                  .doc = "heights in metres above the body's radius; none: the bare sphere"}};
  type.output = PortType::Geometry;
  type.parameters = {
      {.name = "level", .type = ParameterType::Integer, .defaultValue = std::int64_t(2), .minimum = 0.0,
       .maximum = 6.0, .doc = "splits of the icosahedron into patches: 20 x 4^level patches (2: 320, ~16 deg each)"},
      {.name = "depth", .type = ParameterType::Integer, .defaultValue = std::int64_t(5), .minimum = 0.0,
       .maximum = 8.0, .doc = "subdivisions of each patch: 4^depth triangles (5 is seed 000's default)"},
  };
  type.create = [](const NodeSetup& setup) { return std::make_unique<IcosahedralGeometry>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::icosahedral

STRATA_PLUGIN("geometry-icosahedral", "0.1.0", strata::icosahedral::registerTypes)
