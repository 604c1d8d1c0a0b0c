#pragma once
// Label-free calibration: both classes' thresholds from the segments' colour gradients alone.
//
// Why it works without labels: an achromatic edge (wall, robot, furniture, shadow) has a
// gradient along (1,1,1), so its angle to a class's transition v = to - from is fixed by
// geometry: theta_A = acos(v.(1,1,1) / (|v| sqrt 3)), 35.26 deg for green-to-white and 54.74 deg
// for black-to-green. The class's own edges form a mode at smaller angles. Per class, a mixture
// over the angle and the log projection is fitted by EM (class_mixture.hpp):
//   class      Gaussian in both, seeded from the rows below theta_A - seed_margin_deg;
//   achromatic Cauchy centred at theta_A (fixed: it is physics) times a Gaussian in contrast;
//   background uniform over [0, theta_A + window_deg], broad in contrast.
// The contrast matters where the field's colours are pale: the class's angle mode then runs into
// the grey spike, and painted lines are still brighter edges than most grey clutter.
// The box is where the class's posterior falls to 1/2: max_angle_deg right of its mean among
// edges strong enough to pass, min_projection down from its mean contrast among edges inside the
// angle, never below the projection the weakest edge the detector accepts has inside the cone
// (contrast floor * cos(max_angle) / sqrt 2, the floor being a low percentile of the gradient
// norm normal to the segments), and never into the spike's core. min_length is a
// low percentile of the saliency of the class's own members (posterior >= 1/2): relative to
// the class, because Humanoid markings are a third as long as SSL's, and low, because what
// has the class's colour but is not the class (a warm-lit wall corner, a shirt) is short.
//
// A class is refused only when the data hold no mode of its colours at all; a fit that is
// weak (few edges, a box the fit expects to be impure) is kept with a warning.
//
// Labels are never read. The result depends only on the set of segments, not on their order.
#include <cstddef>
#include <cstdint>
#include <optional>

#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

struct CalibrationParams {
  std::size_t min_segments = 50;    // fewer: the statistics say nothing
  double window_deg = 10;           // fit angles in [0, theta_A + window]: the spike and its tails
  double seed_margin_deg = 3;       // the class's seed: angles below theta_A - margin
  double floor_percentile = 1;      // of the normal gradient norm: the detector's contrast floor
  double length_percentile = 2;     // of the class members' saliency: min_length
  double min_class_mass = 8;        // segments the marking class must hold (EM mass): fewer is no mode
  double min_boundary_mass = 30;    // the boundary's: a wall shows many edges, a false one costs more
  double few_edges = 30;            // below this mass the fit is kept with a warning
  double spike_margin_deg = 0.5;    // max_angle stays this far below theta_A...
  // ...unless fitted on stripes: then it reaches this far past theta_A. A stripe is paint by
  // geometry, and pale, blurred or fringed paint's edges lie at the grey spike and just past it,
  // where the colour alone cannot follow them (Humanoid held-out recall 0.661 -> 0.750 at the
  // same precision; docs/calibration.md).
  double stripe_angle_margin_deg = 3;
  double min_separation = 1;        // (max_angle - mean) / sd at the noise floor: colour separates
  double target_precision = 0.9;    // else the lowest projection floor whose box the fit expects this pure
  double weak_precision = 0.8;      // expected precision below this: kept with a warning
  int max_iterations = 200;
  double tolerance = 1e-6;          // |delta log-likelihood| per point
};

// One class's fit, or the reason it was refused.
struct ClassCalibration {
  std::optional<ClassThresholds> thresholds;  // empty: refused (see `refused`)
  std::string refused;                        // why the data do not support a fit
  std::string warning;                        // fitted, but weakly: what to do about it
  double achromatic_deg = 0;                  // theta_A, from the class's colours
  double mean_deg = 0, sd_deg = 0;            // the class's angle mode
  double achromatic_scale_deg = 0;            // the Cauchy's fitted scale
  double class_mass = 0;                      // segments the EM gives the class
  double separation = 0;                      // (max_angle - mean) / sd
  bool used_contrast = false;                 // the colours did not separate: the contrast did
  bool on_stripes = false;                    // fitted on stripes alone (the marking candidates)
  double contrast_mean = 0;                   // the class's typical projection (geometric mean)
  double grey_contrast_mean = 0;              // the grey edges' typical projection
  double expected_precision = 0;              // of the box, under the fitted mixture
  double expected_recall = 0;
  bool kept_given = false;                    // refused, but the given thresholds kept (keep_given_markings)
  std::size_t fit_rows = 0;                   // segments in the fit window
  int iterations = 0;
};

struct Calibration {
  ClassCalibration marking, boundary;
  double contrast_floor = 0;  // the percentile of the normal gradient norm
  std::size_t segments = 0;
};

// Fits both classes of `start` (its colours, sidedness and gradient mode are kept). With
// `boundary_candidates` (one flag per segment, CalibrationInputs gives them) the boundary class
// is fitted on the flagged segments alone: those along their frame's field boundary. Likewise
// the marking class on `marking_candidates`: the stripes, where the detector checks them; its
// colour cut then holds up to the grey spike's margin over the noise floor (no contrast box).
Calibration calibrate(std::span<const Segment> segments, const Thresholds& start = {},
                      const CalibrationParams& params = {}, std::span<const std::uint8_t> boundary_candidates = {},
                      std::span<const std::uint8_t> marking_candidates = {});

// Thresholds that never pass: what a class the data do not show gets, so that a field without a
// boundary wall does not mark furniture as one.
ClassThresholds disabled_class();

// Where the frames showed a field (`frames_with_field` > 0) and enough segments to fit on, but
// the marking class was refused (too few of its edges, or none told from grey ones: a dim or
// distant view of the lines), the given marking thresholds are kept and the refusal becomes a
// warning that says so and what to do: a venue then gets a file that marks what the given one
// did, instead of none. Without a field in view (pictures without green, segments from a file)
// or with too few segments for any statistics, the refusal stands.
void keep_given_markings(Calibration& calibration, const Thresholds& start, std::size_t frames_with_field,
                         const CalibrationParams& params = {});

// `start` with each fitted class replaced, refused ones disabled. Throws fieldlines::Error
// naming the reason when the marking class was refused: without it there is nothing to write.
Thresholds calibrated_thresholds(const Calibration& calibration, const Thresholds& start = {});

// What every face (CLI, Python) records of a fit in the thresholds file's provenance:
// {"method": "label-free", "contrast_floor", "fit": {"marking": {...}, "boundary": {...}}}, each
// class with its mode, spread, mass, separation, contrasts, expected precision and recall, rows,
// iterations, "fitted", "kept_given", "refused" and "warning".
nlohmann::json calibration_provenance(const Calibration& calibration);

}  // namespace fieldlines
