// `fieldlines calibrate PATH... -o robot.json`: thresholds for a new field without a label.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/videoio.hpp>

#include "app/cli/image_inputs.hpp"
#include "app/cli/labelled_data.hpp"
#include "app/cli/output_file.hpp"
#include "app/cli/progress.hpp"
#include "app/cli/subcommand.hpp"
#include "fieldlines/data/image_io.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/data/video_io.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "fieldlines/train/calibrate.hpp"
#include "fieldlines/train/calibration_inputs.hpp"
#include "fieldlines/train/detector_calibration.hpp"
#include "fieldlines/train/stripe_width.hpp"

namespace fieldlines::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHelp = R"(usage: fieldlines calibrate PATH... -o THRESHOLDS [options]

Fits both classes' thresholds (field marking, field boundary) from the colour gradients of the
segments alone: no label is needed, and labels present in the input are never read. Writes an
ordinary thresholds file for the robot (provenance "method": "label-free"). The same input
always gives the same file.

PATH is an image, a folder of images, a video (every N-th frame), a project file or a reference
CSV (its label columns may be missing).

Detector: from images and videos it chooses the detector parameters too and writes them into the
file: ELSED's anchor grid and smoothing (scan interval 2, kernel 5), minimum length 25, the
stripes stage on (markings must be turf, paint, turf; the turf in any of the frame's own turf
colours), no stripe wider than the venue's own stripes allow (1.5 times the widest it marks
near the camera), and a coarse pass where wide near lines break up; the rest, the gradient
threshold included, from --thresholds (default built-in). --keep-detector keeps the detector
parameters of --thresholds instead; segments from a project or CSV keep them always (they were
detected already).

A class the images do not show (no boundary wall, say) is disabled and reported; a weak fit
(few edges, classes that overlap) is kept with a warning. When the markings cannot be fitted
(too few segments, no edge of their colours apart from grey edges), it says why and what to do,
exits with 2 and writes no thresholds file (--json still gets the report, with "refused").

Light: each image's field colour (the median of its green pixels) is measured, every frame's
gradients are scaled by one gain onto the median field brightness of all of them before the fit,
and the file turns the same per-frame adaptation on for the robot ("light": {"adapt",
"reference_field"}), so a frame in shade or against the light keeps its contrast thresholds.

options:
  -o, --output FILE   thresholds file to write (atomically)
  --json REPORT       also write the fit's figures (per class: mode, spread, mass, contrasts,
                      expected precision and recall, warning; "refused" when it refuses)
  --every N           from a video, take every N-th frame (default 10)
  --thresholds FILE   detector parameters and colour classes to start from (default: built-in)
  --keep-detector     do not choose the detector parameters: keep those of --thresholds
  --no-light-adaptation
                      do not map each frame onto one light by its field colour (see below)
  --quiet             no summary on stdout, no progress on stderr
  -h, --help          this help

examples:
  fieldlines calibrate venue-photos/ -o robot.json
  fieldlines calibrate warmup.mp4 --every 15 -o robot.json --json fit.json
  fieldlines calibrate labels.csv -o robot.json && fieldlines eval labels.csv --thresholds robot.json
)";

struct Inputs {
  CalibrationInputs data;
  std::size_t images = 0;  // images, frames, or image entries of a project / CSV
  int failed = 0;          // inputs that could not be read (reported, the rest went on)
};

// What to do with each input: a decoded frame, a project or CSV path, one that could not be
// read (printed once: by the pass that counts it).
struct InputVisitor {
  std::function<void(const cv::Mat&)> frame;
  std::function<void(const std::string&)> data_file = [](const std::string&) {};
  std::function<void()> failed;  // empty: failures are neither printed nor counted
};

void visit_video(const fs::path& path, int every, bool quiet, const InputVisitor& v) {
  cv::VideoCapture capture;
  if (!open_video_file(capture, path.string())) throw Error(path.string() + ": cannot open as a video");
  const double count = capture.get(cv::CAP_PROP_FRAME_COUNT);
  const std::size_t expected = count > 0 ? static_cast<std::size_t>(count) / every + 1 : 0;
  Progress progress("calibrate " + path.filename().string(), expected, stderr,
                    {quiet ? ProgressParams::Mode::Off : ProgressParams::Mode::Auto});
  for_each_nth_frame(capture, every, [&](long, const cv::Mat& frame) {
    if (!frame.empty()) {
      v.frame(frame);
      progress.advance();
    }
    return true;
  });
}

bool is_data_file(const fs::path& path) {
  return is_reference_csv_data(path.string()) || lower_extension(path) == ".json";
}

