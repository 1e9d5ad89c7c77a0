#include "page_loader.hpp"

#include <algorithm>
#include <exception>

namespace strata::paging {

PageLoader::PageLoader(int threads, std::size_t maxHeld, Reader reader)
    : reader_(std::move(reader)), maxHeld_(std::max<std::size_t>(1, maxHeld)) {
  for (int i = 0; i < threads; ++i) threads_.emplace_back([this](const std::stop_token& stop) { work(stop); });
}

PageLoader::~PageLoader() {
  for (auto& thread : threads_) thread.request_stop();
  changed_.notify_all();
}

void PageLoader::replaceQueue(const std::vector<LayerPage>& wanted) {
  {
    std::scoped_lock lock(mutex_);
    queue_.clear();
    for (const LayerPage& page : wanted) {
      const bool finished = std::ranges::any_of(finished_, [&](const LoadedPage& done) { return done.page == page; });
      if (!reading_.contains(page) && !finished) queue_.push_back(page);
    }
  }
  changed_.notify_all();
}

std::vector<LoadedPage> PageLoader::take(std::size_t count) {
  std::vector<LoadedPage> taken;
  {
    std::scoped_lock lock(mutex_);
    const std::size_t n = std::min(count, finished_.size());
    std::move(finished_.begin(), finished_.begin() + std::ptrdiff_t(n), std::back_inserter(taken));
    finished_.erase(finished_.begin(), finished_.begin() + std::ptrdiff_t(n));
  }
  changed_.notify_all();  // room for readers waiting on maxHeld
  return taken;
}

std::size_t PageLoader::outstanding() const {
  std::scoped_lock lock(mutex_);
  return queue_.size() + reading_.size() + finished_.size();
}

void PageLoader::waitForAny() const {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return !finished_.empty() || (queue_.empty() && reading_.empty()); });
}

std::size_t PageLoader::peakHeld() const {
  std::scoped_lock lock(mutex_);
  return peakHeld_;
}

void PageLoader::work(const std::stop_token& stop) {
  std::unique_lock lock(mutex_);
  while (true) {
    changed_.wait(lock, stop, [&] { return !queue_.empty() && reading_.size() + finished_.size() < maxHeld_; });
    if (stop.stop_requested()) return;
    LoadedPage loaded{queue_.front(), {}, {}};
    queue_.erase(queue_.begin());
    reading_.insert(loaded.page);
    peakHeld_ = std::max(peakHeld_, reading_.size() + finished_.size());
    lock.unlock();
    try {
      reader_(loaded.page, loaded.texels);
    } catch (const std::exception& error) {
      loaded.texels = {};
      loaded.error = error.what();
    }
    lock.lock();
    reading_.erase(loaded.page);
    finished_.push_back(std::move(loaded));
    changed_.notify_all();
  }
}

}  // namespace strata::paging
