#include "fieldlines/train/pso.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/train/random.hpp"

namespace fieldlines {
void validate(const PsoParams& p) {
  const auto bad = [](const std::string& what) { throw Error("PSO parameter " + what); };
  if (p.particles < 1 || p.particles > 100000) bad("particles must be in 1..100000");
  if (p.iterations < 1 || p.iterations > 1000000) bad("iterations must be in 1..1000000");
  if (!(std::isfinite(p.inertia) && p.inertia >= 0 && p.inertia <= 2)) bad("inertia must be in [0, 2]");
  if (!(std::isfinite(p.cognitive) && p.cognitive >= 0 && p.cognitive <= 5)) bad("cognitive weight must be in [0, 5]");
  if (!(std::isfinite(p.social) && p.social >= 0 && p.social <= 5)) bad("social weight must be in [0, 5]");
}

PsoResult pso_maximise(int dims, const PsoParams& params, const SwarmObjective& objective,
                       const PsoCallback& on_iteration, std::stop_token stop) {
  validate(params);
  if (dims < 1) throw Error("PSO needs at least one dimension");
  const auto n = static_cast<std::size_t>(params.particles);
  const auto d = static_cast<std::size_t>(dims);
  // SplitMix64, not <random>'s distributions: a seed gives the same swarm with any standard library.
  SplitMix64 rng(params.seed);
  std::vector<double> x(n * d), v(n * d), scores(n);
  for (double& xi : x) xi = rng.uniform();
  for (double& vi : v) vi = 0.2 * rng.uniform() - 0.1;

  PsoResult r;
  r.personal_best_positions = x;
  r.personal_best_scores.assign(n, -INFINITY);
  r.best_position.assign(d, 0.5);
  r.best_score = -INFINITY;

  for (int it = 0; it < params.iterations; ++it) {
    if (stop.stop_requested()) {
      r.cancelled = true;
      break;
    }
    objective(x, scores);
    for (std::size_t p = 0; p < n; ++p) {
      // Strictly better only: ties keep the earlier point, which keeps runs reproducible.
      if (scores[p] > r.personal_best_scores[p]) {
        r.personal_best_scores[p] = scores[p];
        std::copy_n(x.begin() + static_cast<std::ptrdiff_t>(p * d), d,
                    r.personal_best_positions.begin() + static_cast<std::ptrdiff_t>(p * d));
      }
      if (scores[p] > r.best_score) {
        r.best_score = scores[p];
        std::copy_n(x.begin() + static_cast<std::ptrdiff_t>(p * d), d, r.best_position.begin());
      }
    }
    r.iterations_run = it + 1;
    if (on_iteration) on_iteration({it + 1, r.best_score, r.best_position, x, scores});
    if (it + 1 == params.iterations) break;
    for (std::size_t p = 0; p < n; ++p) {
      for (std::size_t k = 0; k < d; ++k) {
        const std::size_t i = p * d + k;
        const double r1 = rng.uniform(), r2 = rng.uniform();
        v[i] = params.inertia * v[i] + params.cognitive * r1 * (r.personal_best_positions[i] - x[i]) +
               params.social * r2 * (r.best_position[k] - x[i]);
        x[i] += v[i];
        if (x[i] < 0.0) x[i] = 0.0, v[i] = 0.0;
        if (x[i] > 1.0) x[i] = 1.0, v[i] = 0.0;
      }
    }
  }
  return r;
}

}  // namespace fieldlines
