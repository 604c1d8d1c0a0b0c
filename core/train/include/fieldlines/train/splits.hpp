#pragma once
// Seeded train/test splits of a LabelledSet: by image (no image on both sides, the default) or
// by row (the paper's protocol), and k-fold. Same seed, same split, on every platform.
#include <cstdint>
#include <string_view>
#include <vector>

#include "fieldlines/data/labelled_set.hpp"
#include "fieldlines/data/split_spec.hpp"  // SplitMode, SplitSpec (recorded in project files)

namespace fieldlines {

struct Split {
  std::vector<std::size_t> train, test;  // segment indices, ascending
};

// `train_fraction` in (0, 1]: the share of rows (ByRow) or images (ByImage) put in train,
// rounded, with at least one unit in train. Throws fieldlines::Error on a bad fraction.
Split split_train_test(const LabelledSet& data, SplitMode mode, double train_fraction,
                       std::uint64_t seed);
// The same with the parameters a project records: the studio's split, and the CLI's defaults.
inline Split split_train_test(const LabelledSet& data, const SplitSpec& spec) {
  return split_train_test(data, spec.mode, spec.train_fraction, spec.seed);
}

// k folds; fold i tests on the i-th of k near-equal parts and trains on the rest.
// Throws fieldlines::Error when k < 2 or there are fewer units than folds.
std::vector<Split> k_fold(const LabelledSet& data, SplitMode mode, int k, std::uint64_t seed);

// The seeded permutation of 0..n-1 the splits use (Fisher-Yates on splitmix64).
std::vector<std::size_t> seeded_permutation(std::size_t n, std::uint64_t seed);

}  // namespace fieldlines
