#pragma once
// The detector's parameters and their one description. DetectorParams holds the defaults;
// kDetectorParamSpecs names every field with its valid range, unit and meaning. The JSON reader
// and writer, validate(), the CLI's help and the studio's sliders all read that table, so a
// range or a name is written here and nowhere else.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace fieldlines {

struct DetectorParams {
  // The configuration the method's authors ran (reference/README.md). What each field means,
  // its unit and its valid range: kDetectorParamSpecs below.
  int gaussian_kernel = 7;
  double gaussian_sigma = 1.0;
  int gradient_threshold = 30;
  int anchor_threshold = 8;
  int scan_interval = 10;
  int min_line_length = 40;
  double line_fit_error = 0.2;
  double px_to_segment_dist = 1.5;
  double validation_threshold = 0.15;
  bool validate = true;
  bool treat_junctions = true;
  std::vector<int> junction_sizes{5, 7, 9};
  // The gradient pass then runs in row bands (frames too short for bands of a useful height
  // keep one). Speed only: the results are the same bits for any count, so it is not written
  // into thresholds or project files. Workers start on the first detect.
  int threads = 1;
  // Painted lines as stripes (stripes.hpp): Marking segments that are not part of a stripe
  // become None, and the stripes' centre lines are LineDetector::features().markings. Off by
  // default: the reference reproduction has no such stage.
  bool stripes = false;
  int stripe_samples = 5;
  double stripe_max_width = 0.15;
  bool stripe_require_twin = false;
  // The stripes' turf in every colour the frame's own turf shows (turf_colours.hpp: sun and
  // shade, patchy turf), not only within a tolerance of its median colour (the field boundary
  // always takes them). Off: the median's colour alone. Calibration turns it on (measured both
  // ways in docs/detector.md).
  bool stripe_turf_colours = false;
  // L, T and X junctions of the stripes' centre lines (intersections.hpp). Off by default like
  // the stripes; on, it runs the stripes stage too (its input).
  bool intersections = false;
  double intersection_min_angle = 10;  // far corners look this acute in perspective
  double intersection_reach = 1.5;
  // With the camera known, a junction whose arms do not meet at right angles on the turf
  // (ground_features.hpp: square_on_ground) within this many degrees is dropped; 0: off. A
  // field's lines meet square; what the image calls a corner in perspective often is not one.
  double intersection_ground_tolerance = 15;
  // The centre circle from short stripe pieces (centre_circle.hpp); off by default. On, the frame
  // is drawn a second time for pieces from piece_length px, which the junctions take too.
  bool centre_circle = false;
  int piece_length = 10;
  // The centre circle's radius on the turf, metres (the Humanoid Kid and SPL rules: 0.75; SSL 0.5;
  // MSL 2): used only when the camera is known (LineDetector::set_camera), to fit it on the turf.
  double centre_circle_radius = 0.75;
  // A field darker than this (R + G + B of its colour, light.hpp) lowers the gradient threshold
  // in proportion for that frame, so a dim frame keeps the edges a bright one has; 0: off, the
  // method's fixed threshold.
  double dark_field = 0;
  // Near rows hold wide lines on coarse, textured turf, whose edges break up at the full scale;
  // far rows hold lines a pixel or two wide that a coarser scale loses. With coarse_scale above
  // 1, the rows from coarse_from (a share of the height, from the top) down are detected a second
  // time at 1 / coarse_scale of the size, and a coarse segment joins the full-scale ones where
  // none of them lies along it (detector.cpp). 1: off, the method's one scale. When the field
  // boundary is measured (its gate, the features) and the turf fills the frame's top
  // (FieldBoundary::fills_top: a camera looking down at its feet), no row is far: the band
  // starts at the top. Held-out Humanoid halves: on any segment 0.894 -> 0.900, marking the same.
  int coarse_scale = 1;
  double coarse_from = 0.5;
  // ...and from coarse_twins_from down to coarse_from, the lines the coarse scale resolves: a
  // coarse segment there joins only when it has a twin, the line's other edge, drawn too (at
  // least two coarse pixels off, facing it, no farther than the stripes' widest paint there).
  // Above the near rows a line is a few coarse pixels wide at most, and the coarse scale blurs
  // its two edges into one segment off both. 1 (or anything at or below coarse_from): none.
  double coarse_twins_from = 1;
  // Far rows' lines a pixel or two wide give the gradient two edges so close that smoothing
  // blurs them into each other; the line itself is brighter than both sides. With thin_reach
  // above 0, the rows above thin_to (a share of the height) are drawn a second time on that
  // ridge (lines up to 2 thin_reach - 1 px wide), and a segment along a line's centre joins the
  // others where they do not already hold both of its edges (detector.cpp). 0: off.
  // With the field boundary's gate (Thresholds::field_boundary_gate), from a band above the
  // field's top only (a marking above it would be none).
  int thin_reach = 0;
  double thin_to = 0.6;
  // ...and, when the field boundary is measured (its gate, the features), the far lines along it:
  // within this share of the height below the boundary, the brightness averaged over runs of
  // columns at each offset from it finds a line whose ridge on any one column is below the
  // pass's threshold (the far touch line blurred into a wall's foot; along_boundary.hpp). 0: off.
  double thin_along_boundary = 0.05;
  bool operator==(const DetectorParams&) const = default;
};

