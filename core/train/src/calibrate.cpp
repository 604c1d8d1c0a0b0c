#include "fieldlines/train/calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/train/percentile.hpp"

namespace fieldlines {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = 180.0 / kPi;

double norm3(const Rgb& g) { return std::sqrt(double(g[0]) * g[0] + double(g[1]) * g[1] + double(g[2]) * g[2]); }

// The angle an achromatic (1,1,1) gradient makes with the class's transition.
double achromatic_angle_deg(const ColourClass& c) {
  const double v[3] = {double(c.to[0]) - c.from[0], double(c.to[1]) - c.from[1], double(c.to[2]) - c.from[2]};
  const double nv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  double cosine = (v[0] + v[1] + v[2]) / (nv * std::sqrt(3.0));
  if (c.two_sided) cosine = std::abs(cosine);
  return std::acos(std::clamp(cosine, -1.0, 1.0)) * kDeg;
}

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

double gaussian(double x, double mean, double sd) {
  const double z = (x - mean) / sd;
  return std::exp(-0.5 * z * z) / (sd * std::sqrt(2 * kPi));
}
double cauchy(double x, double centre, double scale) {
  const double d = x - centre;
  return scale / (kPi * (scale * scale + d * d));
}

struct Mixture {
  double mean = 0, sd = 1, scale = 1;    // class Gaussian; achromatic Cauchy's scale
  double w_class = 0, w_achromatic = 0, w_uniform = 0;
  double uniform = 0;                    // 1 / window width
  double class_mass = 0;
  int iterations = 0;
};

// EM over the angles `x` (all in [0, theta_a + window]). Empty when a component collapses.
std::optional<Mixture> fit_mixture(const std::vector<double>& x, double theta_a, double x_max,
                                   const CalibrationParams& params) {
  std::vector<double> seed;
  for (const double a : x)
    if (a < theta_a - params.seed_margin_deg) seed.push_back(a);
  if (seed.size() < 2) return std::nullopt;
  const double n = double(x.size());
  Mixture m;
  m.mean = percentile(seed, 50);
  std::vector<double> deviation;
  for (const double a : seed) deviation.push_back(std::abs(a - m.mean));
  m.sd = std::max(1.4826 * percentile(deviation, 50), 1.0);  // MAD as a normal sd
  m.scale = 1;
  m.w_class = 0.9 * double(seed.size()) / n;
  m.w_achromatic = 0.9 - m.w_class;
  m.w_uniform = 0.1;
  m.uniform = 1.0 / x_max;
  std::vector<double> r_class(x.size()), r_achromatic(x.size());
  double previous = -INFINITY;
  for (int it = 0; it < params.max_iterations; ++it) {
    m.iterations = it + 1;
    double log_likelihood = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double c = m.w_class * gaussian(x[i], m.mean, m.sd);
      const double a = m.w_achromatic * cauchy(x[i], theta_a, m.scale);
      const double total = c + a + m.w_uniform * m.uniform;
      log_likelihood += std::log(total);
      r_class[i] = c / total;
      r_achromatic[i] = a / total;
    }
    double n_class = 0, n_achromatic = 0, sum = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      n_class += r_class[i];
      n_achromatic += r_achromatic[i];
      sum += r_class[i] * x[i];
    }
    if (n_class < 1) return std::nullopt;
    // A set without a single grey edge (a clean synthetic field) keeps a trace of the grey
    // component instead of failing: the cut then falls where the class's own tail ends.
    n_achromatic = std::max(n_achromatic, 1e-3);
    m.w_class = n_class / n;
    m.w_achromatic = n_achromatic / n;
    m.w_uniform = std::max(0.0, 1.0 - m.w_class - m.w_achromatic);
    m.mean = sum / n_class;
    double var = 0, scale2 = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      var += r_class[i] * (x[i] - m.mean) * (x[i] - m.mean);
      // Student-t (nu = 1) EM: each point's latent precision weight.
      const double z = (x[i] - theta_a) / m.scale;
      scale2 += r_achromatic[i] * 2.0 / (1.0 + z * z) * (x[i] - theta_a) * (x[i] - theta_a);
    }
    m.sd = std::max(std::sqrt(var / n_class), 0.25);
    m.scale = std::max(std::sqrt(scale2 / n_achromatic), 0.1);
    m.class_mass = n_class;
    if (std::abs(log_likelihood - previous) < params.tolerance * n) break;
    previous = log_likelihood;
  }
  return m;
}

double class_posterior(const Mixture& m, double theta_a, double x) {
  const double c = m.w_class * gaussian(x, m.mean, m.sd);
  return c / (c + m.w_achromatic * cauchy(x, theta_a, m.scale) + m.w_uniform * m.uniform);
}

