// `fieldlines eval --gt DIR`: detection + classification scored against synthetic ground truth.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/synth/camera.hpp"
#include "fieldlines/synth/feature_truth.hpp"
#include "fieldlines/synth/field.hpp"
#include "fieldlines/synth/ground_score.hpp"
#include "fieldlines/synth/gt_eval.hpp"
#include "fieldlines/synth/centre_line_score.hpp"
#include "fieldlines/synth/hand_truth.hpp"
#include "app/cli/eval_overlay.hpp"
#include "app/cli/overlay_files.hpp"
#include "fieldlines/data/image_io.hpp"
#include "fieldlines/synth/synth.hpp"
#include "fieldlines/train/percentile.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "app/cli/subcommand.hpp"
#include "app/cli/synth_set.hpp"

namespace fieldlines::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHelp = R"(usage: fieldlines eval --gt DIR [DIR...] [--thresholds FILE] [options]
       fieldlines eval --hand DIR [DIR...] --data DATA [--thresholds FILE] [options]

Detects and classifies the segments of every image of synthetic sets (made by `fieldlines
synth`; each image's truth is DIR/truth/<name>.json) and scores them against the exact ground
truth, per scene and lighting condition and pooled. With --hand, the images are real frames
under DATA and their truth is drawn by hand (DIR/<name>.json, schema fieldlines-hand-truth, as
in tests/data/hand_truth); the rows are the folders, and a second table scores the detected
field boundary against the drawn one on the columns it spans (within 4 px, within 2 % of the
frame's height, median error; a frame where no field was found counts its height) and the
stripes' centre lines (what the robot takes from the stripes stage) against the drawn lines'
centres: precision, the share of their length within half the line's width + 1 px of a drawn
line's centre (parallel within 10 degrees); recall, the share of the drawn lines' visible
centre-line length so near a stripe's. Scores:
  precision  predicted segments of a class whose truth label agrees (a segment's truth label is
             the class whose line edges it follows for >= 60% of its length, within 2.5 px and
             10 degrees; otherwise none)
  recall     share of the visible line-edge length covered by segments predicted as that class
             (both edges of a painted line count; parts under --min-width px are not visible)

options:
  --gt DIR           a synthetic set (more sets as extra arguments)
  --hand DIR         a folder of hand-truth files (more folders as extra arguments)
  --data DATA        the folder the hand-truth files' "image" paths are relative to
  --thresholds FILE  detector parameters and thresholds (default: the built-in defaults)
  --features         every field feature stage on (stripes, intersections, centre circle); with
                     --gt, and whenever the thresholds turn intersections or the centre circle
                     on, a second table scores them against the truth of the frames' field and
                     camera: intersections matched within 6 px (precision, recall, type correct
                     of matched) and the centre circle found on frames showing >= 30 % of it
                     (centre within 10 % of its radius; wrong: ellipses matching no circle),
                     the field boundary (share of the columns showing carpet where it is within
                     4 px of the carpet's top) and the markings (share of the pixels along the
                     stripes' centre lines within half the line's width + 1 px of a line's centre)
  --truth-camera     give the detector each frame's camera from its truth (intrinsics, pitch,
                     roll, height: what a robot's kinematics know) and its field's centre circle
                     radius, so the circle is also fitted on the turf (--gt only); with
                     --features a third table scores the features on the ground: each matched
                     junction's error over its true distance, the circle's centre error within 4 m
  --camera-error DEG,FRAC
                     with --truth-camera: the camera given is off, its pitch and roll each by up
                     to DEG degrees and its height by up to FRAC of it (uniform, drawn per frame
                     from its seed and index: the same every run), as a robot's pose estimate is
  --max-distance PX  edge match distance (default 2.5)
  --min-width PX     painted parts narrower than this are not visible: they do not count in
                     recall, nor in the truth of junctions, their arms and the circle (default 1)
  --per-image        also one row per image, under its group's row (in the boundary table too):
                     which frames a set's figures come from
  --markdown         print the table as Markdown
  --json OUT         write the scores as JSON (per group and total; with --per-image each group's
                     "per_image" too)
  --draw DIR         an overlay per image, DIR/<truth folder>/<name>.png: the segments as
                     `fieldlines detect --draw` draws them, and every truth line edge dotted green
                     where a segment of its class lies on it (what recall counts), red where only
                     a segment of another label does (the classification lost it), cyan where no
                     segment does (the detector missed it); with --hand, the drawn field boundary
                     solid green beside the detected one (dashed white)
  -h, --help         this help
Exit codes: 0 ok, 1 some images could not be read (they are skipped), 2 usage or fatal error.

examples:
  fieldlines eval --gt synth/ssl_test
  fieldlines eval --gt synth/ssl_test synth/kid_test --thresholds robot.json --markdown
  fieldlines eval --hand tests/data/hand_truth/msl-bangkok --data ../shared/data --thresholds msl.json
  fieldlines eval --hand tests/data/hand_truth/humanoid --data ../shared/data --draw overlays
  fieldlines eval --hand tests/data/hand_truth/ssl --data ../shared/data --thresholds ssl.json --per-image
)";

// The detected field boundary against a hand-drawn one, per column the hand's polylines span: the
// error in px (the frame's height where the detector found no field), and how many are within
// 2 % of the frame's height (a real frame's drawing is accurate to about 1.5 px).
struct HandBoundary {
  std::vector<double> errors_px;
  long within_share = 0;
  static constexpr double kShare = 0.02;
  HandBoundary& operator+=(const HandBoundary& o) {
    errors_px.insert(errors_px.end(), o.errors_px.begin(), o.errors_px.end());
    within_share += o.within_share;
    return *this;
  }
};

HandBoundary score_hand_boundary(const std::vector<float>& truth_rows, const FieldBoundary& detected, int height) {
  HandBoundary out;
  for (std::size_t x = 0; x < truth_rows.size(); ++x) {
    if (truth_rows[x] < 0) continue;
    const double e = detected.empty() ? height : std::abs(detected.y_at(float(x)) - truth_rows[x]);
    out.errors_px.push_back(e);
    out.within_share += e <= HandBoundary::kShare * height;
  }
  return out;
}

struct Group {
  GtScore score;
  synth::FeatureScore features;
  synth::GroundScore ground;  // with --truth-camera and the features
  HandBoundary hand_boundary;
  synth::CentreLineScore centre_lines;
  double detect_ms = 0;
  Group& operator+=(const Group& o) {
    score += o.score, features += o.features, ground += o.ground;
    hand_boundary += o.hand_boundary, centre_lines += o.centre_lines, detect_ms += o.detect_ms;
    return *this;
  }
};

// One image's own scores (--per-image), under its group.
struct ImageGroup {
  std::string name;
  Group group;
};

// A row of the tables: a scene and condition's (or a hand-truth folder's) scores, and with
// --per-image each of its images'.
struct GroupRow {
  Group sum;
  std::vector<ImageGroup> images;
};


// "-" where a score is undefined (nothing predicted, or nothing visible: Kid has no wall).
std::string fmt(double value, bool defined) {
  if (!defined) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", value);
  return buf;
}

void print_row(bool markdown, const std::string& scene, const std::string& condition, const Group& g) {
  const GtScore& s = g.score;
  const double ms = s.images > 0 ? g.detect_ms / s.images : 0;
  const std::string mp = fmt(s.marking.precision(), s.marking.predicted > 0);
  const std::string mr = fmt(s.marking.recall(), s.marking.visible_px > 0);
  const std::string bp = fmt(s.boundary.precision(), s.boundary.predicted > 0);
  const std::string br = fmt(s.boundary.recall(), s.boundary.visible_px > 0);
  const long segments = s.marking.predicted + s.boundary.predicted + s.none_predicted;
  if (markdown) {
    std::printf("| %s | %s | %d | %s | %s | %s | %s | %ld | %.1f |\n", scene.c_str(), condition.c_str(), s.images,
                mp.c_str(), mr.c_str(), bp.c_str(), br.c_str(), segments, ms);
  } else {
    std::printf("%-12s %-11s %6d %9s %9s %10s %10s %9ld %9.1f\n", scene.c_str(), condition.c_str(), s.images,
                mp.c_str(), mr.c_str(), bp.c_str(), br.c_str(), segments, ms);
  }
}

void print_feature_row(bool markdown, const std::string& scene, const std::string& condition, const Group& g) {
  const synth::FeatureScore& f = g.features;
  const std::string p = fmt(f.precision(), f.detected > 0), r = fmt(f.recall(), f.truth > 0),
                    t = fmt(f.type_accuracy(), f.matched > 0), c = fmt(f.circle_rate(), f.circles > 0),
                    b = fmt(f.boundary_share(), f.boundary_columns > 0), m = fmt(f.marking_share(), f.marking_px > 0);
  if (markdown) {
    std::printf("| %s | %s | %ld | %ld | %s | %s | %s | %ld/%ld | %s | %ld/%ld | %s | %s |\n", scene.c_str(),
                condition.c_str(), f.truth, f.detected, p.c_str(), r.c_str(), t.c_str(), f.circles_found, f.circles,
                c.c_str(), f.ellipses_wrong, f.ellipses, b.c_str(), m.c_str());
  } else {
    std::printf("%-12s %-11s %6ld %6ld %7s %7s %7s %5ld/%-5ld %7s %5ld/%-8ld %8s %8s\n", scene.c_str(),
                condition.c_str(), f.truth, f.detected, p.c_str(), r.c_str(), t.c_str(), f.circles_found, f.circles,
                c.c_str(), f.ellipses_wrong, f.ellipses, b.c_str(), m.c_str());
  }
}

// The features on the ground against the truth (ground_score.hpp): junctions' error as a share of
// their distance, the circle's centre error within 4 m.
void print_ground_row(bool markdown, const std::string& scene, const std::string& condition, const Group& g) {
  const synth::GroundScore& s = g.ground;
  const auto within = [](const std::vector<double>& v, double limit) {
    return double(std::count_if(v.begin(), v.end(), [&](double e) { return e <= limit; })) / double(v.size());
  };
  const bool j = !s.junction_error_share.empty(), c = !s.circle_error_m.empty();
  const std::string jm = fmt(j ? 100 * median(s.junction_error_share) : 0, j),
                    j90 = fmt(j ? 100 * percentile(s.junction_error_share, 90) : 0, j),
                    j5 = fmt(j ? within(s.junction_error_share, 0.05) : 0, j),
                    jd = fmt(j ? median(s.junction_distance_m) : 0, j),
                    cm = fmt(c ? 100 * median(s.circle_error_m) : 0, c), c10 = fmt(c ? within(s.circle_error_m, 0.1) : 0, c);
  const long matched = static_cast<long>(s.junction_error_share.size()), found = static_cast<long>(s.circle_error_m.size());
  if (markdown)
    std::printf("| %s | %s | %ld | %s | %s | %s | %s | %ld/%ld | %s | %s |\n", scene.c_str(), condition.c_str(), matched,
                jd.c_str(), jm.c_str(), j90.c_str(), j5.c_str(), found, s.near_circles, cm.c_str(), c10.c_str());
  else
    std::printf("%-12s %-11s %8ld %8s %9s %9s %8s %5ld/%-5ld %9s %8s\n", scene.c_str(), condition.c_str(), matched,
                jd.c_str(), jm.c_str(), j90.c_str(), j5.c_str(), found, s.near_circles, cm.c_str(), c10.c_str());
}

// Columns within the feature score's boundary tolerance (4 px), as the synthetic fields count them.
long within_boundary_px(const HandBoundary& b) {
  const float px = synth::FeatureScoreParams{}.max_boundary_px;
  return std::count_if(b.errors_px.begin(), b.errors_px.end(), [&](double e) { return e <= px; });
}

void print_hand_boundary_row(bool markdown, const std::string& folder, const Group& g) {
  const HandBoundary& b = g.hand_boundary;
  const long n = static_cast<long>(b.errors_px.size());
  const long within_px = within_boundary_px(b);
  const std::string w4 = fmt(n > 0 ? double(within_px) / n : 0, n > 0),
                    ws = fmt(n > 0 ? double(b.within_share) / n : 0, n > 0), med = fmt(median(b.errors_px), n > 0);
  const synth::CentreLineScore& c = g.centre_lines;
  const std::string cp = fmt(c.precision(), c.detected_px > 0), cr = fmt(c.recall(), c.truth_px > 0);
  if (markdown)
    std::printf("| %s | %d | %ld | %s | %s | %s | %s | %s |\n", folder.c_str(), g.score.images, n, w4.c_str(), ws.c_str(),
                med.c_str(), cp.c_str(), cr.c_str());
  else
    std::printf("%-12s %6d %8ld %10s %10s %10s %9s %9s\n", folder.c_str(), g.score.images, n, w4.c_str(), ws.c_str(),
                med.c_str(), cp.c_str(), cr.c_str());
}

nlohmann::json to_json(const Group& g) {
  auto cls = [](const GtClassScore& c) {
    return nlohmann::json{{"predicted", c.predicted}, {"correct", c.correct},     {"precision", c.precision()},
                          {"visible_px", c.visible_px}, {"covered_px", c.covered_px}, {"recall", c.recall()}};
  };
  return {{"images", g.score.images},
          {"marking", cls(g.score.marking)},
          {"boundary", cls(g.score.boundary)},
          {"none", {{"predicted", g.score.none_predicted}, {"correct", g.score.none_correct}}},
          {"detect_ms_mean", g.score.images > 0 ? g.detect_ms / g.score.images : 0.0},
          {"intersections", {{"truth", g.features.truth}, {"detected", g.features.detected},
                             {"matched", g.features.matched}, {"type_correct", g.features.type_correct},
                             {"precision", g.features.precision()}, {"recall", g.features.recall()},
                             {"type_accuracy", g.features.type_accuracy()}}},
          {"circle", {{"frames", g.features.circles}, {"found", g.features.circles_found},
                      {"rate", g.features.circle_rate()}, {"ellipses", g.features.ellipses},
                      {"ellipses_wrong", g.features.ellipses_wrong}}},
          {"field_boundary", {{"columns", g.features.boundary_columns}, {"within_4px", g.features.boundary_right},
                              {"share", g.features.boundary_share()}}},
          {"markings", {{"px", g.features.marking_px}, {"on_line_px", g.features.marking_on_line_px},
                        {"share", g.features.marking_share()}}},
          {"ground", {{"junctions_matched", g.ground.junction_error_share.size()},
                      {"junction_error_median_share", median(g.ground.junction_error_share)},
                      {"circles_within_reach", g.ground.near_circles},
                      {"circles_found_on_ground", g.ground.circle_error_m.size()},
                      {"circle_centre_error_median_m", median(g.ground.circle_error_m)}}},
          {"hand_field_boundary", {{"columns", g.hand_boundary.errors_px.size()},
                                   {"within_2pct_height", g.hand_boundary.within_share},
                                   {"within_4px", within_boundary_px(g.hand_boundary)},
                                   {"median_error_px", median(g.hand_boundary.errors_px)}}},
          {"centre_lines", {{"truth_px", g.centre_lines.truth_px}, {"covered_px", g.centre_lines.covered_px},
                            {"recall", g.centre_lines.recall()}, {"detected_px", g.centre_lines.detected_px},
                            {"on_line_px", g.centre_lines.on_line_px}, {"precision", g.centre_lines.precision()}}}};
}

}  // namespace

std::vector<SynthSetImage> list_synth_set(const fs::path& dir) {
  std::vector<SynthSetImage> out;
  for (const fs::path& image : list_images(dir)) {
    const fs::path truth = synth::truth_path(image);
    if (fs::exists(truth)) out.push_back({image, truth});
  }
  if (out.empty())
    throw Error(dir.string() + ": no image with ground truth (expected <name>.png with truth/<name>.json, "
                "as written by fieldlines synth)");
  return out;
}

namespace {

// One image to score: where it is, its truth, and the row it counts in.
struct EvalImage {
  fs::path image, mask;  // mask: synthetic sets only
  synth::GroundTruth truth;
  std::string row, condition;
  std::vector<float> boundary_rows;  // hand truth only: synth::field_boundary_rows
  std::string folder;                // the truth folder's name: its overlays' subfolder (--draw)
};

// "dir/" and "dir" both name "dir".
std::string folder_name(const fs::path& dir) {
  fs::path normal = dir.lexically_normal();
  if (normal.filename().empty()) normal = normal.parent_path();
  return normal.filename().string();
}
// Loaded when scored, so a bad truth file skips its image (exit 1) and the others go on.
using EvalItem = std::function<EvalImage()>;

std::vector<EvalItem> synth_items(const std::vector<fs::path>& dirs) {
  std::vector<EvalItem> items;
  for (const fs::path& dir : dirs)
    for (const auto& [image, truth_file] : list_synth_set(dir))
      items.push_back([image = image, file = truth_file, folder = folder_name(dir)] {
        synth::GroundTruth truth = synth::load_truth(file);
        std::string row(synth::to_string(truth.scene)), condition(synth::to_string(truth.condition));
        fs::path mask = file.parent_path() / truth.mask;
        return EvalImage{image, std::move(mask), std::move(truth), std::move(row), std::move(condition), {}, folder};
      });
  return items;
}

std::vector<EvalItem> hand_items(const std::vector<fs::path>& dirs, const fs::path& data) {
  std::vector<EvalItem> items;
  for (const fs::path& dir : dirs)
    for (const fs::path& file : synth::list_hand_truth(dir))
      items.push_back([file, data, row = folder_name(dir)] {
        synth::HandTruth hand = synth::load_hand_truth(file);
        std::vector<float> rows = synth::field_boundary_rows(hand);
        return EvalImage{data / hand.image, {}, std::move(hand.truth), row, "hand", std::move(rows), row};
      });
  return items;
}

// How far the camera given to the detector is off (--camera-error): at most this many degrees of
// pitch and of roll, this share of its height.
struct CameraError {
  double degrees = 0, height_share = 0;
};
CameraError parse_camera_error(const std::optional<std::string>& text) {
  if (!text) return {};
  CameraError e;
  char comma = 0;
  int used = 0;
  if (std::sscanf(text->c_str(), "%lf%c%lf%n", &e.degrees, &comma, &e.height_share, &used) != 3 || comma != ',' ||
      used != static_cast<int>(text->size()) || !(e.degrees >= 0 && e.degrees <= 30) ||
      !(e.height_share >= 0 && e.height_share < 1))
    throw Error("--camera-error: expected DEG,FRAC with DEG in [0, 30] and FRAC in [0, 1), got '" + *text + "'");
  return e;
}

// The frame's camera from its truth, off by up to `error` (drawn from the frame's seed and index),
// and its field's centre circle radius.
void give_truth_camera(const synth::GroundTruth& truth, const CameraError& error, LineDetector& detector) {
  GroundCamera camera = synth::to_ground_camera(truth.intrinsics, truth.pose);
  std::mt19937_64 random(truth.seed * 1000003 + static_cast<std::uint64_t>(truth.index));
  std::uniform_real_distribution<double> unit(-1, 1);
  const double radians = error.degrees * std::numbers::pi / 180;
  camera.pitch_rad += radians * unit(random);
  camera.roll_rad += radians * unit(random);
  camera.height_m *= 1 + error.height_share * unit(random);
  detector.set_camera(camera);
  DetectorParams params = detector.params();
  params.centre_circle_radius = synth::centre_circle_radius(synth::make_field({.scene = truth.scene}));
  if (params.centre_circle_radius > 0) detector.set_params(params);
}

}  // namespace

int cmd_eval_gt(const Args& args) {
  const auto parsed = parse_or_print_help(
      args,
      {"--gt", "--hand", "--data", "--thresholds", "--max-distance", "--min-width", "--json", "--camera-error", "--draw"},
      {"--markdown", "--features", "--truth-camera", "--per-image"},
      kHelp);
  if (!parsed) return 0;
  const ParsedArgs& a = *parsed;
  const bool hand = a.value("--hand").has_value();
  if (hand && a.value("--gt")) throw Error("--gt and --hand cannot be mixed");
  std::vector<fs::path> dirs;
  if (const auto gt = a.value(hand ? "--hand" : "--gt")) dirs.emplace_back(*gt);
  for (const std::string& p : a.positionals()) dirs.emplace_back(p);
  if (dirs.empty()) throw Error("--gt DIR or --hand DIR is required (see fieldlines eval --gt --help)");
  const auto data = a.value("--data");
  if (hand && !data) throw Error("--hand needs --data DATA, the folder its image paths are relative to");
  const auto json_path = output_path(a, "--json");  // checked before the detection runs
  ThresholdsFile file;
  if (const auto t = a.value("--thresholds")) file = load_thresholds_file(*t);
  if (a.flag("--features")) file.detector = with_every_feature(file.detector);
  const bool features = !hand && (file.detector.intersections || file.detector.centre_circle);
  GtMatchParams match;
  match.max_distance_px = static_cast<float>(a.double_or("--max-distance", match.max_distance_px, 0.1, 50));
  match.min_width_px = static_cast<float>(a.double_or("--min-width", match.min_width_px, 0, 100));
  const bool markdown = a.flag("--markdown"), per_image = a.flag("--per-image");
  const bool truth_camera = a.flag("--truth-camera");
  if (truth_camera && hand) throw Error("--truth-camera needs synthetic sets (--gt): hand-drawn truth has no camera");
  const CameraError camera_error = parse_camera_error(a.value("--camera-error"));
  if (a.value("--camera-error") && !truth_camera) throw Error("--camera-error needs --truth-camera");

  const std::optional<fs::path> draw = a.value("--draw") ? std::optional<fs::path>(*a.value("--draw")) : std::nullopt;
  if (draw) make_overlay_folder(*draw);
  std::set<fs::path> drawn;  // overlays written: a second image of the same name gets <stem>-2.png

  const std::vector<EvalItem> items = hand ? hand_items(dirs, *data) : synth_items(dirs);
  LineDetector detector(file.detector, file.thresholds);
  detector.set_find_field_boundary(features || hand || draw);
  std::map<std::pair<std::string, std::string>, GroupRow> groups;
  Group total;
  int failed = 0;
  for (const EvalItem& load : items) {
    try {
      const EvalImage item = load();
      const cv::Mat img = load_image(item.image);
      if (truth_camera) give_truth_camera(item.truth, camera_error, detector);
      const auto start = std::chrono::steady_clock::now();
      const std::vector<Segment> segments = detector.detect(img);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      const GtEdges truth_edges(item.truth, match);
      const GtScore score = truth_edges.score(segments);
      if (draw) {
        const fs::path folder = *draw / item.folder;
        make_overlay_folder(folder);
        const fs::path out = next_overlay_path(folder, item.image, drawn, {canonical_path(item.image)});
        write_overlay(out, draw_eval_overlay(img, segments, detector.field_boundary(), truth_edges, item.boundary_rows));
      }
      synth::FeatureScore feature_score;
      synth::GroundScore ground_score;
      if (features) {
        // Without its mask (not written, unreadable) every column showing carpet counts.
        const cv::Mat mask = cv::imread(item.mask.string(), cv::IMREAD_UNCHANGED);
        const auto ft = synth::feature_truth(item.truth, mask, match.min_width_px);
        feature_score = synth::score_features(item.truth, ft, detector.features());
        if (truth_camera)
          ground_score = synth::score_ground(ft, detector.features(), detector.ground_features(), *detector.camera(),
                                             synth::to_ground_camera(item.truth.intrinsics, item.truth.pose));
      }
      const HandBoundary hand_boundary = score_hand_boundary(item.boundary_rows, detector.field_boundary(), img.rows);
      const synth::CentreLineScore centre_lines = synth::score_centre_lines(item.truth, detector.features().markings, match);
      Group one;
      one.score = score, one.features = feature_score, one.ground = ground_score;
      one.hand_boundary = hand_boundary, one.centre_lines = centre_lines, one.detect_ms = ms;
      GroupRow& row = groups[{item.row, item.condition}];
      row.sum += one;
      total += one;
      if (per_image) row.images.push_back({item.image.filename().string(), std::move(one)});
    } catch (const Error& e) {
      std::fprintf(stderr, "fieldlines eval: %s\n", e.what());
      ++failed;
    }
  }
  if (total.score.images == 0) throw Error("no image with ground truth found in the given folders");

  if (markdown) {
    std::printf("| scene | condition | images | marking precision | marking recall | boundary precision | "
                "boundary recall | segments | detect ms |\n|---|---|---|---|---|---|---|---|---|\n");
  } else {
    std::printf("%-12s %-11s %6s %9s %9s %10s %10s %9s %9s\n", "scene", "condition", "images", "mark P", "mark R",
                "bound P", "bound R", "segments", "det ms");
  }
  nlohmann::json out = {{"groups", nlohmann::json::array()}};
  for (const auto& [key, row] : groups) {
    print_row(markdown, key.first, key.second, row.sum);
    nlohmann::json j = to_json(row.sum);
    j["scene"] = key.first, j["condition"] = key.second;
    if (per_image) {
      j["per_image"] = nlohmann::json::array();
      for (const ImageGroup& im : row.images) {
        print_row(markdown, "  " + im.name, key.second, im.group);
        nlohmann::json ij = to_json(im.group);
        ij["image"] = im.name;
        j["per_image"].push_back(std::move(ij));
      }
    }
    out["groups"].push_back(j);
  }
  print_row(markdown, "all", "all", total);
  if (features) {
    std::printf("\n");
    if (markdown) {
      std::printf("| scene | condition | true junctions | detected | precision | recall | type correct | "
                  "circles found | circle rate | wrong ellipses | boundary within 4 px | markings on line |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    } else {
      std::printf("%-12s %-11s %6s %6s %7s %7s %7s %11s %7s %-14s %8s %8s\n", "scene", "condition", "true J", "det J",
                  "J prec", "J rec", "J type", "circles", "rate", "wrong/ellipses", "bound 4px", "mark on");
    }
    for (const auto& [key, row] : groups) print_feature_row(markdown, key.first, key.second, row.sum);
    print_feature_row(markdown, "all", "all", total);
  }
  if (features && truth_camera) {
    std::printf("\n");
    if (markdown)
      std::printf("| scene | condition | junctions matched | their median distance m | ground error median %% | "
                  "90th percentile %% | within 5 %% | circles within 4 m found | centre error median cm | within 10 cm |\n"
                  "|---|---|---|---|---|---|---|---|---|---|\n");
    else
      std::printf("%-12s %-11s %8s %8s %9s %9s %8s %11s %9s %8s\n", "scene", "condition", "J match", "J dist m",
                  "J err %", "J p90 %", "J 5 %", "circles", "C err cm", "C 10cm");
    for (const auto& [key, row] : groups) print_ground_row(markdown, key.first, key.second, row.sum);
    print_ground_row(markdown, "all", "all", total);
  }
  if (hand) {
    std::printf("\n");
    if (markdown)
      std::printf("| folder | images | boundary columns | within 4 px | within 2 %% of height | median error px | "
                  "centre lines P | centre lines R |\n|---|---|---|---|---|---|---|---|\n");
    else
      std::printf("%-12s %6s %8s %10s %10s %10s %9s %9s\n", "folder", "images", "columns", "within 4px", "within 2%",
                  "median px", "centre P", "centre R");
    for (const auto& [key, row] : groups) {
      print_hand_boundary_row(markdown, key.first, row.sum);
      for (const ImageGroup& im : row.images) print_hand_boundary_row(markdown, "  " + im.name, im.group);
    }
    print_hand_boundary_row(markdown, "all", total);
  }
  out["total"] = to_json(total);
  if (json_path) write_file_atomically(*json_path, out.dump(2) + "\n");
  if (draw) std::printf("overlays written to %s\n", draw->string().c_str());
  return failed > 0 ? 1 : 0;
}

}  // namespace fieldlines::cli
