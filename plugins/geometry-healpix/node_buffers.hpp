#pragma once
#include <strata/gl.hpp>

#include "node_batch.hpp"

namespace strata::healpix {

// The GPU side of the nodes: the stitched proxy grid's indices (uploaded once), and each frame's nodes,
// their outline vertices and their draws. Each draw is one instance whose baseInstance names its node: an instanced
// vertex attribute (divisor 1) reads it from a buffer of 0, 1, 2, ..., which GL 4.5 offsets by baseInstance (gl_DrawID
// needs 4.6).
class NodeBuffers {
 public:
  explicit NodeBuffers(int cells);
  ~NodeBuffers();
  NodeBuffers(const NodeBuffers&) = delete;
  NodeBuffers& operator=(const NodeBuffers&) = delete;

  // Uploads the frame's nodes and draws, growing the buffers when there are more nodes than before.
  void upload(const NodeBatch& batch);
  // Draws the uploaded nodes with the program in use (healpix_surface.vert).
  void draw() const;

 private:
  enum Buffer { kIndices, kNodes, kDraws, kNodeNumbers, kBoundary, kBufferCount };
  void reserve(std::size_t nodes);

  int cells_;

  std::size_t capacity_ = 0;
  std::size_t nodes_ = 0;
  GLuint buffers_[kBufferCount] = {};
  GLuint vertexArray_ = 0;
};

}  // namespace strata::healpix
