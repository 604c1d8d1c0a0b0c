#pragma once
// Private: a few threads kept for the detector's lifetime that run one job per band, so a
// frame's gradient pass can use several cores without creating threads or allocating per frame.
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
  BandWorkers() = default;
  BandWorkers(const BandWorkers&) = delete;
  BandWorkers& operator=(const BandWorkers&) = delete;
  ~BandWorkers();  // joins

  // Keeps `count` worker threads (the caller is one more). Starts or stops threads only when the
  // count changes, so it allocates then and never per frame.
  void resize(int count);
  int size() const { return static_cast<int>(threads_.size()); }

  // Calls job(band) for every band in [0, bands): band 0 on the calling thread, band i on worker
  // i - 1 (bands <= size() + 1). Returns when all are done; rethrows a worker's exception. A plain
  // function pointer and context rather than std::function, which could allocate.
  template <class Job>
  void run(int bands, Job& job) {
    run_erased(bands, [](void* j, int band) { (*static_cast<Job*>(j))(band); }, &job);
  }

 private:
  using Erased = void (*)(void*, int);
  void run_erased(int bands, Erased fn, void* context);
  void work(int index, std::uint64_t seen);
  void stop_all();

  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::uint64_t generation_ = 0;  // bumped per run; a worker runs once per new value
  int bands_ = 0, pending_ = 0;
  Erased fn_ = nullptr;
  void* context_ = nullptr;
  bool stopping_ = false;
  std::exception_ptr error_;
  std::vector<std::thread> threads_;
};

}  // namespace fieldlines::elsed

#pragma GCC visibility pop
