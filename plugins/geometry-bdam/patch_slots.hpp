#pragma once
#include <cstdint>
#include <list>
#include <map>
#include <optional>
#include <tuple>

#include "cube_bintree.hpp"

namespace strata::bdam {

// Which patch each slot of geometry.bdam's GPU buffers holds, least recently drawn first out [Cignoni et al. 2003,
// §4.4: "an LRU-managed cache keeps the most recent ... patches directly in graphics memory"]. The roots, which every
// frame's refinement starts from, are never evicted; nor is a patch drawn or taken in the frame under way.
class PatchSlots {
 public:
  explicit PatchSlots(std::size_t capacity);

  std::size_t capacity() const { return capacity_; }
  std::size_t used() const { return slots_.size(); }
  std::optional<std::size_t> slotOf(const BintreeNode& node) const;
  // Marks a held patch drawn in `frame`.
  void touch(const BintreeNode& node, std::uint64_t frame);
  // A slot for `node` in `frame`: a free one, or the least recently drawn patch's (not a root's, nor one of
  // `frame`'s), which is evicted. Empty when every slot is in use this frame.
  std::optional<std::size_t> take(const BintreeNode& node, std::uint64_t frame);
  std::uint64_t evicted() const { return evicted_; }

 private:
  using Key = std::tuple<int, int, std::uint64_t>;
  static Key keyOf(const BintreeNode& node) { return {node.root, node.level, node.path}; }
  struct Held {
    std::size_t slot;
    std::uint64_t frame;
    std::list<Key>::iterator age;
  };

  std::size_t capacity_;
  std::map<Key, Held> slots_;
  std::list<Key> byAge_;  // least recently drawn first
  std::uint64_t evicted_ = 0;
};

}  // namespace strata::bdam
