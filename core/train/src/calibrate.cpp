#include "fieldlines/train/calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/train/percentile.hpp"
#include "class_mixture.hpp"

namespace fieldlines {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = 180.0 / kPi;

constexpr const char* kNoMarkings = "no field markings seen: no edges of white paint on green apart from grey edges";
constexpr const char* kMarkingsToDo =
    ". Use frames that show the field's lines, or label a few segments of each class in the studio";
constexpr const char* kNoBoundary = "no dark field edge seen (a field without a black wall at its edge)";

double norm3(const Rgb& g) { return std::sqrt(double(g[0]) * g[0] + double(g[1]) * g[1] + double(g[2]) * g[2]); }

// The gradient across the segment: along its normal, so the part along the line (noise) is gone.
double normal_gradient_norm(const Segment& s) {
  const double dx = double(s.x1) - s.x0, dy = double(s.y1) - s.y0;
  const double len = std::hypot(dx, dy);
  if (!(len > 0)) return 0;
  const double tx = dx / len, ty = dy / len;
  double sum = 0;
  for (int c = 0; c < 3; ++c) {
    const double g = -ty * s.grad_x[c] + tx * s.grad_y[c];
    sum += g * g;
  }
  return std::sqrt(sum);
}

// The projection the weakest edge the detector accepts has at `angle_deg` from the transition,
// its gradient at 45 degrees to the axes: the floor below which only noise is left.
double projection_floor(double contrast_floor, double angle_deg) {
  return contrast_floor * std::cos(angle_deg / kDeg) / std::sqrt(2.0);
}

struct Measured {
  double angle, projection, length;
  bool candidate = true;  // fitted on (boundary: along the field boundary; marking: a stripe)
};

// The first angle right of the class mean (0.01 deg grid) where the class no longer dominates
// the edges of log projection >= m_min; empty when it dominates up to the grey spike.
std::optional<double> angle_cut(const detail::ClassMixture& m, double m_min) {
  for (int step = 0;; ++step) {
    const double a = m.class_angle.mean + 0.01 * step;
    if (a >= m.theta_a) return std::nullopt;
    if (m.posterior_at_angle(a, m_min) <= 0.5) return a;
  }
}

// What the fit expects of a box over its rows: precision and recall from their responsibilities.
struct BoxExpectation {
  double precision = 0, recall = 0;
  double f_half() const {  // F-0.5: precision weighs twice recall
    const double d = 0.25 * precision + recall;
    return d > 0 ? 1.25 * precision * recall / d : 0;
  }
};
BoxExpectation expect_box(std::span<const detail::MixtureRow> rows, std::span<const double> responsibility,
                          double a_cut, double m_cut) {
  double inside = 0, inside_class = 0, class_total = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    class_total += responsibility[i];
    if (rows[i].angle <= a_cut && rows[i].log_projection >= m_cut) {
      inside += 1;
      inside_class += responsibility[i];
    }
  }
  return {inside > 0 ? inside_class / inside : 0, class_total > 0 ? inside_class / class_total : 0};
}

// Edge counts in messages: a class mass holds as many whole edges as it reaches (rounded down: a
// mass of 7.6 is not the 8 needed), and a need is met by whole edges only (rounded up).
std::string edges_held(double mass) { return std::to_string(static_cast<long>(std::floor(mass))); }
std::string edges_needed(double mass) { return std::to_string(static_cast<long>(std::ceil(mass))); }

// What differs between the classes' fits.
struct ClassRules {
  double min_mass;         // below: no mode
  const char* no_mode;     // the refusal's cause
  const char* what_to_do;  // and what to do about it
  bool use_contrast;       // may the contrast tell it from grey edges (white paint: yes)
  bool on_stripes;         // the rows are stripes: geometry, not the colour, kept grey edges out
};

