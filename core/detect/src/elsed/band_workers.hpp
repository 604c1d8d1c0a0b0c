#pragma once
// Private: a few threads kept for the detector's lifetime that share one frame's row bands, so
// the gradient pass can use several cores without creating threads or allocating per frame.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#pragma GCC visibility push(hidden)  // private to the library (see line_model.hpp)

namespace fieldlines::elsed {

class BandWorkers {
 public:
  static constexpr int kMaxBands = 64;

  BandWorkers() = default;
  BandWorkers(const BandWorkers&) = delete;
  BandWorkers& operator=(const BandWorkers&) = delete;
  ~BandWorkers();  // joins

  // Keeps `count` worker threads (the caller is one more). Starts or stops threads only when the
  // count changes, so it allocates then and never per frame.
  void resize(int count);
  int size() const { return static_cast<int>(threads_.size()); }

  // Calls job(band) once for every band in [0, bands) (at most kMaxBands) and returns when all
  // are done, rethrowing the first exception. The caller and the woken workers claim bands in
  // turn, so a worker that is slow to wake (a busy machine) only means the caller does more.
  // A plain function pointer and context rather than std::function, which could allocate.
  template <class Job>
  void run(int bands, Job& job) {
    run_erased(bands, [](void* j, int band) { (*static_cast<Job*>(j))(band); }, &job);
  }

 private:
  using Erased = void (*)(void*, int);
  void run_erased(int bands, Erased fn, void* context);
  void work(std::uint64_t seen);
  // Claims and runs bands of `generation` until none is left.
  void claim_bands(std::uint64_t generation, int bands, Erased fn, void* context);
  void stop_all();

  // Wakes the workers, once per run; what they read under it describes the run.
  std::mutex mutex_;
  std::condition_variable wake_;
  std::uint64_t generation_ = 0;
  int bands_ = 0;
  Erased fn_ = nullptr;
  void* context_ = nullptr;
  bool stopping_ = false;
  std::exception_ptr error_;

  // generation << 8 | next unclaimed band: a claim succeeds only within its own run, so a late
  // worker never starts a band of a run that has already returned.
  std::atomic<std::uint64_t> ticket_{0};
  std::atomic<int> finished_{0};  // bands done in the current run
  std::vector<std::thread> threads_;
};

}  // namespace fieldlines::elsed

#pragma GCC visibility pop
