#include <cstdio>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/synth/synth.hpp"

namespace fieldlines::synth {
namespace {

namespace fs = std::filesystem;

void write_png(const fs::path& path, const cv::Mat& image) {
  std::vector<uchar> bytes;
  if (!cv::imencode(".png", image, bytes)) throw Error(path.string() + ": could not encode PNG");
  write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace

SynthSample generate(const SynthParams& params, std::uint64_t seed, int index) {
  if (params.conditions.empty()) throw Error("synth: no lighting condition given");
  if (index < 0) throw Error("synth: image index must be >= 0");
  const FieldModel field = make_field(params.field);
  const CameraRanges ranges = params.camera.value_or(default_camera_ranges(field.scene));
  const Condition condition = params.conditions[static_cast<std::size_t>(index) % params.conditions.size()];

  // Separate streams per concern, so e.g. adding clutter never moves the camera of a seed.
  const std::uint64_t base = image_seed(seed, static_cast<std::uint64_t>(index));
  Rand world_rand(base ^ 0x1001), camera_rand(base ^ 0x2002), light_rand(base ^ 0x3003);
  const World world = make_world(field, params.clutter, world_rand);
  const Camera camera = sample_camera(field, params.intrinsics, ranges, camera_rand);
  const Lighting lighting = sample_lighting(condition, world, light_rand);

  Rendered r = render(world, camera, lighting, params.render);
  if (params.camera_effects) apply_camera_effects(r.bgr, lighting, base ^ 0x4004);

  SynthSample s;
  s.bgr = r.bgr;
  s.mask = r.mask;
  const std::string stem = sample_stem(field.scene, seed, index);
  s.truth.image = stem + ".png";
  s.truth.mask = "../masks/" + stem + ".png";
  s.truth.scene = field.scene;
  s.truth.condition = condition;
  s.truth.seed = seed;
  s.truth.index = index;
  s.truth.line_width = field.line_width;
  s.truth.intrinsics = camera.intrinsics();
  s.truth.pose = camera.pose();
  s.truth.features = extract_features(world, camera, params.truth);
  return s;
}

std::string sample_stem(Scene scene, std::uint64_t seed, int index) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "_%llu_%04d", static_cast<unsigned long long>(seed), index);
  return std::string(to_string(scene)) + buf;
}

SampleFiles sample_files(const fs::path& dir, const std::string& stem) {
  return {dir / (stem + ".png"), dir / "masks" / (stem + ".png"), dir / "truth" / (stem + ".json")};
}

fs::path truth_path(const fs::path& image) {
  return image.parent_path() / "truth" / (image.stem().string() + ".json");
}

SampleFiles write_sample(const SynthSample& sample, const fs::path& dir) {
  const std::string stem = fs::path(sample.truth.image).stem().string();
  const SampleFiles files = sample_files(dir, stem);
  std::error_code ec;
  for (const fs::path& d : {dir, dir / "masks", dir / "truth"}) {
    fs::create_directories(d, ec);
    if (ec) throw Error(d.string() + ": cannot create folder (" + ec.message() + ")");
  }
  write_png(files.image, sample.bgr);
  write_png(files.mask, sample.mask);
  save_truth(files.truth, sample.truth);
  return files;
}

}  // namespace fieldlines::synth
