#include "bench/peers/order_rounds.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <numeric>
#include <random>

namespace fieldlines::peers {
namespace {

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

}  // namespace

double timed_call_ms(const TimedDetector& d, const cv::Mat& image, Clock clock) {
  if (clock == Clock::ThreadCpu) {
    const double t0 = thread_cpu_ms();
    d.run(image);
    return thread_cpu_ms() - t0;
  }
  const auto t0 = std::chrono::steady_clock::now();
  d.run(image);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<std::size_t> random_order(std::size_t n, std::mt19937_64& rng) {
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin(), order.end(), rng);
  return order;
}

const char* order_name(Order order) { return order == Order::Block ? "block" : "interleaved"; }
const char* clock_name(Clock clock) { return clock == Clock::ThreadCpu ? "thread-cpu" : "wall"; }

std::vector<double> DetectorTimes::pooled(Order order) const {
  std::vector<double> all;
  for (const auto& round : ms[static_cast<int>(order)]) all.insert(all.end(), round.begin(), round.end());
  return all;
}

std::size_t calls_expected(std::size_t detectors, std::size_t images, const RoundsParams& params) {
  const auto rounds = static_cast<std::size_t>(params.rounds), passes = static_cast<std::size_t>(params.passes);
  // Warm-up pass + both orders' passes + one untimed call per detector before each block.
  return detectors * images * (1 + 2 * rounds * passes) + detectors * rounds;
}

std::vector<DetectorTimes> time_in_both_orders(const std::vector<TimedDetector>& detectors,
                                               const std::vector<cv::Mat>& images, const RoundsParams& params,
                                               const std::function<void()>& advance) {
  const auto tick = [&] {
    if (advance) advance();
  };
  std::vector<DetectorTimes> out(detectors.size());
  for (std::size_t d = 0; d < detectors.size(); ++d) {
    out[d].name = detectors[d].name;
    for (auto& by_round : out[d].ms) by_round.resize(static_cast<std::size_t>(params.rounds));
  }
  for (const auto& image : images) {
    for (std::size_t d = 0; d < detectors.size(); ++d) {
      out[d].segments += static_cast<double>(detectors[d].run(image));
      tick();
    }
  }

  std::mt19937_64 rng(params.seed);
  const auto block = [&](std::size_t round) {
    for (const std::size_t d : random_order(detectors.size(), rng)) {
      detectors[d].run(images.front());  // its buffers and tables back in cache, untimed
      tick();
      auto& ms = out[d].ms[static_cast<int>(Order::Block)][round];
      for (int pass = 0; pass < params.passes; ++pass) {
        for (const auto& image : images) {
          ms.push_back(timed_call_ms(detectors[d], image, params.clock));
          tick();
        }
      }
    }
  };
  const auto interleaved = [&](std::size_t round) {
    for (int pass = 0; pass < params.passes; ++pass) {
      for (const auto& image : images) {
        for (const std::size_t d : random_order(detectors.size(), rng)) {
          out[d].ms[static_cast<int>(Order::Interleaved)][round].push_back(timed_call_ms(detectors[d], image, params.clock));
          tick();
        }
      }
    }
  };
  for (std::size_t round = 0; round < static_cast<std::size_t>(params.rounds); ++round) {
    if (std::bernoulli_distribution(0.5)(rng)) {
      block(round);
      interleaved(round);
    } else {
      interleaved(round);
      block(round);
    }
  }
  return out;
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(pos);
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

double total(const std::vector<double>& ms) { return std::accumulate(ms.begin(), ms.end(), 0.0); }

double mean(const std::vector<double>& ms) { return ms.empty() ? 0 : total(ms) / static_cast<double>(ms.size()); }

RatioSummary ratio_in_both_orders(const DetectorTimes& a, const DetectorTimes& b) {
  RatioSummary s;
  std::vector<double> per_round[2];
  for (const Order order : kOrders) {
    const int o = static_cast<int>(order);
    for (std::size_t r = 0; r < a.ms[o].size(); ++r)
      per_round[o].push_back(total(a.ms[o][r]) / total(b.ms[o][r]));
    s.by_order[o] = quantile(per_round[o], 0.5);
  }
  s.worse_order = s.by_order[1] > s.by_order[0] ? Order::Interleaved : Order::Block;
  const auto& worse = per_round[static_cast<int>(s.worse_order)];
  s.worse = s.by_order[static_cast<int>(s.worse_order)];
  s.min = *std::min_element(worse.begin(), worse.end());
  s.max = *std::max_element(worse.begin(), worse.end());
  return s;
}

}  // namespace fieldlines::peers