ClassCalibration fit_class(const std::vector<Measured>& rows, const ColourClass& cls, double contrast_floor,
                           const CalibrationParams& params, const ClassRules& rules) {
  const auto& [min_mass, no_mode, what_to_do, use_contrast, on_stripes] = rules;
  ClassCalibration out;
  out.achromatic_deg = achromatic_angle_deg(cls);
  const double theta_a = out.achromatic_deg;
  const double x_max = theta_a + params.window_deg;
  // The floor at the achromatic angle keeps the weakest real edges in the fit.
  const double fit_floor = projection_floor(contrast_floor, theta_a);
  // Sorted, so that the sums of the EM (and so every bit of the result) do not depend on the
  // order the segments came in.
  std::vector<std::pair<detail::MixtureRow, double>> kept;  // (row, length)
  const auto in_window = [&](const Measured& r) {
    return r.projection >= fit_floor && r.projection > 0 && r.angle <= x_max;
  };
  for (const Measured& r : rows)
    if (r.candidate && in_window(r)) kept.push_back({{r.angle, std::log(r.projection)}, r.length});
  std::sort(kept.begin(), kept.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first.angle, a.first.log_projection, a.second) <
           std::tie(b.first.angle, b.first.log_projection, b.second);
  });
  std::vector<detail::MixtureRow> x;
  for (const auto& k : kept) x.push_back(k.first);
  out.fit_rows = x.size();
  // The colours first: where they separate the class (its angle cut, the class's posterior at
  // 1/2, lies min_separation sd right of its mean), that cut and the detector's noise floor.
  // Otherwise, and only for a class whose contrast tells it from grey edges (white paint; a dark
  // wall's foot is as dark as a robot's), the mixture over both features: the lowest projection
  // floor whose box it expects target_precision pure, the angle where the class stops dominating
  // edges that strong, never into the grey spike's core; where no floor reaches the target, the
  // floor of the best expected F-0.5.
  const detail::MixtureFitParams fit{params.seed_margin_deg, params.max_iterations, params.tolerance};
  std::optional<detail::ClassMixture> m = detail::fit_class_mixture(x, theta_a, x_max, false, fit);
  if (!m || m->class_mass < min_mass) {
    out.class_mass = m ? m->class_mass : 0;
    out.refused = std::string(no_mode);
    if (m) out.refused += " (" + edges_held(m->class_mass) + " edges of its colours, at least " +
                          edges_needed(min_mass) + " needed)";
    out.refused += what_to_do;
    return out;
  }
  const double angle_cap = theta_a - params.spike_margin_deg;
  const auto log_floor_at = [&](double angle) {
    return std::log(std::max(projection_floor(contrast_floor, angle), 1e-6));
  };
  // Fitted on stripes, the class is paint by geometry: its colour cut holds however close to the
  // grey spike it lies (pale paint's edges sit there), up to the spike's margin where the class
  // dominates that far, over the noise floor. A contrast box would cut the weaker paint edges
  // that the stripe check keeps.
  const std::optional<double> colour_cut =
      on_stripes ? std::min(angle_cut(*m, 0).value_or(angle_cap), angle_cap) : angle_cut(*m, 0);
  const bool colour_separates =
      colour_cut && (on_stripes || *colour_cut - m->class_angle.mean >= params.min_separation * m->class_angle.sd);
  if (!colour_separates && !use_contrast) {
    out.class_mass = m->class_mass;
    out.refused = std::string(no_mode) + ": its edges cannot be told from grey edges" + what_to_do;
    return out;
  }
  if (!colour_separates) m = detail::fit_class_mixture(x, theta_a, x_max, true, fit);
  if (!m) {
    out.refused = std::string(no_mode) + what_to_do;
    return out;
  }
  out.used_contrast = !colour_separates;
  out.on_stripes = on_stripes;
  out.mean_deg = m->class_angle.mean;
  out.sd_deg = m->class_angle.sd;
  out.achromatic_scale_deg = m->achromatic_scale;
  out.class_mass = m->class_mass;
  out.iterations = m->iterations;
  out.contrast_mean = std::exp(m->class_magnitude.mean);
  out.grey_contrast_mean = std::exp(m->achromatic_magnitude.mean);
  std::vector<double> responsibility(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) responsibility[i] = m->class_responsibility(x[i]);
  const auto box_at = [&](double m_min) {  // (angle cut, projection floor at that angle)
    const double a = std::min(angle_cut(*m, m_min).value_or(angle_cap), angle_cap);
    return std::pair{a, std::max(m_min, log_floor_at(a))};
  };
  double a_cut = 0, m_cut = 0;
  if (colour_separates) {
    a_cut = *colour_cut;
    m_cut = log_floor_at(a_cut);
  } else {
    std::tie(a_cut, m_cut) = box_at(log_floor_at(angle_cap));
    double best_f = -1;
    for (double m_try = m_cut; m_try <= m->class_magnitude.mean + m->class_magnitude.sd; m_try += 0.02) {
      const auto [a_try, m_box] = box_at(m_try);
      const BoxExpectation e = expect_box(x, responsibility, a_try, m_box);
      const bool reached = e.precision >= params.target_precision;
      if (reached || e.f_half() > best_f) a_cut = a_try, m_cut = m_box, best_f = e.f_half();
      if (reached) break;
    }
  }
  const BoxExpectation expected = expect_box(x, responsibility, a_cut, m_cut);
  out.separation = (a_cut - m->class_angle.mean) / m->class_angle.sd;
  if (!(expected.recall > 0)) {
    out.refused = std::string(no_mode) + ": its edges cannot be told from grey edges, by colour or by contrast" +
                  what_to_do;
    return out;
  }
  out.expected_precision = expected.precision;
  out.expected_recall = expected.recall;
  // Of stripes, the lengths of every row the class claims, stripes or not: stripes are the
  // longer pieces (a short one has few profiles to pass), and the robot checks each one anyway.
  std::vector<double> member_length;
  for (const Measured& r : rows)
    if ((r.candidate || on_stripes) && in_window(r) &&
        m->class_responsibility({r.angle, std::log(r.projection)}) >= 0.5)
      member_length.push_back(r.length);
  if (m->class_mass < params.few_edges)
    out.warning = "few edges of the class (" + edges_held(m->class_mass) + "): calibrate on more frames";
  else if (out.expected_precision < params.weak_precision)
    out.warning = "the class overlaps grey edges (expected precision " +
                  std::to_string(std::lround(100 * out.expected_precision)) +
                  " %): review the proposals in the studio";
  // The class's own shortest few: below them, clutter of the class's colour is all that is left.
  ClassThresholds t;
  // On stripes the robot checks every marking's geometry: the colour test may reach past the
  // grey spike (the projection floor stays the colour fit's).
  t.max_angle_deg = static_cast<float>(on_stripes ? std::max(a_cut, theta_a + params.stripe_angle_margin_deg) : a_cut);
  t.min_projection = static_cast<float>(std::exp(m_cut));
  t.min_length = static_cast<float>(percentile(member_length, params.length_percentile));
  out.thresholds = t;
  return out;
}

}  // namespace

