// `fieldlines bench`: our detector against OpenCV's line detectors, same process, same images.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "app/cli/args.hpp"
#include "app/cli/commands.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/image_io.hpp"
#include "app/cli/image_inputs.hpp"
#include "app/cli/output_file.hpp"
#include "app/cli/progress.hpp"
#include "bench/peers/peer_detectors.hpp"

namespace fieldlines::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHelp = R"(usage: fieldlines bench [options] PATH...

Times, in this process, on the same colour images and on one thread (cv::setNumThreads(1);
our rows may take more with --detector-threads):
  fieldlines  our LineDetector: ELSED + colour gradients + classification
  edlines     OpenCV ximgproc EdgeDrawing in EDLines mode (detectEdges + detectLines)
  fld         OpenCV ximgproc FastLineDetector
  lsd         OpenCV LineSegmentDetector
  gradients   our gradient stage alone: one fused pass (grey, Gaussian, Sobel x/y, magnitude,
              direction), what the fieldlines row starts with
  floor       cvtColor + 5x5 Gaussian + Sobel x and y: what any gradient-based detector pays
Each call starts from the BGR image (grey conversion is timed). Detectors are interleaved image
by image so that machine load affects them alike. Prints the median and 90th percentile ms per
image, segments per image and the ratio ours/theirs, then checks the targets
ours <= 0.4 x edlines and ours <= 1.5 x floor (--floor-target), and prints gradients/floor.
PATH is an image or a folder; images that fail to load are reported and skipped (exit 1).

options:
  --repeat N    timed passes over all images (default 5); one untimed warm-up pass first
  --floor-target X  the ours/floor ratio to check (default 1.5, the SSL target; the Humanoid
                frames, larger and busier, have 2)
  --scale WxH   resize every loaded image to W x H pixels (cv::resize, INTER_LINEAR; stretched
                if the aspect ratio differs) before timing, e.g. 1280x720 or 1920x1080;
                W and H in [8, 8192]
  --detector-threads N  DetectorParams::threads for the fieldlines and gradients rows (default
                1, in [1, 64]): the gradient pass runs in N row bands at once; the peers and the
                floor stay on one thread
  --json OUT    write {"images":N,"scale":{"width","height"} (with --scale),"detector_threads":N,
                "detectors":[{"name","median_ms","p90_ms","segments_per_image"}]}
  --quiet       no progress on stderr
  -h, --help    this help

examples:
  fieldlines bench ../shared/data/elsed-ssl/images
  fieldlines bench --repeat 20 --json bench.json frame.png
  fieldlines bench --quiet --repeat 10 --scale 1920x1080 --detector-threads 2 ../shared/data/elsed-ssl/images
)";

// Linear interpolation between closest ranks (the usual "type 7" quantile).
double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(pos);
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

struct Timing {
  std::string name;
  std::vector<double> ms;
  double segments = 0;  // summed over the first timed pass
  double median() const { return quantile(ms, 0.5); }
  double p90() const { return quantile(ms, 0.9); }
};

// "WxH", both sides in [8, 8192] (FLD and LSD need a few pixels; 8192 keeps a frame's maps
// far below any int overflow).
cv::Size parse_scale(const std::string& text) {
  const auto bad = [&] {
    return Error("--scale: expected WxH with W and H whole numbers in [8, 8192] (e.g. 1280x720), got '" + text + "'");
  };
  const std::size_t x = text.find('x');
  if (x == std::string::npos) throw bad();
  try {
    return {parse_int(std::string_view(text).substr(0, x), "--scale", 8, 8192),
            parse_int(std::string_view(text).substr(x + 1), "--scale", 8, 8192)};
  } catch (const Error&) {
    throw bad();
  }
}

}  // namespace

