// `fieldlines detect`: detect and classify field lines in images or folders.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "app/cli/detections_json.hpp"
#include "app/cli/detector_params_help.hpp"
#include "fieldlines/detect/camera_file.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/image_io.hpp"
#include "fieldlines/data/overlay.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "app/cli/image_inputs.hpp"
#include "app/cli/output_file.hpp"
#include "app/cli/overlay_files.hpp"
#include "app/cli/parallel_batch.hpp"
#include "app/cli/progress.hpp"
#include "app/cli/subcommand.hpp"
#include "app/cli/video_stream.hpp"

namespace fieldlines::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHelp = R"(usage: fieldlines detect [options] PATH...
       fieldlines detect [--thresholds FILE] --video FILE|/dev/videoN [--video-out OUT.avi] [--max-frames N]

Detects line segments in each image (PATH is an image or a folder of images, read in
file-name order), measures their colour gradients and classifies them as field marking,
field boundary or none. Prints one summary line per image on stdout.

options:
  --thresholds FILE detector parameters (listed below) and classification thresholds from a
                    thresholds file (as `fieldlines train` writes it); default: the reference's
  --json OUT        write every segment to OUT (schema: docs/detect_and_bench.md)
  --csv OUT         write every segment in the reference annotation CSV format
                    (img_path = file name, B,G,R channels, reference y sign, label columns)
  --draw DIR        write an overlay per image to DIR/<name>.png
                    (the studio's palette: marking magenta, boundary blue, none yellow,
                    each over a dark outline; legend top-left; with field features
                    drawn, theirs top-right); segments above the field boundary
                    (stands, walls, lights) faint, so what lies on the field reads first
  --draw-all        ... every segment at full strength, above the field boundary too
  --stripes         keep only markings that are painted stripes (turf, paint, turf) and write
                    their centre lines and widths ("markings" in --json); the thresholds file's
                    "stripes" parameter otherwise (default off: the reference's behaviour)
  --no-stripes      the stage off, whatever the thresholds file says
  --features        every field feature stage on: the stripes, their L/T/X intersections
                    ("intersections" in --json) and the centre circle ("ellipses"); each is
                    also a thresholds file parameter (stripes, intersections, centre_circle).
                    The circle draws the frame a second time (1.5-2.1x a plain detect in all);
                    without it, stripes and junctions cost about 1.1-1.2x
  --camera FILE     a fixed camera over the field (a camera file: intrinsics, pitch, roll and
                    height; docs/detector.md): the centre circle is also fitted on the turf as
                    a circle of the thresholds file's centre_circle_radius, which finds one the
                    frame shows a single arc of; --json adds each image's features on the ground
                    ("ground": metres from the camera's foot, soccer_vision_3d_msgs names, each
                    point's covariance from 1 degree of pitch and roll noise)
  --threads N       images processed in parallel, one detector per thread (default 1);
                    outputs keep the input order
  --quiet           no per-image lines on stdout, no progress on stderr
  --video SRC       process a video file or a camera (/dev/videoN) frame by frame, with a
                    live frames-per-second and latency readout on stderr
  --video-out OUT   with --video: write the overlays as an MJPG video (.avi)
  --max-frames N    with --video: stop after N frames
  --steady MS       with --video and --camera: junctions and the centre circle held steady on
                    the ground over the stream (a feature missed for up to MS milliseconds is
                    kept; steady_features.hpp), and a summary of how often each was seen and
                    held; off by default, as on the robot
  -h, --help        this help

A bad file (missing, corrupt, empty, unsupported pixel type, too large) is reported on
stderr and skipped; the batch goes on and the exit code is 1 at the end.
Exit codes: 0 all images processed, 1 some failed, 2 usage or fatal error.

)";

constexpr const char* kExamples = R"(
examples:
  fieldlines detect frame.png
  fieldlines detect --json out/lines.json --draw out/overlays ../shared/data/elsed-ssl/images
  fieldlines detect --threads 2 --quiet --json lines.json a.png b.jpg more_frames/
  fieldlines detect --thresholds trained.json --csv segments.csv frames/
  fieldlines detect --video match.mp4 --video-out match-lines.avi
  fieldlines detect --thresholds robot.json --video /dev/video0 --max-frames 600
  fieldlines detect --features --camera head.json --json out/lines.json frames/
)";

