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
  for (int i = 0; i < count; ++i) threads_.emplace_back([this, i, g = generation_] { work(i, g); });
}

void BandWorkers::work(int index, std::uint64_t seen) {
  for (;;) {
    Erased fn = nullptr;
    void* context = nullptr;
    bool mine = false;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      mine = index + 1 < bands_;
      fn = fn_;
      context = context_;
    }
    if (!mine) continue;
    std::exception_ptr error;
    try {
      fn(context, index + 1);
    } catch (...) {
      error = std::current_exception();
    }
    bool last = false;
    {
      const std::lock_guard lock(mutex_);
      if (error && !error_) error_ = error;
      last = --pending_ == 0;
    }
    if (last) done_.notify_one();
  }
}

void BandWorkers::run_erased(int bands, Erased fn, void* context) {
  bands = std::clamp(bands, 1, size() + 1);
  if (bands > 1) {
    {
      const std::lock_guard lock(mutex_);
      fn_ = fn;
      context_ = context;
      bands_ = bands;
      pending_ = bands - 1;
      ++generation_;
    }
    wake_.notify_all();
  }
  std::exception_ptr error;
  try {
    fn(context, 0);
  } catch (...) {
    error = std::current_exception();
  }
  if (bands > 1) {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return pending_ == 0; });
    if (!error) error = error_;
    error_ = nullptr;
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace fieldlines::elsed
