#pragma once
// Global-best particle swarm optimisation over the unit box [0,1]^dims (callers map their
// bounded parameters to it, so one set of weights suits every parameter's scale).
//
// Each iteration evaluates the whole swarm, updates personal and global bests, reports, then
// moves: v = w v + c1 r1 (pbest - x) + c2 r2 (gbest - x); x += v, clamped to the box (the velocity
// component is zeroed on a wall). Deterministic: same seed and objective, same result.
#include <cstdint>
#include <functional>
#include <span>
#include <stop_token>
#include <vector>

namespace fieldlines {

struct PsoParams {
  int particles = 100;
  int iterations = 100;      // swarm evaluations
  double inertia = 0.7;      // w
  double cognitive = 1.5;    // c1: pull towards the particle's own best
  double social = 1.5;       // c2: pull towards the swarm's best
  std::uint64_t seed = 1;
};

// Validates ranges; throws fieldlines::Error naming the bad field.
void validate(const PsoParams& params);

struct PsoIteration {
  int iteration = 0;                      // 1-based
  double best_score = 0;
  std::span<const double> best_position;  // dims values in [0,1]
  std::span<const double> positions;      // particles x dims, row-major, as evaluated
  std::span<const double> scores;         // particles
};

struct PsoResult {
  std::vector<double> best_position;
  double best_score = 0;
  std::vector<double> personal_best_positions;  // particles x dims
  std::vector<double> personal_best_scores;
  int iterations_run = 0;
  bool cancelled = false;
};

// Scores every row of `positions` (particles x dims) into `scores`; higher is better.
using SwarmObjective = std::function<void(std::span<const double> positions, std::span<double> scores)>;
using PsoCallback = std::function<void(const PsoIteration&)>;

// Stops early (cancelled = true, bests so far) when `stop` is requested between iterations.
PsoResult pso_maximise(int dims, const PsoParams& params, const SwarmObjective& objective,
                       const PsoCallback& on_iteration = {}, std::stop_token stop = {});

}  // namespace fieldlines
