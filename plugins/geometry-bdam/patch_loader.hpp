#pragma once
#include <cstdint>
#include <set>
#include <tuple>
#include <vector>

#include "bdam_data.hpp"
#include "patch_slots.hpp"

namespace strata::bdam {

// A patch read and decoded on the CPU, for its slot on the GPU.
struct PendingPatch {
  std::size_t slot = 0;
  DisplacedPatch patch;
};

// Where geometry.bdam's patches come from: read from the mapped face files and decoded on a worker, each given a slot
// (PatchSlots) and held until the GL thread uploads it. A patch that cannot be read is reported once and never asked
// for again; the refinement then keeps the coarser patch above it.
class PatchLoader {
 public:
  PatchLoader(const BdamData& data, std::size_t slots);

  // Whether a node's patch is on the GPU or on its way there.
  bool resident(const BintreeNode& node) const;
  // Reads and decodes `nodes` (those not resident, nor failed), at most `budget`, into slots for `frame`.
  void load(const std::vector<BintreeNode>& nodes, std::size_t budget, std::uint64_t frame);
  // The slot of a resident node's patch, marked drawn in `frame`, and its index count.
  std::pair<std::size_t, std::uint32_t> drawn(const BintreeNode& node, std::uint64_t frame);
  // The patches read since the last call, for the GL thread.
  std::vector<PendingPatch> takePending();
  // Asks the kernel to read `nodes`' patches ahead that are not resident (FaceFile::prefetch).
  void prefetch(const std::vector<BintreeNode>& nodes) const;

  std::uint64_t loaded() const { return loaded_; }
  std::uint64_t evicted() const { return slots_.evicted(); }
  std::uint64_t vertices(const BintreeNode& node) const;

 private:
  using Key = std::tuple<int, int, std::uint64_t>;
  const BdamData& data_;
  PatchSlots slots_;
  std::vector<std::uint32_t> indices_, vertices_;  // per slot, of the patch it holds
  std::vector<PendingPatch> pending_;
  std::set<Key> failed_;
  std::uint64_t loaded_ = 0;
};

}  // namespace strata::bdam