// The options, the detector parameters a --thresholds file sets, the examples.
std::string help_text() { return kHelp + detector_params_help() + kExamples; }

struct Options {
  std::optional<fs::path> thresholds, json, csv, draw;  // json and csv checked as output paths
  int threads = 1;
  bool quiet = false;
  bool draw_all = false;  // overlays: segments above the field boundary at full strength
  std::optional<GroundCamera> camera;
  std::optional<bool> stripes;  // overrides the thresholds file's
  bool features = false;        // turns every feature stage on
  std::vector<std::string> paths;
  std::optional<std::string> video;
  std::optional<fs::path> video_out;
  long max_frames = -1;
  std::optional<double> steady_ms;
};

void apply_feature_options(const Options& opt, DetectorParams& params) {
  if (opt.stripes) params.stripes = *opt.stripes;
  if (opt.features) params = with_every_feature(params);
}

// Output files are checked here, before a possibly long batch, not after it.
Options parse(const ParsedArgs& a) {
  Options o;
  if (const auto v = a.value("--thresholds")) o.thresholds = *v;
  o.json = output_path(a, "--json");
  o.csv = output_path(a, "--csv");
  if (const auto v = a.value("--draw")) o.draw = *v;
  o.threads = a.int_or("--threads", 1, 1, 256);
  o.quiet = a.flag("--quiet");
  o.draw_all = a.flag("--draw-all");
  if (o.draw_all && !o.draw) throw Error("--draw-all needs --draw DIR");
  if (const auto v = a.value("--camera")) o.camera = load_camera_file(*v);
  if (a.flag("--stripes") && a.flag("--no-stripes")) throw Error("--stripes and --no-stripes exclude each other");
  if (a.flag("--stripes")) o.stripes = true;
  if (a.flag("--no-stripes")) o.stripes = false;
  o.features = a.flag("--features");
  if (o.features && o.stripes == false) throw Error("--features and --no-stripes exclude each other");
  o.paths = a.positionals();
  o.video = a.value("--video");
  o.video_out = output_path(a, "--video-out");
  o.max_frames = a.int_or("--max-frames", -1, 1, 1 << 30);
  if (a.value("--steady")) {
    o.steady_ms = a.double_or("--steady", 80, 0, 10000);
    if (!o.video || !o.camera) throw Error("--steady needs --video and --camera (it holds features on the ground)");
  }
  return o;
}

// Prefixes the path unless the message already starts with it (image_io's messages do).
std::string with_path(const fs::path& path, const std::string& message) {
  const std::string p = path.string();
  return message.rfind(p, 0) == 0 ? message : p + ": " + message;
}

struct ItemResult {
  std::optional<ImageDetections> detections;
  std::optional<std::string> error;
};

std::string summary_line(const ImageDetections& d) {
  std::map<Label, int> counts;
  for (const Segment& s : d.segments) ++counts[s.label];
  char buf[160];
  std::snprintf(buf, sizeof buf, ": %zu segments (%d marking, %d boundary, %d none), %dx%d, %.2f ms",
                d.segments.size(), counts[Label::Marking], counts[Label::Boundary], counts[Label::None],
                d.width, d.height, d.detect_ms);
  return d.path.string() + buf;
}

}  // namespace

