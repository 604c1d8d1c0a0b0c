#pragma once
// Runs a batch on a few worker threads. Items are handed out one at a time (images differ in
// cost), and `work` gets the worker index so each worker can own its detector and buffers.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace fieldlines::cli {

// Calls work(item, worker) for every item in [0, count), worker in [0, workers). `work` should
// report its own per-item failures; an exception escaping it stops the batch and is rethrown here.
template <class Work>
void run_parallel_batch(std::size_t count, int workers, Work&& work) {
  const auto n = static_cast<std::size_t>(std::max(1, workers));
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto loop = [&](int worker) {
    try {
      for (std::size_t i = next++; i < count; i = next++) work(i, worker);
    } catch (...) {
      std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = count;  // stop handing out items
    }
  };
  if (n == 1 || count <= 1) {
    loop(0);
  } else {
    std::vector<std::jthread> pool;
    for (std::size_t w = 0; w < std::min(n, count); ++w) pool.emplace_back(loop, static_cast<int>(w));
  }  // jthreads join here
  if (failure) std::rethrow_exception(failure);
}

}  // namespace fieldlines::cli
