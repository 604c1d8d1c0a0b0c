#include "band_workers.hpp"

#include <algorithm>

namespace fieldlines::elsed {

BandWorkers::~BandWorkers() { stop_all(); }

void BandWorkers::stop_all() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
  threads_.clear();
  stopping_ = false;
}

void BandWorkers::resize(int count) {
  if (count == size()) return;
  stop_all();
  threads_.reserve(static_cast<std::size_t>(count));
  // Each starts from the current generation, so it neither replays the last run nor misses the
  // next one if that is posted before the thread first takes the lock.
  for (int i = 0; i < count; ++i) threads_.emplace_back([this, g = generation_] { work(g); });
}

void BandWorkers::work(std::uint64_t seen) {
  for (;;) {
    Erased fn = nullptr;
    void* context = nullptr;
    int bands = 0;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      fn = fn_;
      context = context_;
      bands = bands_;
    }
    claim_bands(seen, bands, fn, context);
  }
}

void BandWorkers::claim_bands(std::uint64_t generation, int bands, Erased fn, void* context) {
  for (;;) {
    std::uint64_t ticket = ticket_.load(std::memory_order_acquire);
    do {
      if (ticket >> 8 != generation || static_cast<int>(ticket & 0xFF) >= bands) return;
    } while (!ticket_.compare_exchange_weak(ticket, ticket + 1, std::memory_order_acq_rel));
    try {
      fn(context, static_cast<int>(ticket & 0xFF));
    } catch (...) {
      const std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
    // Release: the band's writes are visible to the caller once it sees the count.
    if (finished_.fetch_add(1, std::memory_order_acq_rel) + 1 == bands) finished_.notify_one();
  }
}

void BandWorkers::run_erased(int bands, Erased fn, void* context) {
  bands = std::clamp(bands, 1, kMaxBands);
  if (bands == 1 || threads_.empty()) {
    for (int band = 0; band < bands; ++band) fn(context, band);
    return;
  }
  std::uint64_t generation = 0;
  {
    const std::lock_guard lock(mutex_);
    generation = ++generation_;
    fn_ = fn;
    context_ = context;
    bands_ = bands;
    finished_.store(0, std::memory_order_relaxed);
    ticket_.store(generation << 8, std::memory_order_release);
  }
  wake_.notify_all();
  claim_bands(generation, bands, fn, context);
  // Every band is claimed; wait for those still running on a worker.
  for (int done = finished_.load(std::memory_order_acquire); done != bands;
       done = finished_.load(std::memory_order_acquire))
    finished_.wait(done, std::memory_order_acquire);
  std::exception_ptr error;
  {
    const std::lock_guard lock(mutex_);
    std::swap(error, error_);
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace fieldlines::elsed