// The first angle right of the class mean (0.01 deg grid) where the class no longer dominates.
std::optional<double> posterior_crossing(const Mixture& m, double theta_a) {
  for (int step = 0;; ++step) {
    const double x = m.mean + 0.01 * step;
    if (x >= theta_a) return std::nullopt;
    if (class_posterior(m, theta_a, x) <= 0.5) return x;
  }
}

// The projection the weakest edge the detector accepts has at `angle_deg` from the transition,
// its gradient at 45 degrees to the axes: the floor below which only noise is left.
double projection_floor(double contrast_floor, double angle_deg) {
  return contrast_floor * std::cos(angle_deg / kDeg) / std::sqrt(2.0);
}

struct Measured {
  double angle, projection, length;
};


ClassCalibration fit_class(const std::vector<Measured>& rows, const ColourClass& cls, double contrast_floor,
                           const CalibrationParams& params) {
  ClassCalibration out;
  out.achromatic_deg = achromatic_angle_deg(cls);
  const double theta_a = out.achromatic_deg;
  const double x_max = theta_a + params.window_deg;
  // The floor at the achromatic angle keeps the weakest real edges in the fit.
  const double fit_floor = projection_floor(contrast_floor, theta_a);
  // Sorted, so that the sums of the EM (and so every bit of the result) do not depend on the
  // order the segments came in.
  std::vector<std::pair<double, double>> kept;  // (angle, length)
  for (const Measured& r : rows)
    if (r.projection >= fit_floor && r.angle <= x_max) kept.emplace_back(r.angle, r.length);
  std::sort(kept.begin(), kept.end());
  std::vector<double> x, length;
  for (const auto& [angle, len] : kept) {
    x.push_back(angle);
    length.push_back(len);
  }
  out.fit_rows = x.size();
  const std::optional<Mixture> m = fit_mixture(x, theta_a, x_max, params);
  if (!m) {
    out.refused = "no colour mode apart from grey edges (is there a green field in the images?)";
    return out;
  }
  out.mean_deg = m->mean;
  out.sd_deg = m->sd;
  out.achromatic_scale_deg = m->scale;
  out.class_mass = m->class_mass;
  out.iterations = m->iterations;
  const std::optional<double> cut = posterior_crossing(*m, theta_a);
  if (!cut) {
    out.refused = "the class's edges cannot be told from grey edges";
    return out;
  }
  out.separation = (*cut - m->mean) / m->sd;
  if (m->class_mass < params.min_class_mass) {
    out.refused = "too few of its edges (" + std::to_string(static_cast<long>(std::lround(m->class_mass))) +
                  ", at least " + std::to_string(static_cast<long>(params.min_class_mass)) + " needed)";
    return out;
  }
  if (out.separation < params.min_separation) {
    out.refused = "its edges are not separable from grey edges";
    return out;
  }
  // The class's own shortest few: below them, clutter of the class's colour is all that is left.
  std::vector<double> member_length;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (class_posterior(*m, theta_a, x[i]) >= 0.5) member_length.push_back(length[i]);
  ClassThresholds t;
  t.max_angle_deg = static_cast<float>(*cut);
  t.min_projection = static_cast<float>(projection_floor(contrast_floor, *cut));
  t.min_length = static_cast<float>(percentile(member_length, params.length_percentile));
  out.thresholds = t;
  return out;
}

}  // namespace

Calibration calibrate(std::span<const Segment> segments, const Thresholds& start, const CalibrationParams& params) {
  Calibration out;
  out.segments = segments.size();
  if (segments.size() < params.min_segments) {
    const std::string why = "too few segments (" + std::to_string(segments.size()) + ", at least " +
                            std::to_string(params.min_segments) + " needed)";
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
  for (const Segment& s : segments) {
    normal_norms.push_back(normal_gradient_norm(s));
    const SegmentFeatures f = compute_features(s, start);
    boundary.push_back({f.boundary.angle_deg, f.boundary.projection, f.length});
    // For a straight edge grad_x and grad_y are one colour vector scaled by the normal's
    // components: the dominant one measures the same angle with less noise.
    const int m = f.marking_count == 2 && norm3(s.grad_x) > norm3(s.grad_y) ? 1 : 0;
    marking.push_back({f.marking[m].angle_deg, f.marking[m].projection, f.length});
  }
  out.contrast_floor = percentile(normal_norms, params.floor_percentile);
  out.marking = fit_class(marking, start.marking, out.contrast_floor, params);
  out.boundary = fit_class(boundary, start.boundary, out.contrast_floor, params);
  return out;
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
                          {"fit_rows", k.fit_rows}, {"iterations", k.iterations},
                          {"fitted", k.thresholds.has_value()},
                          {"refused", k.thresholds ? nlohmann::json(nullptr) : nlohmann::json(k.refused)}};
  };
  return {{"method", "label-free"},
          {"contrast_floor", c.contrast_floor},
          {"fit", {{"marking", class_json(c.marking)}, {"boundary", class_json(c.boundary)}}}};
}

}  // namespace fieldlines
