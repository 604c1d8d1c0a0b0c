#pragma once
// Timing detectors against each other so that the ratio does not depend on the order they run in.
//
// A detector's time depends on what ran just before it: the same call is faster when it runs
// back to back with itself (its tables and buffers stay in cache) than when three other
// detectors have flushed the caches between two of its calls. So every detector is timed in
// both orders, over repeated rounds:
//   block        each detector makes all its calls of the round back to back (one untimed call
//                first, so its buffers are warm), detectors in a random order;
//   interleaved  image by image, every detector once per image, in a random order per image.
// Each round runs the two orders in a random order (seeded), so slow drift of the machine's
// load hits both alike. A ratio a/b is taken per round and per order (a's time over b's, each
// summed over all its calls of that round, on the same images), then summarised over rounds.
// Summed, not the median call: over frames of unequal cost (a busy 800x600 frame beside a plain
// 640x360 one) the median call is one frame's, and a stage whose cost lies in the busy frames
// (the field features: 1.6x by medians, 2.9x in total on the Humanoid frames) would hide there.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "bench/peers/peer_detectors.hpp"

namespace fieldlines::peers {

enum class Order { Block, Interleaved };
inline constexpr Order kOrders[] = {Order::Block, Order::Interleaved};
const char* order_name(Order order);  // "block", "interleaved"

// What a call's time is. On a machine shared with other processes, wall time also counts the
// other processes' turns, and a long call (a peer's 10 ms) is preempted far more often than a
// short one (our 1 ms): the ratio then flatters the short call. The calling thread's CPU time
// does not count those turns; it misses work done on other threads, so a detector that runs
// threads of its own is timed by the wall clock.
enum class Clock { ThreadCpu, Wall };
const char* clock_name(Clock clock);  // "thread-cpu", "wall"

struct RoundsParams {
  int rounds = 5;          // >= 1
  int passes = 1;          // passes over all images per order per round, >= 1
  std::uint64_t seed = 1;  // the random orders
  Clock clock = Clock::ThreadCpu;
};

struct DetectorTimes {
  std::string name;
  // ms[order][round]: the time (RoundsParams::clock) of every timed call in that order and round.
  std::vector<std::vector<double>> ms[2];
  double segments = 0;  // summed over one untimed pass over all images
  // Every call of one order, all rounds pooled.
  std::vector<double> pooled(Order order) const;
};

// Runs one untimed warm-up pass (interleaved; it also counts segments), then the rounds.
// `advance` (may be empty) is called once per detector call, warm-ups included; the total is
// calls_expected().
std::vector<DetectorTimes> time_in_both_orders(const std::vector<TimedDetector>& detectors,
                                               const std::vector<cv::Mat>& images, const RoundsParams& params,
                                               const std::function<void()>& advance = {});
std::size_t calls_expected(std::size_t detectors, std::size_t images, const RoundsParams& params);

// One call of `d` on `image`, timed by `clock`, in ms.
double timed_call_ms(const TimedDetector& d, const cv::Mat& image, Clock clock);
// 0..n-1 in a random order drawn from rng.
std::vector<std::size_t> random_order(std::size_t n, std::mt19937_64& rng);

// Linear interpolation between closest ranks (the usual "type 7" quantile); v not empty.
double quantile(std::vector<double> v, double q);

// The sum of `ms`: a round's total time.
double total(const std::vector<double>& ms);
// The mean call of `ms` (0 when empty).
double mean(const std::vector<double>& ms);

// a/b in each order: the median over rounds of (a's total time) / (b's total time) in the
// round. `worse` is the larger of the two (the one less flattering to a), `min`/`max` its
// spread over rounds.
struct RatioSummary {
  double by_order[2] = {0, 0};
  Order worse_order = Order::Block;
  double worse = 0, min = 0, max = 0;
};
RatioSummary ratio_in_both_orders(const DetectorTimes& a, const DetectorTimes& b);

}  // namespace fieldlines::peers
