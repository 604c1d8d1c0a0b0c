// Training speed: one class on ~3,000 labelled segments, 100 particles x 100 iterations plus
// the exact polish (target: well under 100 ms), and the feature table's scoring loop against
// the straightforward peer (classify() every segment for every particle). Label-free
// calibration of both classes on the same 3,000 segments (target: under 100 ms), beside it.
#include <filesystem>
#include <random>

#include <benchmark/benchmark.h>

#include "fieldlines/train/calibrate.hpp"
#include "fieldlines/train/feature_table.hpp"
#include "fieldlines/train/metrics.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "fieldlines/train/training.hpp"

namespace fl = fieldlines;

namespace {

// The authors' D3 and D1 rows (3,000 of them) when ../shared is present; otherwise synthetic
// rows of the same mix so the benchmark still runs.
const std::vector<fl::Segment>& segments() {
  static const std::vector<fl::Segment> segs = [] {
    std::vector<fl::Segment> out;
    const std::filesystem::path dir = std::filesystem::path(FIELDLINES_SHARED_DIR) / "data/elsed-ssl/annotations";
    for (const char* f : {"D3_ssl_artificial_light.csv", "D1_ssl_natural_light.csv"}) {
      if (!std::filesystem::exists(dir / f)) break;
      for (const auto& r : fl::read_reference_csv(dir / f))
        if (out.size() < 3000) out.push_back(r.segment);
    }
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0, 1);
    while (out.size() < 3000) {
      fl::Segment s;
      s.x1 = 100, s.saliency = 20 + 300 * u(rng);
      const float m = 10 + 120 * u(rng);
      const int kind = static_cast<int>(out.size() % 3);
      s.grad_y = kind == 0 ? fl::Rgb{m, m, m} : kind == 1 ? fl::Rgb{0, m, 0} : fl::Rgb{m * u(rng), -m * u(rng), m};
      s.label = u(rng) < .9f ? static_cast<fl::Label>(2 - kind) : fl::Label::None;
      out.push_back(s);
    }
    return out;
  }();
  return segs;
}

void BM_TrainMarking(benchmark::State& state) {
  fl::TrainParams p;
  p.polish = state.range(0) != 0;
  p.threads = static_cast<int>(state.range(1));
  double score = 0;
  for (auto _ : state) {
    const fl::TrainResult r = fl::train(segments(), {}, p);
    score = r.score;
    benchmark::DoNotOptimize(r);
  }
  state.counters["segments"] = static_cast<double>(segments().size());
  state.counters["score"] = score;
}
void BM_CalibrateBothClasses(benchmark::State& state) {
  bool fitted = false;
  for (auto _ : state) {
    const fl::Calibration c = fl::calibrate(segments());
    fitted = c.marking.thresholds.has_value();
    benchmark::DoNotOptimize(c);
  }
  state.counters["segments"] = static_cast<double>(segments().size());
  state.counters["marking_fitted"] = fitted;
}
BENCHMARK(BM_CalibrateBothClasses)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_TrainMarking)
    ->ArgNames({"polish", "threads"})
    ->Args({1, 1})
    ->Args({0, 1})
    ->Args({1, 2})
    ->Unit(benchmark::kMillisecond);

// One swarm evaluation (100 threshold sets) with the precomputed feature table...
void BM_ScoreSwarm_FeatureTable(benchmark::State& state) {
  const fl::FeatureTable table(segments(), {});
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<fl::ClassThresholds> swarm;
  for (int i = 0; i < 100; ++i) swarm.push_back({10 + 245 * u(rng), 20 + 50 * u(rng), 50 + 250 * u(rng)});
  const fl::Thresholds base;
  for (auto _ : state)
    for (const auto& m : swarm) benchmark::DoNotOptimize(table.count(base.boundary.thresholds, m));
  state.SetItemsProcessed(state.iterations() * 100 * static_cast<long>(segments().size()));
}
BENCHMARK(BM_ScoreSwarm_FeatureTable)->Unit(benchmark::kMicrosecond);

// ...and the peer: classify() each segment from its gradients for every threshold set.
void BM_ScoreSwarm_ClassifyPeer(benchmark::State& state) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<fl::Thresholds> swarm(100);
  for (auto& t : swarm) t.marking.thresholds = {10 + 245 * u(rng), 20 + 50 * u(rng), 50 + 250 * u(rng)};
  for (auto _ : state) {
    for (const auto& t : swarm) {
      fl::Counts c;
      for (const auto& s : segments()) fl::tally(c, s.label, fl::classify(s, t));
      benchmark::DoNotOptimize(c);
    }
  }
  state.SetItemsProcessed(state.iterations() * 100 * static_cast<long>(segments().size()));
}
BENCHMARK(BM_ScoreSwarm_ClassifyPeer)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
