// `fieldlines calibrate-camera FRAMES... --camera START.json -o CAMERA.json`: a standing robot's
// camera pitch and roll (and height) from the field lines it sees (train/camera_fit.hpp).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/cli/image_inputs.hpp"
#include "app/cli/output_file.hpp"
#include "app/cli/progress.hpp"
#include "app/cli/subcommand.hpp"
#include "fieldlines/data/image_io.hpp"
#include "fieldlines/detect/camera_file.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "fieldlines/detect/field_place.hpp"
#include "fieldlines/train/camera_fit.hpp"
#include "fieldlines/train/frame_lines.hpp"

namespace fieldlines::cli {
namespace {

namespace fs = std::filesystem;
constexpr double kDeg = std::numbers::pi / 180;

constexpr const char* kHelp = R"(usage: fieldlines calibrate-camera FRAMES... --camera START.json -o CAMERA.json [options]

Fits the camera's pitch and roll from the field's own lines: projected on the ground with the
right pose, a field's lines are all parallel or perpendicular. FRAMES (images or folders) show
the field from one camera whose intrinsics are known and whose pitch, roll and height are the
same in every frame (the robot stands; where it stands and where it looks may differ). The
detector's stripes (the painted lines' centre lines) of all frames are fitted together, from
START.json's pose within 8 degrees (docs/camera_calibration.md). The focal lengths are fitted
too, within a few per cent of START.json's (a lens's focal is rarely known better than that;
the principal point is kept).

The height does not change a direction. With --line-width, the painted width in metres, it
scales the start's height by that width over the stripes' median width on the ground; without
it the start's height is kept (and the report says so).

Writes CAMERA.json (the camera file `fieldlines detect --camera` reads: the intrinsics of
START.json with the fitted pose), atomically, and a report on stdout. Refused with exit code 2
and no file written: START.json unreadable, a camera that sees no ground, frames without enough
lines (2 in 2 directions) or lines that do not pin the pose down (its sd above 0.5 degree),
frames that contradict each other (the lines still stray after the fit), no readable frame.

options:
  --camera FILE       the start camera: intrinsics, pitch, roll, height (camera file)
  -o, --output FILE   the fitted camera file to write
  --line-width M      the painted line width in metres (SPL and Humanoid 0.05, MSL 0.125,
                      SSL 0.01): the height from the stripes' widths
  --thresholds FILE   detector parameters and thresholds (default: built-in); the stripes
                      stage is on whatever the file says
  --json REPORT       also write the fit's figures as JSON
  --place             also say where each frame's camera stands on the field and which way it
                      looks, from the centre circle (the field's origin) and the halfway line
                      through it, with the fitted camera (field_place.hpp); the field is
                      symmetric, so the place is the one with x <= 0 (--positive-half: x >= 0)
  --quiet             no report on stdout, no progress on stderr
  -h, --help          this help

examples:
  fieldlines calibrate-camera standing/ --camera nominal.json -o camera.json --line-width 0.05
  fieldlines calibrate-camera a.png b.png c.png --camera nominal.json -o camera.json --json fit.json
)";

struct Frames {
  std::vector<FrameLines> lines;
  std::vector<fs::path> images;  // parallel to lines
  int failed = 0;  // images that could not be read (reported, the rest went on)
};

// Each readable image's stripes, with a progress bar; unreadable ones reported and counted.
Frames detect_frames(const std::vector<std::string>& paths, FrameLinesDetector& detector, bool quiet) {
  const ImageInputs inputs = expand_image_inputs(paths);
  Frames out;
  Progress progress("calibrate-camera", inputs.images.size(), stderr,
                    {quiet ? ProgressParams::Mode::Off : ProgressParams::Mode::Auto});
  for (const FailedImage& f : inputs.failed) {
    progress.message("fieldlines calibrate-camera: " + f.error);
    ++out.failed;
  }
  for (const fs::path& image : inputs.images) {
    try {
      out.lines.push_back(detector.detect(image));
      out.images.push_back(image);
    } catch (const Error& e) {
      progress.message("fieldlines calibrate-camera: " + std::string(e.what()));
      ++out.failed;
    }
    progress.advance();
  }
  return out;
}

double deg(double rad) { return rad / kDeg; }

// --place: each frame's place on the field through the fitted camera (field_place.hpp), from the
// centre circle and the halfway line its detector finds with every feature stage on.
std::vector<std::optional<FieldPlace>> frame_places(const Frames& frames, const GroundCamera& camera,
                                                    const ThresholdsFile& config, bool negative_half) {
  LineDetector detector(with_every_feature(config.detector), config.thresholds);
  detector.set_camera(camera);
  std::vector<std::optional<FieldPlace>> out;
  for (const fs::path& image : frames.images) {
    detector.detect(load_image(image));
    out.push_back(place_from_centre_circle(detector.ground_features(), {.negative_half = negative_half}));
  }
  return out;
}

nlohmann::json place_json(const std::optional<FieldPlace>& p) {
  if (!p) return nullptr;
  return {{"x_m", p->x_m}, {"y_m", p->y_m}, {"yaw_deg", deg(p->yaw_rad)}, {"halfway_pieces", p->halfway_pieces}};
}

