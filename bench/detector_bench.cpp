// Google Benchmark: our detect+classify against OpenCV's EDLines, FastLineDetector and LSD and
// the cvtColor + Gaussian 5x5 + Sobel x/y floor, single thread, same colour images, same process.
// Images: ../shared/data/elsed-ssl/images when present (the method's 640x480 robot frames),
// otherwise synthetic 640x480 fields. One iteration is one pass over all images, so every
// detector is timed on the same frames.
//
// A detector's time depends on what ran before it (bench/peers/order_rounds.hpp), so each is
// timed in both orders: block/<name> calls one detector on every image back to back;
// "interleaved" calls every detector once per image, in a random order per image, and times
// each call on the thread's CPU clock (its counters, ms per image). By default 5 repetitions
// run in a random interleaving, and the ratios at the end are per repetition, per order: the
// worse order for us, with its min-max over repetitions, is what the targets are checked on.
//
//   build/release/bench/detector_bench [--benchmark_repetitions=7 --benchmark_enable_random_interleaving=true]
//       [--benchmark_display_aggregates_only=false]   (shows every repetition, not only the aggregates)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <random>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "fieldlines/data/image_io.hpp"
#include "bench/peers/order_rounds.hpp"
#include "bench/peers/peer_detectors.hpp"

namespace {

namespace fs = std::filesystem;

// Green carpet, a dark wall, white lines at varying angles and camera-like noise.
std::vector<cv::Mat> synthetic_frames() {
  std::vector<cv::Mat> frames;
  cv::RNG rng(7);
  for (int i = 0; i < 8; ++i) {
    cv::Mat img(480, 640, CV_8UC3, cv::Scalar(50, 140, 40));
    const int wall = 60 + rng.uniform(0, 40);
    const std::vector<cv::Point> poly{{0, 0}, {639, 0}, {639, wall + rng.uniform(-15, 15)}, {0, wall}};
    cv::fillConvexPoly(img, poly, cv::Scalar(25, 25, 25));
    for (int l = 0; l < 5; ++l)
      cv::line(img, {rng.uniform(0, 640), rng.uniform(wall + 10, 480)}, {rng.uniform(0, 640), rng.uniform(wall + 10, 480)},
               {250, 250, 250}, rng.uniform(3, 9), cv::LINE_AA);
    cv::Mat noise(img.size(), CV_16SC3), noisy;
    rng.fill(noise, cv::RNG::NORMAL, 0, 4);
    img.convertTo(noisy, CV_16SC3);
    noisy += noise;
    noisy.convertTo(img, CV_8UC3);
    frames.push_back(img);
  }
  return frames;
}

std::vector<cv::Mat> load_frames(std::string& source) {
  const fs::path dir = fs::path(FIELDLINES_SHARED_DIR) / "data/elsed-ssl/images";
  std::vector<cv::Mat> frames;
  if (fs::is_directory(dir)) {
    for (const auto& p : fieldlines::list_images(dir)) frames.push_back(fieldlines::to_bgr8(fieldlines::load_image(p)).clone());
  }
  if (!frames.empty()) {
    source = dir.string();
    return frames;
  }
  source = "synthetic 640x480 fields (shared data not found at " + dir.string() + ")";
  return synthetic_frames();
}

namespace peers = fieldlines::peers;

// Console output as usual, plus every repetition's ms per image of each detector in each order
// (CPU time: the 2-core machine is shared and wall time also counts other processes' turns).
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  RatioReporter(const std::vector<peers::TimedDetector>& detectors, std::size_t frames, bool aggregates_only)
      : frames_(frames), aggregates_only_(aggregates_only) {
    for (const auto& d : detectors) {
      times_.push_back({});
      times_.back().name = d.name;
      medians_.push_back(times_.back());
    }
  }
  void ReportRuns(const std::vector<Run>& runs) override {
    std::vector<Run> shown;
    for (const Run& r : runs)
      if (!aggregates_only_ || r.run_type == Run::RT_Aggregate) shown.push_back(r);
    ConsoleReporter::ReportRuns(shown.empty() ? runs : shown);
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      // Without repetitions (or with none reported) the median aggregates stand in, no spread.
      const bool repetition = r.run_type == Run::RT_Iteration;
      if (!repetition && r.aggregate_name != "median") continue;
      auto& into = repetition ? times_ : medians_;
      const std::string name = r.run_name.function_name;
      for (auto& t : into) {
        if (name == "block/" + t.name)
          add(t, peers::Order::Block, repetition ? r.repetition_index : 0,
              r.GetAdjustedCPUTime() / static_cast<double>(frames_));
        else if (name == "interleaved" && r.counters.count(t.name))
          add(t, peers::Order::Interleaved, repetition ? r.repetition_index : 0, r.counters.at(t.name).value);
      }
    }
  }
  // One "round" per repetition, holding that repetition's ms per image; the median aggregates
  // as one round when the repetitions were not reported; empty when a benchmark was filtered out.
  std::vector<peers::DetectorTimes> times() const {
    for (const auto* set : {&times_, &medians_})
      if (std::all_of(set->begin(), set->end(), complete)) return *set;
    return {};
  }

 private:
  static bool complete(const peers::DetectorTimes& t) {
    for (const auto& rounds : t.ms) {
      if (rounds.empty()) return false;
      for (const auto& r : rounds)
        if (r.empty()) return false;
    }
    return true;
  }
  static void add(peers::DetectorTimes& t, peers::Order order, std::int64_t repetition, double ms) {
    auto& rounds = t.ms[static_cast<int>(order)];
    const auto k = static_cast<std::size_t>(std::max<std::int64_t>(0, repetition));
    if (rounds.size() <= k) rounds.resize(k + 1);
    rounds[k].push_back(ms);
  }
  std::size_t frames_;
  bool aggregates_only_;
  std::vector<peers::DetectorTimes> times_, medians_;
};