Calibration calibrate(std::span<const Segment> segments, const Thresholds& start, const CalibrationParams& params,
                      std::span<const std::uint8_t> boundary_candidates,
                      std::span<const std::uint8_t> marking_candidates) {
  for (const auto& [flags, what] : {std::pair{boundary_candidates, "boundary"}, {marking_candidates, "marking"}})
    if (!flags.empty() && flags.size() != segments.size())
      throw Error("calibrate: " + std::to_string(flags.size()) + " " + what + " flags for " +
                  std::to_string(segments.size()) + " segments");
  Calibration out;
  out.segments = segments.size();
  if (segments.size() < params.min_segments) {
    const std::string why = "too few segments (" + std::to_string(segments.size()) + ", at least " +
                            std::to_string(params.min_segments) +
                            " needed): use more frames that show the field, or label a few segments of each "
                            "class in the studio";
    out.marking.refused = out.boundary.refused = why;
    out.marking.achromatic_deg = achromatic_angle_deg(start.marking);
    out.boundary.achromatic_deg = achromatic_angle_deg(start.boundary);
    return out;
  }
  std::vector<double> normal_norms;
  std::vector<Measured> marking, boundary;
  normal_norms.reserve(segments.size());
  marking.reserve(segments.size());
  boundary.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    normal_norms.push_back(normal_gradient_norm(s));
    const SegmentFeatures f = compute_features(s, start);
    boundary.push_back({f.boundary.angle_deg, f.boundary.projection, f.length,
                        boundary_candidates.empty() || boundary_candidates[i] != 0});
    // For a straight edge grad_x and grad_y are one colour vector scaled by the normal's
    // components: the dominant one measures the same angle with less noise.
    const int m = f.marking_count == 2 && norm3(s.grad_x) > norm3(s.grad_y) ? 1 : 0;
    marking.push_back({f.marking[m].angle_deg, f.marking[m].projection, f.length,
                       marking_candidates.empty() || marking_candidates[i] != 0});
  }
  const bool stripes = std::find(marking_candidates.begin(), marking_candidates.end(), 0) != marking_candidates.end();
  out.contrast_floor = percentile(normal_norms, params.floor_percentile);
  out.marking = fit_class(marking, start.marking, out.contrast_floor, params,
                          {params.min_class_mass, kNoMarkings, kMarkingsToDo, true, stripes});
  out.boundary = fit_class(boundary, start.boundary, out.contrast_floor, params,
                           {params.min_boundary_mass, kNoBoundary, "", false, false});
  return out;
}

