#pragma once
// Threshold training: PSO over the bounded thresholds of one class (or both), then an exact
// polish that sweeps each threshold over the data's own breakpoints until nothing improves.
//
// Usage:  TrainParams p;  p.target = TrainClass::Marking;
//         TrainResult r = train(labelled_segments, Thresholds{}, p);
// Safe to run on a worker thread: it only reads its inputs, reports through `on_progress`
// (called on the calling thread) and stops early when `stop` is requested.
#include <functional>
#include <span>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/train/feature_table.hpp"
#include "fieldlines/train/metrics.hpp"
#include "fieldlines/train/pso.hpp"

namespace fieldlines {

enum class TrainClass { Marking, Boundary, Both };
std::string_view to_string(TrainClass c);
bool parse_train_class(std::string_view text, TrainClass& out);  // marking|boundary|both

// What training maximises, on the trained class's counts (pooled over both classes for Both).
struct Objective {
  enum class Kind { TpMinusFp, F1, FBeta } kind = Kind::TpMinusFp;  // TP - FP is the paper's
  double beta = 1.0;     // FBeta only
  // TpMinusFp only: TP - fp_cost * FP. A group of segments is worth admitting when its precision
  // exceeds fp_cost / (1 + fp_cost): 1 (the paper's) admits anything above 1/2. The "ours"
  // protocol's cost is set in protocol_spec() (protocols.cpp says why).
  double fp_cost = 1.0;
  double score(const ClassCounts& c) const;
  std::string name() const;  // "tp-fp", "tp-fp:1.5", "f1", "fbeta:2"
};
// Parses "tp-fp", "tp-fp:C", "f1" or "fbeta:B" (0 < B, C <= 100); throws fieldlines::Error otherwise.
Objective parse_objective(std::string_view text);

// The class's counts the objective sees (marking, boundary, or both pooled).
ClassCounts target_counts(const Counts& c, TrainClass target);

struct Range {
  float lo = 0, hi = 0;
  bool operator==(const Range&) const = default;
};

struct ThresholdBounds {
  // The reference implementation's search box.
  Range projection{10, 255};
  Range angle_deg{20, 70};
  Range length{50, 300};
  bool operator==(const ThresholdBounds&) const = default;
};
void validate(const ThresholdBounds& b);  // throws fieldlines::Error on lo > hi, NaN, angle > 180

struct TrainParams {
  TrainClass target = TrainClass::Marking;
  Objective objective;
  PsoParams pso;
  ThresholdBounds marking_bounds, boundary_bounds;
  bool polish = true;     // exact breakpoint polish after PSO
  int polish_starts = 8;  // also polish this many of the best distinct particle bests (besides
                          // the PSO best and the box corners)
  int threads = 1;        // workers scoring the swarm (1 = the calling thread only)
};

// Passed to the callback after every PSO iteration and, when the polish runs, once more after
// it (phase Polish), so that a progress display ends on the result's own score rather than on
// the PSO's lower one. The spans are only valid during the call (copy what you keep, e.g. to
// hand to a UI thread).
enum class TrainingPhase { Pso, Polish };
struct TrainingProgress {
  TrainingPhase phase = TrainingPhase::Pso;
  int iteration = 0, iterations = 0;  // Polish: the PSO's iterations run, of its iterations
  double best_score = 0;              // Polish: exactly TrainResult::score
  Thresholds best;                        // the best thresholds so far (Polish: the result's)
  std::span<const Thresholds> particles;  // every particle's thresholds this iteration (Polish:
                                          // where each polish start ended)
  std::span<const double> scores;         // and their scores
};
using TrainingCallback = std::function<void(const TrainingProgress&)>;

struct TrainResult {
  Thresholds thresholds;  // `start` with the trained class(es) replaced
  double score = 0;       // objective on the training data
  double pso_score = 0;   // before the polish
  Counts counts;          // on the training data
  int iterations_run = 0;
  bool cancelled = false;
  // Distinct particle bests polished besides the PSO best and the box corners: polish_starts
  // unless the swarm has fewer distinct ones (0 without polish or when cancelled).
  int polished_particle_bests = 0;
};

// `labelled[i].label` is the human label; Unlabelled segments are ignored. `start` gives the
// colour classes, gradient mode and the thresholds of the class that is not trained.
// `candidates` (feature_table.hpp), parallel to `labelled`: what the detector's stripes check
// and field boundary gate let each segment be; the counts and the score are then the robot's.
// Throws fieldlines::Error on bad parameters or when there is nothing labelled.
TrainResult train(std::span<const Segment> labelled, const Thresholds& start, const TrainParams& params,
                  const TrainingCallback& on_progress = {}, std::stop_token stop = {},
                  const LabelledCandidates& candidates = {});

}  // namespace fieldlines
