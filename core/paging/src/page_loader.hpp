#pragma once
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <strata/plugin/page_pyramid.hpp>

namespace strata::paging {

// A page of one attached layer.
struct LayerPage {
  int layer = 0;
  PageKey key;
  auto operator<=>(const LayerPage&) const = default;
};

// A page read, or why it could not be.
struct LoadedPage {
  LayerPage page;
  std::vector<std::byte> texels;  // kPageBytes; empty when `error` says why
  std::string error;
};

// Reads pages on worker threads, so that disk and decompression never hold up a frame ([Kooima 2008, §4.3.2]
// loads asynchronously). The frame replaces the queue with what it wants now, most wanted first; pages read
// but not yet taken are capped, which bounds the CPU memory they hold.
class PageLoader {
 public:
  using Reader = std::function<void(const LayerPage&, std::vector<std::byte>&)>;

  PageLoader(int threads, std::size_t maxHeld, Reader reader);
  ~PageLoader();
  PageLoader(const PageLoader&) = delete;
  PageLoader& operator=(const PageLoader&) = delete;

  // Drops queued pages that were not started and queues `wanted` in order, skipping pages being read
  // or read and not taken.
  void replaceQueue(const std::vector<LayerPage>& wanted);
  // Up to `count` read pages, oldest first.
  std::vector<LoadedPage> take(std::size_t count);
  // Queued, being read, or read and not taken.
  std::size_t outstanding() const;
  // Blocks until a read page waits to be taken or nothing is outstanding.
  void waitForAny() const;
  // The most pages held in memory at once, read or being read.
  std::size_t peakHeld() const;

 private:
  void work(const std::stop_token& stop);

  Reader reader_;
  std::size_t maxHeld_;
  mutable std::mutex mutex_;
  mutable std::condition_variable_any changed_;
  std::vector<LayerPage> queue_;  // most wanted first
  std::set<LayerPage> reading_;
  std::vector<LoadedPage> finished_;
  std::size_t peakHeld_ = 0;
  std::vector<std::jthread> threads_;  // last: joined before the state they use goes
};

}  // namespace strata::paging
