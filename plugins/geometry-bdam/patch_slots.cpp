#include "patch_slots.hpp"

#include <stdexcept>

namespace strata::bdam {

PatchSlots::PatchSlots(std::size_t capacity) : capacity_(capacity) {
  if (capacity < std::size_t(kBintreeRoots)) throw std::invalid_argument("fewer patch slots than roots");
}

std::optional<std::size_t> PatchSlots::slotOf(const BintreeNode& node) const {
  const auto found = slots_.find(keyOf(node));
  if (found == slots_.end()) return std::nullopt;
  return found->second.slot;
}

void PatchSlots::touch(const BintreeNode& node, std::uint64_t frame) {
  Held& held = slots_.at(keyOf(node));
  held.frame = frame;
  byAge_.splice(byAge_.end(), byAge_, held.age);
}

std::optional<std::size_t> PatchSlots::take(const BintreeNode& node, std::uint64_t frame) {
  std::size_t slot = slots_.size();
  if (slots_.size() == capacity_) {
    auto oldest = byAge_.begin();
    while (oldest != byAge_.end() && (std::get<1>(*oldest) == 0 || slots_.at(*oldest).frame == frame)) ++oldest;
    if (oldest == byAge_.end()) return std::nullopt;
    slot = slots_.at(*oldest).slot;
    slots_.erase(*oldest);
    byAge_.erase(oldest);
    ++evicted_;
  }
  byAge_.push_back(keyOf(node));
  slots_[keyOf(node)] = {slot, frame, std::prev(byAge_.end())};
  return slot;
}

}  // namespace strata::bdam