int cmd_bench(const Args& args) {
  const ParsedArgs a(args, {"--json", "--repeat", "--floor-target", "--scale", "--detector-threads"}, {"--quiet", "--help", "-h"});
  if (a.flag("--help") || a.flag("-h")) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (a.positionals().empty()) throw Error("no PATH given: name at least one image or folder (see --help)");
  const int repeat = a.int_or("--repeat", 5, 1, 100000);
  const double floor_target = a.double_or("--floor-target", 1.5, 0.1, 100);
  const std::optional<cv::Size> scale =
      a.has("--scale") ? std::optional<cv::Size>(parse_scale(*a.value("--scale"))) : std::nullopt;
  DetectorParams params;
  params.threads = a.int_or("--detector-threads", 1, 1, 64);
  const std::optional<fs::path> json_out = a.has("--json") ? std::optional<fs::path>(*a.value("--json")) : std::nullopt;
  if (json_out) check_output_path("--json", *json_out);

  ImageInputs inputs = expand_image_inputs(a.positionals());
  std::vector<FailedImage> failed = std::move(inputs.failed);
  std::vector<cv::Mat> images;
  for (const auto& path : inputs.images) {
    try {
      // Every detector gets the same 8-bit BGR frame, as a robot's camera delivers it.
      cv::Mat bgr = to_bgr8(load_image(path)).clone();
      if (scale) cv::resize(bgr, bgr, *scale, 0, 0, cv::INTER_LINEAR);
      images.push_back(std::move(bgr));
    } catch (const std::exception& e) {
      failed.push_back({path, e.what()});
    }
  }
  for (const auto& f : failed) std::fprintf(stderr, "fieldlines bench: %s\n", f.error.c_str());
  if (images.empty()) throw Error("no image could be loaded, nothing to time");

  // Single thread for everyone: OpenCV would otherwise parallelise some peers and not others.
  const int previous_threads = cv::getNumThreads();
  cv::setNumThreads(1);
  auto detectors = peers::make_timed_detectors(params);
  std::vector<Timing> timings;
  for (const auto& d : detectors) timings.push_back({d.name, {}, 0});

  ProgressParams pp;
  if (a.flag("--quiet")) pp.mode = ProgressParams::Mode::Off;
  {
    Progress progress("bench", images.size() * static_cast<std::size_t>(repeat + 1), stderr, pp);
    for (int pass = -1; pass < repeat; ++pass) {  // pass -1 warms caches and buffers, untimed
      for (std::size_t i = 0; i < images.size(); ++i) {
        // Rotate the starting detector per image so none always runs on a cold cache.
        for (std::size_t k = 0; k < detectors.size(); ++k) {
          const std::size_t d = (i + k) % detectors.size();
          const auto t0 = std::chrono::steady_clock::now();
          const std::size_t count = detectors[d].run(images[i]);
          const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
          if (pass >= 0) timings[d].ms.push_back(ms);
          if (pass == 0) timings[d].segments += static_cast<double>(count);
        }
        progress.advance();
      }
    }
  }
  cv::setNumThreads(previous_threads);

  const double ours = timings[0].median();
  auto find = [&](const std::string& name) {
    return std::find_if(timings.begin(), timings.end(), [&](const Timing& t) { return t.name == name; })->median();
  };
  const std::string size_note = scale ? cv::format(" scaled to %dx%d", scale->width, scale->height) : "";
  const std::string thread_note =
      params.threads == 1 ? "single thread"
                          : cv::format("single thread (fieldlines and gradients: %d detector threads)", params.threads);
  std::printf("%zu image%s%s x %d pass%s, %s, median over all timed calls\n\n", images.size(),
              images.size() == 1 ? "" : "s", size_note.c_str(), repeat, repeat == 1 ? "" : "es", thread_note.c_str());
  std::printf("%-11s %10s %10s %14s %12s\n", "detector", "median ms", "p90 ms", "segments/img", "ours/this");
  nlohmann::ordered_json detectors_json = nlohmann::ordered_json::array();
  for (const auto& t : timings) {
    const double per_image = t.segments / static_cast<double>(images.size());
    std::printf("%-11s %10.3f %10.3f %14.1f %12.2f\n", t.name.c_str(), t.median(), t.p90(), per_image,
                ours / t.median());
    detectors_json.push_back(
        {{"name", t.name}, {"median_ms", t.median()}, {"p90_ms", t.p90()}, {"segments_per_image", per_image}});
  }
  const double vs_edlines = ours / find("edlines");
  const double vs_floor = ours / find("floor");
  std::printf("\ntargets: fieldlines/edlines = %.2f (<= 0.40: %s), fieldlines/floor = %.2f (<= %.2f: %s)\n",
              vs_edlines, vs_edlines <= 0.4 ? "met" : "NOT met", vs_floor, floor_target,
              vs_floor <= floor_target ? "met" : "NOT met");
  std::printf("gradients/floor = %.2f (our fused gradient pass against OpenCV's blur + Sobel)\n",
              find("gradients") / find("floor"));

  if (json_out) {
    nlohmann::ordered_json j{{"images", images.size()}};
    if (scale) j["scale"] = {{"width", scale->width}, {"height", scale->height}};
    j["detector_threads"] = params.threads;
    j["detectors"] = detectors_json;
    write_output_file(*json_out, j.dump(2) + "\n");
    std::printf("results written to %s\n", json_out->string().c_str());
  }
  return failed.empty() ? 0 : 1;
}

}  // namespace fieldlines::cli
