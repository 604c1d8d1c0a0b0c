#include "fieldlines/train/sweep.hpp"

#include <algorithm>

#include "fieldlines/detect/error.hpp"

namespace fieldlines {

std::vector<SweepCell> run_sweep(const LabelledSet& data, const SweepParams& p,
                                 const std::function<void(int, int)>& on_run, std::stop_token stop) {
  if (p.seeds < 1) throw Error("sweep needs at least one seed");
  if (p.fractions.empty()) throw Error("sweep needs at least one training fraction");
  for (const double f : p.fractions)
    if (!(f > 0 && f < 1)) throw Error("training fractions must be in (0, 1), got " + std::to_string(f));
  std::vector<SweepCell> cells;
  const int total = static_cast<int>(p.fractions.size()) * p.seeds;
  int done = 0;
  for (const double fraction : p.fractions) {
    SweepCell cell;
    cell.fraction = fraction;
    std::vector<double> precision, recall;
    for (int seed = 1; seed <= p.seeds && !stop.stop_requested(); ++seed) {
      const Split split = split_train_test(data, p.split, fraction, static_cast<std::uint64_t>(seed));
      const LabelledSet train_set = data.subset(split.train), test_set = data.subset(split.test);
      TrainParams tp = p.train;
      tp.pso.seed = static_cast<std::uint64_t>(seed);
      const TrainResult r = train(train_set.segments, p.start, tp, {}, stop);
      const ClassCounts c = target_counts(evaluate(test_set, r.thresholds).total, p.train.target);
      cell.test.push_back(c);
      precision.push_back(c.precision());
      recall.push_back(c.recall());
      if (on_run) on_run(++done, total);
    }
    cell.median_precision = median(precision);
    cell.median_recall = median(recall);
    cells.push_back(std::move(cell));
  }
  return cells;
}

}  // namespace fieldlines
