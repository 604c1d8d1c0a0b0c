// Speed of the synthetic renderer: a whole 640x480 image (world, camera, render, effects,
// ground truth) and each stage, next to the detector on the same image as the in-process peer.
// The budget is < 50 ms per image; compare the per-image time with BM_Detector below.
#include <benchmark/benchmark.h>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/synth/synth.hpp"

namespace {

using namespace fieldlines::synth;

SynthParams params_for(int scene) {
  SynthParams p;
  p.field.scene = scene == 0 ? Scene::Ssl : Scene::Kid;
  p.conditions = {all_conditions().begin(), all_conditions().end()};
  return p;
}

void BM_SynthImage(benchmark::State& state) {
  const SynthParams p = params_for(static_cast<int>(state.range(0)));
  int i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(generate(p, 1, i++ % 10));
  state.SetLabel(p.field.scene == Scene::Ssl ? "ssl" : "kid");
}
BENCHMARK(BM_SynthImage)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

struct Stage {
  World world;
  Camera camera{Intrinsics{}, Pose{}};
  Lighting lighting;
  explicit Stage(int scene) {
    const SynthParams p = params_for(scene);
    const FieldModel f = make_field(p.field);
    fieldlines::Rand r(3);
    world = make_world(f, p.clutter, r);
    camera = sample_camera(f, p.intrinsics, default_camera_ranges(f.scene), r);
    lighting = sample_lighting(Condition::Artificial, world, r);
  }
};

void BM_SynthRenderOnly(benchmark::State& state) {
  const Stage s(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(render(s.world, s.camera, s.lighting));
}
BENCHMARK(BM_SynthRenderOnly)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_SynthTruthOnly(benchmark::State& state) {
  const Stage s(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(extract_features(s.world, s.camera));
}
BENCHMARK(BM_SynthTruthOnly)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_SynthEffectsOnly(benchmark::State& state) {
  const Stage s(0);
  const cv::Mat base = render(s.world, s.camera, s.lighting).bgr;
  for (auto _ : state) {
    cv::Mat img = base.clone();
    apply_camera_effects(img, s.lighting, 5);
    benchmark::DoNotOptimize(img.data);
  }
}
BENCHMARK(BM_SynthEffectsOnly)->Unit(benchmark::kMillisecond);

// The peer: the detector on a synthetic image of the same size.
void BM_Detector(benchmark::State& state) {
  const cv::Mat img = generate(params_for(0), 1, 0).bgr;
  fieldlines::LineDetector det;
  std::vector<fieldlines::Segment> out;
  for (auto _ : state) {
    det.detect(img, out);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_Detector)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
