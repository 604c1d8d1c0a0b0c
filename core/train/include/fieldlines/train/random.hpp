#pragma once
// Portable seeded randomness, in one place for PSO, splits and the synthetic renderer.
//
// std::uniform_real_distribution and friends are implementation-defined, so the same seed could
// give different results with another standard library. Everything here maps fully specified
// integer streams to numbers itself, so a seed means the same swarm, split and scene everywhere.
// PSO and splits draw from SplitMix64; the renderer's Rand runs std::mt19937_64 from a
// SplitMix64-mixed seed (moving it to SplitMix64 would change every synthetic set already made).
#include <cmath>
#include <cstdint>
#include <random>

namespace fieldlines {

// SplitMix64's increment (2^64 / golden ratio) and output mix.
inline constexpr std::uint64_t kSplitMix64Gamma = 0x9E3779B97F4A7C15ull;
constexpr std::uint64_t splitmix64_mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// SplitMix64 finaliser: decorrelates nearby seeds (seed, seed+1, ...) before they reach the engine.
constexpr std::uint64_t mix_seed(std::uint64_t x) { return splitmix64_mix(x + kSplitMix64Gamma); }

// The seed of image `index` in a set generated with `seed`.
constexpr std::uint64_t image_seed(std::uint64_t seed, std::uint64_t index) {
  return mix_seed(seed ^ mix_seed(index + 0x51ED));
}

// Uniform in [0, 1) from the top 53 bits.
constexpr double unit_double(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

// The SplitMix64 generator: tiny state, and the seed is used as given (no mixing), which keeps
// the PSO swarms and splits of every existing seed unchanged.
class SplitMix64 {
 public:
  explicit constexpr SplitMix64(std::uint64_t seed) : state_(seed) {}
  constexpr std::uint64_t next() { return splitmix64_mix(state_ += kSplitMix64Gamma); }
  constexpr double uniform() { return unit_double(next()); }

 private:
  std::uint64_t state_;
};

class Rand {
 public:
  explicit Rand(std::uint64_t seed) : engine_(mix_seed(seed)) {}

  std::uint64_t bits() { return engine_(); }
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return unit_double(engine_()); }
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