// Videos and data files in command-line order, then the images (a folder's sorted).
void visit_inputs(const std::vector<std::string>& paths, int every, bool quiet, const InputVisitor& v) {
  std::vector<std::string> image_paths;
  for (const std::string& p : paths) {
    // Images by name first: telling a CSV by its header would read every image once more.
    if (fs::is_directory(p) || has_image_extension(p)) image_paths.push_back(p);
    else if (has_video_extension(p)) visit_video(p, every, quiet, v);
    else if (is_data_file(p)) v.data_file(p);
    else image_paths.push_back(p);  // the image loader names what is wrong with it
  }
  const ImageInputs images = expand_image_inputs(image_paths);
  Progress progress("calibrate", images.images.size(), stderr,
                    {quiet ? ProgressParams::Mode::Off : ProgressParams::Mode::Auto});
  const auto failed = [&](const std::string& message) {
    if (!v.failed) return;
    progress.message("fieldlines calibrate: " + message);
    v.failed();
  };
  for (const FailedImage& f : images.failed) failed(f.error);
  for (const fs::path& image : images.images) {
    std::optional<cv::Mat> frame;
    try {
      frame = load_image(image);
    } catch (const Error& e) {
      failed(e.what());
    }
    if (frame) v.frame(*frame);
    progress.advance();
  }
}

// A project or reference CSV already holds segments: their features, never their labels.
void add_data_file(Inputs& in, const std::string& path) {
  const Project project = load_data_as_project(path);
  for (const ImageEntry& image : project.images) {
    std::vector<Segment> unlabelled = image.segments;
    for (Segment& s : unlabelled) s.label = Label::Unlabelled;
    in.data.add_segments(unlabelled);
    ++in.images;
  }
}

// The frames detected with `params`; each decoded frame also measured into `contrast` if given.
// Unreadable inputs are printed and counted unless `again` (a second pass did that).
Inputs gather(const std::vector<std::string>& paths, const DetectorParams& params, const Thresholds& start,
              int every, bool quiet, FieldContrast* contrast = nullptr, bool again = false) {
  Inputs in;
  in.data.check_stripes(params);
  LineDetector detector(for_fitting(params), start);
  visit_inputs(paths, every, quiet,
               {.frame =
                    [&](const cv::Mat& image) {
                      if (contrast) contrast->add_image(image);
                      in.data.add_image(detector, image);
                      ++in.images;
                    },
                .data_file = [&](const std::string& p) { add_data_file(in, p); },
                .failed = again ? std::function<void()>{} : [&] { ++in.failed; }});
  return in;
}

struct VenueInputs {
  Inputs in;
  DetectorParams detector;
  nlohmann::json provenance;
};

// The detector for the venue (detector_calibration.hpp) and the inputs detected with it; the
// given detector when no frame showed a field (segments from a file) or with --keep-detector.
// Decoding dominates, so one pass measures the contrast while it detects with the detector a
// field gets; a second pass only when the choice turns out otherwise (no field in view) or
// depends on the contrast (follow_contrast).
VenueInputs gather_for_venue(const std::vector<std::string>& paths, const DetectorParams& given,
                             const Thresholds& start, int every, bool quiet, bool keep_detector) {
  if (keep_detector) return {gather(paths, given, start, every, quiet), given, {{"calibrated", false}}};
  const DetectorCalibrationParams rule;
  FieldContrast contrast(rule, given);
  if (rule.follow_contrast) {
    visit_inputs(paths, every, quiet, {.frame = [&](const cv::Mat& image) { contrast.add_image(image); }, .failed = {}});
    const DetectorParams chosen = calibrated_detector(given, contrast, rule);
    return {gather(paths, chosen, start, every, quiet), chosen, detector_provenance(contrast, chosen)};
  }
  const DetectorParams assumed = field_detector(given, rule);
  Inputs in = gather(paths, assumed, start, every, quiet, &contrast);
  const DetectorParams chosen = calibrated_detector(given, contrast, rule);
  if (!(chosen == assumed)) {
    Inputs again = gather(paths, chosen, start, every, true, nullptr, true);
    again.failed = in.failed;
    in = std::move(again);
  }
  return {std::move(in), chosen, detector_provenance(contrast, chosen)};
}

void show_class(const char* name, const ClassCalibration& c, const ClassThresholds& t) {
  if (!c.thresholds) {
    std::printf("%-9s disabled: %s\n", name, c.refused.c_str());
    return;
  }
  std::printf("%-9s min projection %8.3f  max angle %7.3f deg  min length %8.3f", name, t.min_projection,
              t.max_angle_deg, t.min_length);
  if (c.kept_given) std::printf("   (the given thresholds)\n");
  else std::printf("   (mode %.2f +- %.2f deg, %.0f segments)\n", c.mean_deg, c.sd_deg, c.class_mass);
  if (!c.warning.empty()) std::printf("%-9s warning: %s\n", "", c.warning.c_str());
}

}  // namespace

