#pragma once
// Portable seeded randomness: the one seeded generator of the synthetic renderer, PSO and splits.
//
// std::uniform_real_distribution and friends are implementation-defined, so the same seed could
// give different images with another standard library. Rand maps std::mt19937_64's (fully
// specified) output to numbers itself, so a seed means the same scene everywhere.
#include <cmath>
#include <cstdint>
#include <random>

namespace fieldlines {

// SplitMix64 finaliser: decorrelates nearby seeds (seed, seed+1, ...) before they reach the engine.
constexpr std::uint64_t mix_seed(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// The seed of image `index` in a set generated with `seed`.
constexpr std::uint64_t image_seed(std::uint64_t seed, std::uint64_t index) {
  return mix_seed(seed ^ mix_seed(index + 0x51ED));
}

class Rand {
 public:
  explicit Rand(std::uint64_t seed) : engine_(mix_seed(seed)) {}

  std::uint64_t bits() { return engine_(); }
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [lo, hi] (inclusive); the tiny modulo bias is irrelevant here.
  int integer(int lo, int hi) {
    return lo + static_cast<int>(engine_() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  bool chance(double p) { return uniform() < p; }
  // Box-Muller; one value per call keeps the stream simple to reason about.
  double normal(double mean, double sd) {
    const double u1 = 1.0 - uniform();  // (0, 1]
    const double u2 = uniform();
    return mean + sd * std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace fieldlines