// [lo, hi], or (lo, hi] when lo_open. Empty (lo == hi, closed) means "no range".
struct ParamRange {
  double lo = 0, hi = 0;
  bool lo_open = false;
  constexpr bool empty() const { return lo == hi && !lo_open; }
  constexpr bool contains(double v) const { return (lo_open ? v > lo : v >= lo) && v <= hi; }  // NaN: false
  std::string to_string() const;  // "[1, 1000]", "(0, 20]"
};

struct ParamSpec {
  using Member = std::variant<int DetectorParams::*, double DetectorParams::*, bool DetectorParams::*,
                              std::vector<int> DetectorParams::*>;
  std::string_view name{};  // the field and its JSON key
  Member member{};
  ParamRange range{};       // valid values (a list: each element's); empty for a flag
  std::string_view unit{};  // "px", "rad", ... or empty when unitless
  std::string_view help{};  // one line: what it does
  ParamRange slider{};      // the span worth trying by hand (the studio's slider); empty: no slider
  bool odd = false;         // a kernel size: values of 3 and more must be odd
  bool in_files = true;     // written into and read from thresholds and project files
};

inline constexpr std::array<ParamSpec, 32> kDetectorParamSpecs{{
    {.name = "gaussian_kernel", .member = &DetectorParams::gaussian_kernel, .range = {0, 31}, .unit = "px",
     .help = "smoothing kernel size, odd; below 3: no smoothing", .odd = true},
    {.name = "gaussian_sigma", .member = &DetectorParams::gaussian_sigma, .range = {0, 20, true}, .unit = "px",
     .help = "smoothing (Gaussian) standard deviation", .slider = {0.1, 5}},
    {.name = "gradient_threshold", .member = &DetectorParams::gradient_threshold, .range = {0, 2040},
     .help = "Sobel |dx| + |dy| below this is no edge", .slider = {1, 255}},
    {.name = "anchor_threshold", .member = &DetectorParams::anchor_threshold, .range = {0, 255},
     .help = "an anchor exceeds its neighbours by this", .slider = {0, 64}},
    {.name = "scan_interval", .member = &DetectorParams::scan_interval, .range = {1, 1000}, .unit = "px",
     .help = "anchors are sought on every k-th row and column"},
    {.name = "min_line_length", .member = &DetectorParams::min_line_length, .range = {3, 10000}, .unit = "px",
     .help = "pixels drawn before a line is fitted", .slider = {5, 200}},
    {.name = "line_fit_error", .member = &DetectorParams::line_fit_error, .range = {0, 100, true}, .unit = "px^2",
     .help = "largest mean squared error of a line fit"},
    {.name = "px_to_segment_dist", .member = &DetectorParams::px_to_segment_dist, .range = {0, 100, true},
     .unit = "px", .help = "largest distance of an inlier pixel to its line"},
    {.name = "validation_threshold", .member = &DetectorParams::validation_threshold, .range = {0, 1.5708, true},
     .unit = "rad", .help = "largest gradient angle error of a valid pixel",
     .slider = {0.01, 1}},
    {.name = "validate", .member = &DetectorParams::validate,
     .help = "false: keep every segment, saliency = length"},
    {.name = "treat_junctions", .member = &DetectorParams::treat_junctions,
     .help = "jump over discontinuities along a line"},
    {.name = "junction_sizes", .member = &DetectorParams::junction_sizes, .range = {1, 100}, .unit = "px",
     .help = "jump lengths tried at a junction"},
    {.name = "threads", .member = &DetectorParams::threads, .range = {1, 64},
     .help = "threads of the gradient pass (speed only)", .in_files = false},
    {.name = "stripes", .member = &DetectorParams::stripes,
     .help = "keep only markings that are stripes (turf, paint, turf) and measure their centre lines"},
    {.name = "stripe_samples", .member = &DetectorParams::stripe_samples, .range = {1, 32},
     .help = "profiles across each marking candidate", .slider = {1, 15}},
    {.name = "stripe_max_width", .member = &DetectorParams::stripe_max_width, .range = {0, 1, true},
     .help = "widest stripe on the bottom row, as a share of the image height (a quarter of it on top)",
     .slider = {0.02, 0.5}},
    {.name = "stripe_require_twin", .member = &DetectorParams::stripe_require_twin,
     .help = "a stripe must have both edges detected; otherwise one edge with its profile suffices"},
    {.name = "stripe_turf_colours", .member = &DetectorParams::stripe_turf_colours,
     .help = "a stripe's turf is any colour the frame's own turf shows (sun, shade), not only near its median colour"},
    {.name = "intersections", .member = &DetectorParams::intersections,
     .help = "find L, T and X junctions of the stripes' centre lines (runs the stripes stage too)"},
    {.name = "intersection_min_angle", .member = &DetectorParams::intersection_min_angle, .range = {0, 90, true},
     .unit = "deg", .help = "two centre lines meet only at more than this angle", .slider = {5, 80}},
    {.name = "intersection_reach", .member = &DetectorParams::intersection_reach, .range = {0, 20},
     .help = "how far a line may end short of a crossing, in line widths (plus 4 px)", .slider = {0, 6}},
    {.name = "intersection_ground_tolerance", .member = &DetectorParams::intersection_ground_tolerance,
     .range = {0, 45}, .unit = "deg",
     .help = "with a camera, junctions whose arms are not square on the turf within this are dropped; 0: off",
     .slider = {0, 30}},
    {.name = "centre_circle", .member = &DetectorParams::centre_circle,
     .help = "fit the centre circle to short stripe pieces of a second drawing (runs the stripes stage too)"},
    {.name = "piece_length", .member = &DetectorParams::piece_length, .range = {3, 10000},
     .unit = "px", .help = "shortest piece of the second drawing (the centre circle's, the junctions' too)", .slider = {5, 60}},
    {.name = "centre_circle_radius", .member = &DetectorParams::centre_circle_radius, .range = {0, 100, true},
     .unit = "m", .help = "the centre circle's radius on the turf, for its fit when the camera is known", .slider = {0.25, 3}},
    {.name = "dark_field", .member = &DetectorParams::dark_field, .range = {0, 765},
     .help = "a field darker than this (R + G + B) lowers the gradient threshold in proportion; 0: off",
     .slider = {0, 765}},
    {.name = "coarse_scale", .member = &DetectorParams::coarse_scale, .range = {1, 8},
     .help = "also detect the rows below coarse_from at 1/k of the size (near, wide, textured lines); 1: off",
     .slider = {1, 4}},
    {.name = "coarse_from", .member = &DetectorParams::coarse_from, .range = {0, 1},
     .help = "the coarse pass covers the rows below this share of the height", .slider = {0, 1}},
    {.name = "coarse_twins_from", .member = &DetectorParams::coarse_twins_from, .range = {0, 1},
     .help = "above coarse_from, from this share of the height down the coarse pass keeps lines it resolves "
             "(both edges drawn); 1: none",
     .slider = {0, 1}},
    {.name = "thin_reach", .member = &DetectorParams::thin_reach, .range = {0, 8}, .unit = "px",
     .help = "also draw lines up to 2k - 1 px wide along their centres, above thin_to (far, thin lines); 0: off",
     .slider = {0, 4}},
    {.name = "thin_to", .member = &DetectorParams::thin_to, .range = {0, 1},
     .help = "the thin-line pass covers the rows above this share of the height", .slider = {0, 1}},
    {.name = "thin_along_boundary", .member = &DetectorParams::thin_along_boundary, .range = {0, 0.25},
     .help = "with the thin-line pass and the field boundary, also find far lines within this share of the height below the boundary; 0: off",
     .slider = {0, 0.25}},
}};

// The spec named `name`, or nullptr.
const ParamSpec* find_param_spec(std::string_view name);

// Why `value` is not valid for `spec` ("0 is outside [1, 1000]"), or nothing when it is.
std::optional<std::string> param_error(const ParamSpec& spec, double value);

// The default (DetectorParams{}) as text: a number, true or false, or a list "a, b, c".
std::string param_default_text(const ParamSpec& spec);

// A number as the messages and help print it: up to 6 significant digits, no trailing zeros.
std::string format_param_number(double value);

// `params` with every field feature stage on (stripes, intersections, centre circle): what
// `--features`, the studio and the benchmark's features row run.
inline DetectorParams with_every_feature(DetectorParams params) {
  params.stripes = params.intersections = params.centre_circle = true;
  return params;
}

// Validates every field against kDetectorParamSpecs; throws fieldlines::Error
// "detector parameter <name>: <value> is outside <range>" on the first bad one.
void validate(const DetectorParams& params);

}  // namespace fieldlines
