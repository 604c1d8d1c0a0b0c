#pragma once
// The mixture label-free calibration fits per class, over two features of each segment: the
// angle a of its gradient to the class's transition and m = ln(projection) on it.
//   class       N(a; mean, sd) * N(m; mean, sd)            the class's own colour edges
//   achromatic  Cauchy(a; theta_A, scale) * N(m; mean, sd) grey edges: theta_A is physics
//   background  uniform(a on [0, x_max]) * N(m) of all rows fitted
// The angle alone separates the classes where the field's colours are saturated; where they
// are not (a grey-green carpet, white balance off, a shaded field), the class's mode runs into
// the grey spike and only the contrast tells them apart: painted lines are brighter edges than
// most grey clutter. The magnitude factor lets the fit use that, and degrades to the angle-only
// fit when both components have the same contrast.
#include <cstddef>
#include <optional>
#include <span>

namespace fieldlines::detail {

struct MixtureRow {
  double angle = 0;           // degrees, in [0, x_max]
  double log_projection = 0;  // ln of the projection on the transition
};

struct Normal {
  double mean = 0, sd = 1;
  double density(double x) const;
  double upper_tail(double x) const;  // P(X >= x)
  double below(double x) const;       // P(X <= x)
};

struct ClassMixture {
  bool with_contrast = true;  // false: the angle alone (every magnitude factor is 1)
  double theta_a = 0, x_max = 1;
  Normal class_angle, class_magnitude;
  double achromatic_scale = 1;
  Normal achromatic_magnitude, background_magnitude;
  double w_class = 0, w_achromatic = 0, w_background = 0;
  double class_mass = 0;  // the class's share of the rows, in rows
  int iterations = 0;

  struct Parts {
    double class_part, achromatic_part, background_part;  // weighted densities at a row
  };
  Parts parts(const MixtureRow& row) const;
  double class_responsibility(const MixtureRow& row) const;
  double magnitude_density(const Normal& n, double m) const { return with_contrast ? n.density(m) : 1; }
  double magnitude_tail(const Normal& n, double m) const { return with_contrast ? n.upper_tail(m) : 1; }
  // The class's posterior at angle a among edges of log projection >= m_min.
  double posterior_at_angle(double a, double m_min) const;
  // The class's posterior at log projection m among edges of angle <= a_max.
  double posterior_at_magnitude(double m, double a_max) const;
};

struct MixtureFitParams {
  double seed_margin_deg = 3;  // the class's seed: angles below theta_A - margin
  int max_iterations = 200;
  double tolerance = 1e-6;     // |delta log-likelihood| per row
};

// EM from a seed of the rows left of the spike, over both features or (with_contrast false) the
// angle alone. Empty when there is no such seed or the class
// component empties. `rows` must be sorted for the result not to depend on input order.
std::optional<ClassMixture> fit_class_mixture(std::span<const MixtureRow> rows, double theta_a, double x_max,
                                              bool with_contrast, const MixtureFitParams& params);

}  // namespace fieldlines::detail