int cmd_calibrate(const Args& args) {
  const auto parsed = parse_or_print_help(args, {"-o", "--output", "--json", "--every", "--thresholds"}, {"--quiet", "--no-light-adaptation", "--keep-detector"}, kHelp);
  if (!parsed) return 0;
  const ParsedArgs& a = *parsed;
  if (a.positionals().empty()) throw Error("expected at least one PATH (see --help)");
  // Before any long work: a bad output path fails now, and never over an input.
  const fs::path output = required_output_path(a, "-o", "THRESHOLDS", a.positionals());
  const std::optional<fs::path> report = output_path(a, "--json", a.positionals());
  const int every = a.int_or("--every", 10, 1, 1'000'000);
  const bool quiet = a.flag("--quiet");
  ThresholdsFile config;
  if (const auto t = a.value("--thresholds")) config = load_thresholds_file(*t);

  const auto t0 = std::chrono::steady_clock::now();
  VenueInputs venue = gather_for_venue(a.positionals(), config.detector, config.thresholds, every, quiet,
                                       a.flag("--keep-detector"));
  Inputs& in = venue.in;
  DetectorParams& detector = venue.detector;
  nlohmann::json& detector_report = venue.provenance;
  const Thresholds start = in.data.image_settings(config.thresholds, !a.flag("--no-light-adaptation"));
  const auto t1 = std::chrono::steady_clock::now();
  Calibration fit = calibrate(in.data.segments(), start, {}, in.data.boundary_candidates(),
                              in.data.marking_candidates());
  keep_given_markings(fit, start, in.data.frames_with_field());
  const double fit_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();
  const double gather_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  nlohmann::json p = calibration_provenance(fit);
  p["inputs"] = a.positionals();
  p["detector"] = detector_report;
  p["counts"] = {{"segments", in.data.segments().size()}, {"images", in.images}, {"failed_inputs", in.failed},
                 {"frames_with_field_colour", in.data.frames_with_field()}};
  // No date: the same input gives the same bytes.
  p["fieldlines_version"] = FIELDLINES_VERSION;
  const auto write_report = [&](nlohmann::json r) {
    if (!report) return;
    r["detect_ms"] = gather_ms;
    r["fit_ms"] = fit_ms;
    write_output_file(*report, r.dump(2) + "\n");
  };
  if (!fit.marking.thresholds) {
    // The report still says why, for the studio and scripts; the thresholds file is not written.
    nlohmann::json r = p;
    r["refused"] = fit.marking.refused;
    write_report(r);
  }
  // Throws (exit 2, no thresholds file) when the markings were refused.
  const Thresholds thresholds = calibrated_thresholds(fit, start);
  calibrate_stripe_width(detector, detector_report, in.data, thresholds);
  p["detector"] = detector_report;

  ThresholdsFile file;
  file.detector = detector;
  file.thresholds = thresholds;
  file.provenance = p;
  save_thresholds_file(output, file);
  nlohmann::json r = p;
  r["refused"] = nullptr;
  r["thresholds_file"] = output.string();
  r["thresholds"] = to_json(file)["classes"];
  write_report(r);

  if (!quiet) {
    std::printf("%zu segments from %zu images; contrast floor %.2f\n", in.data.segments().size(), in.images,
                fit.contrast_floor);
    if (start.light.enabled)
      std::printf("light: %zu frames mapped onto field colour (%.0f, %.0f, %.0f)\n", in.data.frames_with_field(),
                  start.light.reference_field[0], start.light.reference_field[1], start.light.reference_field[2]);
    if (detector_report.value("calibrated", false)) {
      // What the frames chose for the detector: the coarse pass says why it is on or off.
      const double gain = 100 * detector_report.value("coarse_gain", 0.0);
      std::printf("detector: scan interval %d, min length %d, stripes ", detector.scan_interval, detector.min_line_length);
      if (detector.stripes) std::printf("up to %.3f of the height at the bottom; ", detector.stripe_max_width);
      else std::printf("off; ");
      if (detector.coarse_scale > 1)
        std::printf("coarse pass 1/%d from %.0f %% of the height (it adds %.0f %% to the stripes)\n", detector.coarse_scale,
                    100 * detector.coarse_from, gain);
      else
        std::printf("one scale (a coarse pass would add %.0f %% to the stripes)\n", gain);
    }
    show_class("boundary", fit.boundary, thresholds.boundary.thresholds);
    show_class("marking", fit.marking, thresholds.marking.thresholds);
    std::printf("fit in %.1f ms; wrote %s\n", fit_ms, output.c_str());
  }
  return in.failed ? 1 : 0;
}

}  // namespace fieldlines::cli