void keep_given_markings(Calibration& c, const Thresholds& start, std::size_t frames_with_field,
                         const CalibrationParams& params) {
  ClassCalibration& m = c.marking;
  if (m.thresholds || frames_with_field == 0 || c.segments < params.min_segments) return;
  m.thresholds = start.marking.thresholds;
  m.kept_given = true;
  m.warning = "kept the given thresholds: " + m.refused;
  m.refused.clear();
}

ClassThresholds disabled_class() { return {1000.f, 0.f, 100000.f}; }

Thresholds calibrated_thresholds(const Calibration& c, const Thresholds& start) {
  if (!c.marking.thresholds) throw Error("cannot calibrate the field markings: " + c.marking.refused);
  Thresholds t = start;
  t.marking.thresholds = *c.marking.thresholds;
  t.boundary.thresholds = c.boundary.thresholds ? *c.boundary.thresholds : disabled_class();
  return t;
}

nlohmann::json calibration_provenance(const Calibration& c) {
  const auto class_json = [](const ClassCalibration& k) {
    return nlohmann::json{{"achromatic_deg", k.achromatic_deg}, {"mean_deg", k.mean_deg},
                          {"sd_deg", k.sd_deg}, {"achromatic_scale_deg", k.achromatic_scale_deg},
                          {"class_mass", k.class_mass}, {"separation", k.separation},
                          {"used_contrast", k.used_contrast}, {"on_stripes", k.on_stripes}, {"contrast_mean", k.contrast_mean}, {"grey_contrast_mean", k.grey_contrast_mean},
                          {"expected_precision", k.expected_precision}, {"expected_recall", k.expected_recall},
                          {"fit_rows", k.fit_rows}, {"iterations", k.iterations},
                          {"fitted", k.thresholds.has_value() && !k.kept_given}, {"kept_given", k.kept_given},
                          {"refused", k.thresholds ? nlohmann::json(nullptr) : nlohmann::json(k.refused)},
                          {"warning", k.warning.empty() ? nlohmann::json(nullptr) : nlohmann::json(k.warning)}};
  };
  return {{"method", "label-free"},
          {"contrast_floor", c.contrast_floor},
          {"fit", {{"marking", class_json(c.marking)}, {"boundary", class_json(c.boundary)}}}};
}

}  // namespace fieldlines