int cmd_detect(const Args& args) {
  const auto parsed = parse_or_print_help(
      args, {"--thresholds", "--json", "--csv", "--draw", "--threads", "--video", "--video-out", "--max-frames",
             "--camera", "--steady"},
      {"--quiet", "--stripes", "--no-stripes", "--features", "--draw-all"}, help_text());
  if (!parsed) return 0;
  const Options opt = parse(*parsed);
  if (opt.video) {
    if (!opt.paths.empty() || opt.json || opt.csv || opt.draw)
      throw Error("--video takes no PATH, --json, --csv or --draw (use --video-out for overlays)");
    ThresholdsFile video_config;
    if (opt.thresholds) video_config = load_thresholds_file(*opt.thresholds);
    apply_feature_options(opt, video_config.detector);
    return run_video_detection({*opt.video, opt.video_out, opt.max_frames, opt.quiet, opt.camera, opt.steady_ms},
                               video_config);
  }
  if (opt.video_out || opt.max_frames >= 0) throw Error("--video-out and --max-frames go with --video");
  if (opt.paths.empty()) throw Error("no PATH given: name at least one image or folder (see --help)");
  if (opt.draw) {
    make_overlay_folder(*opt.draw);
  }

  ThresholdsFile config;  // defaults: the reference's parameters and thresholds
  if (opt.thresholds) config = load_thresholds_file(*opt.thresholds);
  apply_feature_options(opt, config.detector);
  ImageInputs inputs = expand_image_inputs(opt.paths);
  const std::vector<fs::path>& images = inputs.images;
  const auto overlays = opt.draw ? overlay_paths(images, *opt.draw) : std::vector<fs::path>{};

  ProgressParams progress_params;
  if (opt.quiet) progress_params.mode = ProgressParams::Mode::Off;
  Progress progress("detect", images.size(), stderr, progress_params);
  for (const auto& f : inputs.failed) progress.message("fieldlines detect: " + f.error);

  const int workers = std::max(1, std::min<int>(opt.threads, static_cast<int>(images.size())));
  std::vector<LineDetector> detectors;
  for (int w = 0; w < workers; ++w) {
    detectors.emplace_back(config.detector, config.thresholds);
    detectors.back().set_find_field_boundary(opt.json || opt.draw);  // both show it
    detectors.back().set_camera(opt.camera);
  }

  std::vector<ItemResult> results(images.size());
  run_parallel_batch(images.size(), workers, [&](std::size_t i, int worker) {
    const fs::path& path = images[i];
    try {
      const cv::Mat image = load_image(path);
      ImageDetections d;
      d.path = path;
      d.width = image.cols;
      d.height = image.rows;
      const auto t0 = std::chrono::steady_clock::now();
      LineDetector& detector = detectors[static_cast<std::size_t>(worker)];
      detector.detect(image, d.segments);
      d.detect_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      d.field_boundary = detector.field_boundary().points;
      const FieldFeatures& features = detector.features();
      d.markings = features.markings;
      d.intersections = features.intersections;
      d.ellipses = features.ellipses;
      if (opt.camera) d.ground = detector.ground_features();
      if (opt.draw) {
        OverlayParams look;
        look.field_boundary = &detector.field_boundary();
        if (opt.draw_all) look.above_opacity = 1;
        cv::Mat overlay = draw_overlay(image, d.segments, look);
        draw_field_features(overlay, features);
        write_overlay(overlays[i], overlay);
      }
      results[i].detections = std::move(d);
    } catch (const std::bad_alloc&) {
      results[i].error = with_path(path, "out of memory (image too large?)");
    } catch (const std::exception& e) {
      results[i].error = with_path(path, e.what());
    }
    if (results[i].error) progress.message("fieldlines detect: " + *results[i].error);
    progress.advance();
  });
  progress.finish();

  const std::size_t input_count = images.size() + inputs.failed.size();
  std::vector<ImageDetections> done;
  std::vector<FailedImage> failed = std::move(inputs.failed);
  std::size_t total_segments = 0;
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (results[i].detections) {
      total_segments += results[i].detections->segments.size();
      if (!opt.quiet) std::printf("%s\n", summary_line(*results[i].detections).c_str());
      done.push_back(std::move(*results[i].detections));
    } else {
      failed.push_back({images[i], results[i].error.value_or("unknown error")});
    }
  }
  if (opt.json) write_output_file(*opt.json, detections_json(done, failed).dump() + "\n");
  if (opt.csv) {
    std::vector<ReferenceRow> rows;
    for (const auto& d : done)
      for (const Segment& s : d.segments) rows.push_back({d.path.filename().string(), s});
    write_reference_csv(*opt.csv, rows);
  }

  if (!opt.quiet) {
    std::printf("%zu segments in %zu image%s", total_segments, done.size(), done.size() == 1 ? "" : "s");
    if (!failed.empty()) std::printf(", %zu failed", failed.size());
    std::printf("\n");
    if (opt.json) std::printf("segments written to %s\n", opt.json->string().c_str());
    if (opt.csv) std::printf("reference CSV written to %s\n", opt.csv->string().c_str());
    if (opt.draw) std::printf("overlays written to %s\n", opt.draw->string().c_str());
  }
  if (!failed.empty())
    std::fprintf(stderr, "fieldlines detect: %zu of %zu input%s failed (see the messages above)\n", failed.size(),
                 input_count, input_count == 1 ? "" : "s");
  return failed.empty() ? 0 : 1;
}

}  // namespace fieldlines::cli