std::string worse_text(const peers::RatioSummary& r) {
  return cv::format("%.2f [%.2f-%.2f, %s]", r.worse, r.min, r.max, peers::order_name(r.worse_order));
}

}  // namespace

int main(int argc, char** argv) {
  cv::setNumThreads(1);
  std::string source;
  const std::vector<cv::Mat> frames = load_frames(source);
  std::printf("images: %zu from %s\n", frames.size(), source.c_str());

  const auto detectors = peers::make_timed_detectors();
  for (const auto& d : detectors) {
    benchmark::RegisterBenchmark(("block/" + d.name).c_str(), [&frames, &d](benchmark::State& state) {
      std::size_t segments = 0;
      for (auto _ : state)
        for (const auto& frame : frames) segments += d.run(frame);
      state.counters["segments_per_image"] =
          static_cast<double>(segments) / static_cast<double>(state.iterations() * frames.size());
      state.SetLabel(d.what);
    })->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("interleaved", [&frames, &detectors](benchmark::State& state) {
    std::mt19937_64 rng(1);
    std::vector<double> ms(detectors.size(), 0.0);
    for (auto _ : state)
      for (const auto& frame : frames)
        for (const std::size_t d : peers::random_order(detectors.size(), rng))
          ms[d] += peers::timed_call_ms(detectors[d], frame, peers::Clock::ThreadCpu);
    for (std::size_t d = 0; d < detectors.size(); ++d)
      state.counters[detectors[d].name] =
          benchmark::Counter(ms[d] / static_cast<double>(frames.size()), benchmark::Counter::kAvgIterations);
    state.SetLabel("counters: ms per image of each detector, every detector once per image in a random order");
  })->Unit(benchmark::kMillisecond);

  // Repetitions in a random interleaving unless asked otherwise: the per-repetition ratios and
  // their spread need more than one, and the interleaving spreads the machine's drift.
  // The aggregates-only flags are taken over here: Google Benchmark would hide the repetitions
  // from this reporter too, and the ratios' spread is taken over them. Shown: aggregates only,
  // unless =false.
  std::vector<char*> args{argv[0]};
  bool repetitions_given = false, aggregates_only = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    repetitions_given |= arg.rfind("--benchmark_repetitions", 0) == 0;
    if (arg.rfind("--benchmark_report_aggregates_only", 0) == 0 || arg.rfind("--benchmark_display_aggregates_only", 0) == 0)
      aggregates_only = arg.find("=false") == std::string::npos;
    else
      args.push_back(argv[i]);
  }
  std::string repetitions = "--benchmark_repetitions=5", interleaving = "--benchmark_enable_random_interleaving=true";
  if (!repetitions_given) {
    args.push_back(repetitions.data());
    args.push_back(interleaving.data());
  }
  int count = static_cast<int>(args.size());
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
  RatioReporter reporter(detectors, frames.size(), aggregates_only);
  benchmark::RunSpecifiedBenchmarks(&reporter);

  const std::vector<peers::DetectorTimes> times = reporter.times();
  if (times.empty()) {
    std::printf("\n(ratios need every block/<name> benchmark and interleaved: not filtered out)\n");
    benchmark::Shutdown();
    return 0;
  }
  const auto row = [&](const std::string& name) -> const peers::DetectorTimes& {
    return *std::find_if(times.begin(), times.end(), [&](const auto& t) { return t.name == name; });
  };
  std::printf("\nms per image (CPU time, mean over the calls of %zu repetition(s)) and fieldlines / this (lower is\n"
              "better for us; per repetition, summed times; the median over them; worse: the larger order,\n"
              "[min-max over repetitions, order]):\n",
              times.front().ms[0].size());
  std::printf("  %-11s %9s %11s %7s %8s  %s\n", "detector", "block ms", "interl. ms", "block", "interl.", "worse");
  for (const auto& t : times) {
    const peers::RatioSummary r = peers::ratio_in_both_orders(times.front(), t);
    std::printf("  %-11s %9.3f %11.3f %7.2f %8.2f  %s\n", t.name.c_str(), peers::mean(t.pooled(peers::Order::Block)),
                peers::mean(t.pooled(peers::Order::Interleaved)), r.by_order[0], r.by_order[1],
                worse_text(r).c_str());
  }
  const peers::RatioSummary vs_edlines = peers::ratio_in_both_orders(times.front(), row("edlines"));
  const peers::RatioSummary vs_floor = peers::ratio_in_both_orders(times.front(), row("floor"));
  std::printf("targets, on the worse order: fieldlines/edlines = %s (<= 0.40: %s), fieldlines/floor = %s (<= 1.50: %s)\n",
              worse_text(vs_edlines).c_str(), vs_edlines.worse <= 0.4 ? "met" : "NOT met", worse_text(vs_floor).c_str(),
              vs_floor.worse <= 1.5 ? "met" : "NOT met");
  std::printf("gradients only / floor = %s\n", worse_text(peers::ratio_in_both_orders(row("gradients"), row("floor"))).c_str());
  benchmark::Shutdown();
  return 0;
}
