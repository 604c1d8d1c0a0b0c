#include "fieldlines/synth/demo.hpp"

#include <chrono>
#include <cstdlib>
#include <random>
#include <string>
#include <system_error>

#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/synth/gt_eval.hpp"
#include "fieldlines/synth/synth.hpp"

namespace fieldlines {
namespace {

namespace fs = std::filesystem;

void build_demo(const fs::path& dir, const DemoParams& params) {
  synth::SynthParams sp;
  sp.field.scene = synth::Scene::Ssl;
  const auto conditions = synth::all_conditions();
  sp.conditions.assign(conditions.begin(), conditions.end());
  const int n = params.images_per_condition * static_cast<int>(conditions.size());

  Project project;
  LineDetector detector(project.detector, project.thresholds);
  for (int i = 0; i < n; ++i) {
    const synth::SynthSample sample = synth::generate(sp, params.seed, i);
    const synth::SampleFiles files = synth::write_sample(sample, dir / "images");
    ImageEntry entry;
    entry.path = "images/" + files.image.filename().generic_string();
    const auto start = std::chrono::steady_clock::now();
    entry.segments = detector.detect(sample.bgr);
    entry.detect_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    // Conditions cycle with the index, so the first images cover every condition.
    if (i < params.labelled_images) {
      label_from_truth(entry.segments, sample.truth);
    } else {
      for (Segment& s : entry.segments) s.label = Label::Unlabelled;
    }
    project.images.push_back(std::move(entry));
  }
  project.save(dir / "project.json");
}

}  // namespace

fs::path default_demo_folder() {
  if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg != nullptr && *xdg != '\0')
    return fs::path(xdg) / "fieldlines" / "demo";
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0')
    return fs::path(home) / ".local" / "share" / "fieldlines" / "demo";
  throw Error("cannot find the user's data folder: neither XDG_DATA_HOME nor HOME is set");
}

fs::path ensure_demo(const DemoParams& params) {
  if (params.images_per_condition < 1 || params.images_per_condition > 1000)
    throw Error("demo: images per condition must be in [1, 1000]");
  if (params.labelled_images < 0) throw Error("demo: labelled images must be >= 0");
  const fs::path dir = params.folder.empty() ? default_demo_folder() : params.folder;
  const fs::path project = dir / "project.json";
  if (fs::exists(project)) return project;

  std::error_code ec;
  fs::create_directories(dir.parent_path(), ec);
  if (ec) throw Error(dir.parent_path().string() + ": cannot create folder (" + ec.message() + ")");
  // Build beside the final folder, then rename: readers see no demo or a whole one.
  std::random_device rd;
  const fs::path tmp = dir.parent_path() / (dir.filename().string() + ".tmp-" + std::to_string(rd()));
  try {
    build_demo(tmp, params);
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
  if (fs::exists(dir) && !fs::exists(project)) fs::remove_all(dir, ec);  // an old incomplete demo
  fs::rename(tmp, dir, ec);
  if (ec) {
    fs::remove_all(tmp, ec);
    if (fs::exists(project)) return project;  // another process finished first
    throw Error(dir.string() + ": cannot create the demo (" + ec.message() + ")");
  }
  return project;
}

}  // namespace fieldlines
