#include "fieldlines/train/splits.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/train/random.hpp"

namespace fieldlines {
namespace {

// The units being split: rows, or images.
std::size_t unit_count(const LabelledSet& data, SplitMode mode) {
  return mode == SplitMode::ByRow ? data.size() : data.images.size();
}

Split assign(const LabelledSet& data, SplitMode mode, const std::vector<char>& unit_in_train) {
  Split s;
  for (std::size_t i = 0; i < data.size(); ++i) {
    const std::size_t unit = mode == SplitMode::ByRow ? i : data.image_of[i];
    (unit_in_train[unit] ? s.train : s.test).push_back(i);
  }
  return s;
}

}  // namespace

std::vector<std::size_t> seeded_permutation(std::size_t n, std::uint64_t seed) {
  std::vector<std::size_t> p(n);
  std::iota(p.begin(), p.end(), std::size_t{0});
  // SplitMix64, not std::uniform_int_distribution: a seed gives the same split with any standard library.
  SplitMix64 rng(seed);
  for (std::size_t i = n; i > 1; --i) {
    // Modulo bias is below 2^-40 for any realistic n.
    const auto j = static_cast<std::size_t>(rng.next() % i);
    std::swap(p[i - 1], p[j]);
  }
  return p;
}

Split split_train_test(const LabelledSet& data, SplitMode mode, double train_fraction,
                       std::uint64_t seed) {
  if (!(train_fraction > 0.0 && train_fraction <= 1.0))
    throw Error("train fraction must be in (0, 1], got " + std::to_string(train_fraction));
  const std::size_t n = unit_count(data, mode);
  if (n == 0) throw Error("no labelled segments to split");
  const std::size_t n_train = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::llround(train_fraction * static_cast<double>(n))), 1, n);
  const std::vector<std::size_t> perm = seeded_permutation(n, seed);
  std::vector<char> in_train(n, 0);
  for (std::size_t i = 0; i < n_train; ++i) in_train[perm[i]] = 1;
  return assign(data, mode, in_train);
}

std::vector<Split> k_fold(const LabelledSet& data, SplitMode mode, int k, std::uint64_t seed) {
  if (k < 2) throw Error("k-fold needs k >= 2, got " + std::to_string(k));
  const std::size_t n = unit_count(data, mode);
  if (n < static_cast<std::size_t>(k))
    throw Error("k-fold: " + std::to_string(n) + (mode == SplitMode::ByRow ? " rows" : " images") +
                " cannot fill " + std::to_string(k) + " folds");
  const std::vector<std::size_t> perm = seeded_permutation(n, seed);
  std::vector<Split> folds;
  for (int f = 0; f < k; ++f) {
    const std::size_t begin = n * static_cast<std::size_t>(f) / static_cast<std::size_t>(k);
    const std::size_t end = n * static_cast<std::size_t>(f + 1) / static_cast<std::size_t>(k);
    std::vector<char> in_train(n, 1);
    for (std::size_t i = begin; i < end; ++i) in_train[perm[i]] = 0;
    folds.push_back(assign(data, mode, in_train));
  }
  return folds;
}

}  // namespace fieldlines
