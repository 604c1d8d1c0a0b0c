#pragma once
// Precision/recall against training-set size (the paper's Table 3): for each fraction and
// seed, split, train on the train part and evaluate on the rest; report medians over seeds.
#include <functional>
#include <stop_token>
#include <vector>

#include "fieldlines/train/percentile.hpp"

#include "fieldlines/data/labelled_set.hpp"
#include "fieldlines/train/metrics.hpp"
#include "fieldlines/train/splits.hpp"
#include "fieldlines/train/training.hpp"

namespace fieldlines {

struct SweepParams {
  std::vector<double> fractions{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7};
  int seeds = 10;                    // seeds 1..seeds: split seed s, PSO seed s
  SplitMode split = SplitMode::ByRow;
  TrainParams train;
  Thresholds start;                  // colour classes, mode, thresholds of the untrained class
};

struct SweepCell {
  double fraction = 0;
  std::vector<ClassCounts> test;     // per seed, the trained class's test counts
  double median_precision = 0, median_recall = 0;
};

// `on_run(done, total)` after each training run. Throws fieldlines::Error on bad fractions.
std::vector<SweepCell> run_sweep(const LabelledSet& data, const SweepParams& params,
                                 const std::function<void(int, int)>& on_run = {}, std::stop_token stop = {});

}  // namespace fieldlines