nlohmann::json report_json(const CameraFit& fit, const GroundCamera& start, const Frames& frames,
                           const std::optional<double>& line_width,
                           const std::vector<std::optional<FieldPlace>>& places) {
  nlohmann::json per_frame = nlohmann::json::array();
  for (std::size_t i = 0; i < frames.lines.size(); ++i) {
    const double share = fit.frame_fitting_share[i];
    per_frame.push_back({{"image", frames.lines[i].name},
                         {"lines", frames.lines[i].markings.size()},
                         {"fitting_share", std::isnan(share) ? nlohmann::json(nullptr) : nlohmann::json(share)}});
    if (!places.empty()) per_frame.back()["place"] = place_json(places[i]);
  }
  return {{"frames", frames.lines.size()},
          {"failed_inputs", frames.failed},
          {"frames_used", fit.frames_used},
          {"lines_used", fit.lines_used},
          {"start", to_json(start)},
          {"camera", to_json(fit.camera)},
          {"rms_before_deg", fit.rms_before_deg},
          {"rms_after_deg", fit.rms_after_deg},
          {"focal_scale", fit.focal_scale},
          {"fitting_share", fit.fitting_share},
          {"pitch_sd_deg", fit.pitch_sd_deg},
          {"roll_sd_deg", fit.roll_sd_deg},
          {"height", {{"fitted", fit.height_fitted},
                      {"line_width_m", line_width ? nlohmann::json(*line_width) : nlohmann::json(nullptr)},
                      {"median_stripe_width_m", fit.median_width_m},
                      {"stripes", fit.widths_used}}},
          {"per_frame", per_frame}};
}

// Where each frame's camera stands, when --place asked (frames without the circle and the
// halfway line say so).
void print_places(const Frames& frames, const std::vector<std::optional<FieldPlace>>& places) {
  for (std::size_t i = 0; i < places.size(); ++i) {
    const std::string name = frames.images[i].filename().string();
    if (const auto& p = places[i])
      std::printf("%s: at (%.2f, %.2f) m, heading %.1f deg (the centre circle and %d piece(s) of the halfway line)\n",
                  name.c_str(), p->x_m, p->y_m, deg(p->yaw_rad), p->halfway_pieces);
    else
      std::printf("%s: no place (no centre circle with the halfway line through it)\n", name.c_str());
  }
}

void print_report(const CameraFit& fit, const GroundCamera& start, const Frames& frames, const fs::path& output) {
  std::printf("frames: %d of %zu used (%d unreadable), %d lines\n", fit.frames_used, frames.lines.size(), frames.failed,
              fit.lines_used);
  std::printf("pitch %.2f -> %.2f deg, roll %.2f -> %.2f deg (sd %.2f, %.2f for 1 px on the lines' ends)\n",
              deg(start.pitch_rad), deg(fit.camera.pitch_rad), deg(start.roll_rad), deg(fit.camera.roll_rad),
              fit.pitch_sd_deg, fit.roll_sd_deg);
  if (fit.focal_scale != 1)
    std::printf("fx %.1f -> %.1f, fy %.1f -> %.1f (x%.3f)\n", start.fx, fit.camera.fx, start.fy, fit.camera.fy,
                fit.focal_scale);
  std::printf("residual %.2f -> %.2f deg RMS (the better-fitting half of the lines); %.0f %% of the lines' weight fits\n",
              fit.rms_before_deg, fit.rms_after_deg, 100 * fit.fitting_share);
  if (fit.height_fitted)
    std::printf("height %.3f -> %.3f m, from %d stripes' median ground width (%.1f mm at the start height)\n",
                start.height_m, fit.camera.height_m, fit.widths_used, 1000 * fit.median_width_m);
  else
    std::printf("height %.3f m kept from the start camera (no --line-width: directions do not see the height)\n",
                start.height_m);
  std::printf("wrote %s\n", output.string().c_str());
}

}  // namespace

int cmd_calibrate_camera(const Args& args) {
  const auto parsed = parse_or_print_help(args, {"--camera", "-o", "--output", "--json", "--thresholds", "--line-width"},
                                          {"--quiet", "--place", "--positive-half"}, kHelp);
  if (!parsed) return 0;
  const ParsedArgs& a = *parsed;
  if (a.positionals().empty()) throw Error("expected at least one image or folder (see --help)");
  const auto camera_path = a.value("--camera");
  if (!camera_path) throw Error("missing --camera START.json (see --help)");
  // Before any long work: bad paths and values fail now, and never over an input.
  std::vector<std::string> inputs = a.positionals();
  inputs.push_back(*camera_path);
  const fs::path output = required_output_path(a, "-o", "CAMERA.json", inputs);
  const std::optional<fs::path> report = output_path(a, "--json", inputs);
  CameraFitParams params;
  if (a.has("--line-width")) params.line_width_m = a.double_or("--line-width", 0, 0.001, 0.5);
  const GroundCamera start = load_camera_file(*camera_path);
  ThresholdsFile config;
  if (const auto t = a.value("--thresholds")) config = load_thresholds_file(*t);
  const bool quiet = a.flag("--quiet");
  const bool place = a.flag("--place");
  if (a.flag("--positive-half") && !place) throw Error("--positive-half goes with --place");

  FrameLinesDetector detector(config.detector, config.thresholds);  // stripes on
  const Frames frames = detect_frames(a.positionals(), detector, quiet);
  if (frames.lines.empty()) throw Error("no readable frame among the inputs");
  const CameraFit fit = fit_camera(frames.lines, start, params);

  write_output_file(output, to_json(fit.camera).dump(2) + "\n");
  std::vector<std::optional<FieldPlace>> places;
  if (place) places = frame_places(frames, fit.camera, config, !a.flag("--positive-half"));
  if (report) write_output_file(*report, report_json(fit, start, frames, params.line_width_m, places).dump(2) + "\n");
  if (!quiet) {
    print_report(fit, start, frames, output);
    print_places(frames, places);
  }
  return frames.failed ? 1 : 0;
}

}  // namespace fieldlines::cli
