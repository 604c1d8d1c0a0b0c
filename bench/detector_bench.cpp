// Google Benchmark: our detect+classify against OpenCV's EDLines, FastLineDetector and LSD and
// the cvtColor + Gaussian 5x5 + Sobel x/y floor, single thread, same colour images, same process.
// Images: ../shared/data/elsed-ssl/images when present (the method's 640x480 robot frames),
// otherwise synthetic 640x480 fields. Prints each detector's time relative to ours at the end.
//
//   build/release/bench/detector_bench [--benchmark_repetitions=5 --benchmark_report_aggregates_only=true]
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "fieldlines/data/image_io.hpp"
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

// Console output as usual, plus each benchmark's CPU time per image for the ratio table: CPU
// time, because the 2-core machine is shared and wall time also counts other processes' turns.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      const std::string name = r.run_name.function_name;
      // With repetitions keep the median aggregate; otherwise the single run.
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
      if (r.run_type == Run::RT_Iteration && medians_.count(name)) continue;
      if (r.run_type == Run::RT_Aggregate) medians_[name] = r.GetAdjustedCPUTime();
      else times_[name] = r.GetAdjustedCPUTime();
    }
  }
  double time(const std::string& name) const {
    if (const auto it = medians_.find(name); it != medians_.end()) return it->second;
    const auto it = times_.find(name);
    return it == times_.end() ? 0.0 : it->second;
  }

 private:
  std::map<std::string, double> times_, medians_;
};

}  // namespace

int main(int argc, char** argv) {
  cv::setNumThreads(1);
  std::string source;
  const std::vector<cv::Mat> frames = load_frames(source);
  std::printf("images: %zu from %s\n", frames.size(), source.c_str());

  auto detectors = fieldlines::peers::make_timed_detectors();
  for (auto& d : detectors) {
    benchmark::RegisterBenchmark(d.name.c_str(), [&frames, &d](benchmark::State& state) {
      std::size_t i = 0, segments = 0, calls = 0;
      for (auto _ : state) {
        const std::size_t n = d.run(frames[i]);
        benchmark::DoNotOptimize(n);
        segments += n;
        ++calls;
        i = (i + 1) % frames.size();
      }
      state.counters["segments_per_image"] = static_cast<double>(segments) / static_cast<double>(std::max<std::size_t>(1, calls));
      state.SetLabel(d.what);
    })->Unit(benchmark::kMillisecond);
  }

  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);

  const double ours = reporter.time("fieldlines");
  if (ours > 0) {
    std::printf("\nfieldlines CPU time / other detector's CPU time (lower is better for us):\n");
    for (const auto& d : detectors)
      if (const double t = reporter.time(d.name); t > 0) std::printf("  %-10s %6.2f\n", d.name.c_str(), ours / t);
    std::printf("targets: <= 0.40 vs edlines, <= 1.50 vs floor\n");
    if (const double g = reporter.time("gradients"), f = reporter.time("floor"); g > 0 && f > 0)
      std::printf("gradients only / floor: %.2f\n", g / f);
  }
  benchmark::Shutdown();
  return 0;
}
