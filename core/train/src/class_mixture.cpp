#include "class_mixture.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "fieldlines/train/percentile.hpp"

namespace fieldlines::detail {
namespace {

constexpr double kPi = std::numbers::pi;

double cauchy(double x, double centre, double scale) {
  const double d = x - centre;
  return scale / (kPi * (scale * scale + d * d));
}
double cauchy_below(double x, double centre, double scale) { return 0.5 + std::atan((x - centre) / scale) / kPi; }

// Median and MAD as a normal's sd, the robust seed of a component.
Normal robust_normal(std::vector<double> values, double min_sd) {
  Normal n;
  n.mean = median(values);
  for (double& v : values) v = std::abs(v - n.mean);
  n.sd = std::max(1.4826 * median(values), min_sd);
  return n;
}

constexpr double kMinAngleSd = 1.0, kMinMagnitudeSd = 0.05, kMinScale = 0.1;

}  // namespace

double Normal::density(double x) const {
  const double z = (x - mean) / sd;
  return std::exp(-0.5 * z * z) / (sd * std::sqrt(2 * kPi));
}
double Normal::upper_tail(double x) const { return 0.5 * std::erfc((x - mean) / (sd * std::numbers::sqrt2)); }
double Normal::below(double x) const { return 1 - upper_tail(x); }

ClassMixture::Parts ClassMixture::parts(const MixtureRow& r) const {
  return {w_class * class_angle.density(r.angle) * magnitude_density(class_magnitude, r.log_projection),
          w_achromatic * cauchy(r.angle, theta_a, achromatic_scale) *
              magnitude_density(achromatic_magnitude, r.log_projection),
          w_background / x_max * magnitude_density(background_magnitude, r.log_projection)};
}

double ClassMixture::class_responsibility(const MixtureRow& r) const {
  const Parts p = parts(r);
  const double total = p.class_part + p.achromatic_part + p.background_part;
  return total > 0 ? p.class_part / total : 0;
}

double ClassMixture::posterior_at_angle(double angle, double m_min) const {
  const double c = w_class * class_angle.density(angle) * magnitude_tail(class_magnitude, m_min);
  const double a = w_achromatic * cauchy(angle, theta_a, achromatic_scale) * magnitude_tail(achromatic_magnitude, m_min);
  const double b = w_background / x_max * magnitude_tail(background_magnitude, m_min);
  const double total = c + a + b;
  return total > 0 ? c / total : 0;
}

double ClassMixture::posterior_at_magnitude(double m, double a_max) const {
  const double c = w_class * (class_angle.below(a_max) - class_angle.below(0)) * magnitude_density(class_magnitude, m);
  const double a = w_achromatic *
                   (cauchy_below(a_max, theta_a, achromatic_scale) - cauchy_below(0, theta_a, achromatic_scale)) *
                   magnitude_density(achromatic_magnitude, m);
  const double b = w_background * std::min(a_max / x_max, 1.0) * magnitude_density(background_magnitude, m);
  const double total = c + a + b;
  return total > 0 ? c / total : 0;
}

std::optional<ClassMixture> fit_class_mixture(std::span<const MixtureRow> rows, double theta_a, double x_max,
                                              bool with_contrast, const MixtureFitParams& params) {
  std::vector<double> seed_angle, seed_magnitude, spike_magnitude, all_magnitude;
  for (const MixtureRow& r : rows) {
    all_magnitude.push_back(r.log_projection);
    if (r.angle < theta_a - params.seed_margin_deg) {
      seed_angle.push_back(r.angle);
      seed_magnitude.push_back(r.log_projection);
    } else {
      spike_magnitude.push_back(r.log_projection);
    }
  }
  if (seed_angle.size() < 2) return std::nullopt;
  const double n = double(rows.size());
  ClassMixture m;
  m.with_contrast = with_contrast;
  m.theta_a = theta_a;
  m.x_max = x_max;
  m.class_angle = robust_normal(seed_angle, 1.0);
  m.class_magnitude = robust_normal(seed_magnitude, kMinMagnitudeSd);
  m.background_magnitude = robust_normal(all_magnitude, kMinMagnitudeSd);
  m.background_magnitude.sd *= 2;  // broad: whatever the other two leave
  m.achromatic_magnitude = spike_magnitude.size() >= 2 ? robust_normal(spike_magnitude, kMinMagnitudeSd)
                                                        : m.background_magnitude;
  m.achromatic_scale = 1;
  m.w_class = 0.9 * double(seed_angle.size()) / n;
  m.w_achromatic = 0.9 - m.w_class;
  m.w_background = 0.1;

  std::vector<double> r_class(rows.size()), r_achromatic(rows.size());
  double previous = -INFINITY;
  for (int it = 0; it < params.max_iterations; ++it) {
    m.iterations = it + 1;
    double log_likelihood = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto [c, a, b] = m.parts(rows[i]);
      const double total = c + a + b;
      if (!(total > 0)) {
        r_class[i] = r_achromatic[i] = 0;
        continue;
      }
      log_likelihood += std::log(total);
      r_class[i] = c / total;
      r_achromatic[i] = a / total;
    }
    double n_class = 0, n_achromatic = 0;
    double sum_angle = 0, sum_class_m = 0, sum_achromatic_m = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      n_class += r_class[i];
      n_achromatic += r_achromatic[i];
      sum_angle += r_class[i] * rows[i].angle;
      sum_class_m += r_class[i] * rows[i].log_projection;
      sum_achromatic_m += r_achromatic[i] * rows[i].log_projection;
    }
    if (n_class < 1) return std::nullopt;
    // A set without a single grey edge (a clean synthetic field) keeps a trace of the grey
    // component instead of failing: the cut then falls where the class's own tail ends.
    const bool grey_seen = n_achromatic >= 1;
    n_achromatic = std::max(n_achromatic, 1e-3);
    m.w_class = n_class / n;
    m.w_achromatic = n_achromatic / n;
    m.w_background = std::max(0.0, 1.0 - m.w_class - m.w_achromatic);
    m.class_angle.mean = sum_angle / n_class;
    m.class_magnitude.mean = sum_class_m / n_class;
    if (grey_seen) m.achromatic_magnitude.mean = sum_achromatic_m / n_achromatic;
    double var_angle = 0, var_class_m = 0, var_achromatic_m = 0, scale2 = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const MixtureRow& r = rows[i];
      var_angle += r_class[i] * (r.angle - m.class_angle.mean) * (r.angle - m.class_angle.mean);
      var_class_m += r_class[i] * (r.log_projection - m.class_magnitude.mean) * (r.log_projection - m.class_magnitude.mean);
      var_achromatic_m += r_achromatic[i] * (r.log_projection - m.achromatic_magnitude.mean) *
                          (r.log_projection - m.achromatic_magnitude.mean);
      // Student-t (nu = 1) EM: each row's latent precision weight.
      const double z = (r.angle - theta_a) / m.achromatic_scale;
      scale2 += r_achromatic[i] * 2.0 / (1.0 + z * z) * (r.angle - theta_a) * (r.angle - theta_a);
    }
    m.class_angle.sd = std::max(std::sqrt(var_angle / n_class), kMinAngleSd);
    m.class_magnitude.sd = std::max(std::sqrt(var_class_m / n_class), kMinMagnitudeSd);
    if (grey_seen) m.achromatic_magnitude.sd = std::max(std::sqrt(var_achromatic_m / n_achromatic), kMinMagnitudeSd);
    m.achromatic_scale = std::max(std::sqrt(scale2 / n_achromatic), kMinScale);
    m.class_mass = n_class;
    if (std::abs(log_likelihood - previous) < params.tolerance * n) break;
    previous = log_likelihood;
  }
  return m;
}

}  // namespace fieldlines::detail
