#pragma once
// Live retraining while the user labels: after every label change both classes are retrained
// in the background (fieldlines/train/review.hpp: label-free until a class has enough labels,
// then trained on the train split), and each result adds a point to the learning curve, so the
// user watches the classifier converge as they label.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "fieldlines/train/metrics.hpp"
#include "fieldlines/train/review.hpp"
#include "gui/model/job.hpp"
#include "gui/model/leave_one_out.hpp"
#include "gui/model/proposal_gate.hpp"

namespace fieldlines::studio {

// One retraining's inputs, copied so the worker shares nothing with the UI thread.
struct AutoTrainInput {
  std::vector<Segment> all;          // every segment of the project, for label-free calibration
  ProposalGate gates;                // of `all`: calibration fits each class on its candidates
  std::vector<Segment> train, test;  // the labelled segments of each split
  ProposalGate train_gates;          // of `train`: each class is trained on its candidates
  Thresholds start;
  ProposalParams params;
  // With too few test images: every label with its image, for leave-one-image-out figures.
  std::optional<LabelledSet> leave_one_out;
};

struct AutoTrainResult {
  ProposalThresholds made;
  Counts train_counts, test_counts;  // of made.thresholds on each split
  std::size_t train_segments = 0, test_segments = 0;
  bool few_test_images = false;  // leave-one-out was asked for
  LeaveOneOut leave_one_out;     // images = 0 when not asked for or fewer than 2 labelled images
  double elapsed_ms = 0;
};

// A point of the learning curve: the figures after a retraining on `labelled` labels.
struct CurvePoint {
  std::size_t labelled = 0, test_segments = 0;
  Counts test;  // on the test split (empty classes are n/a, ClassCounts::empty)
  // Too few test images to judge (leave_one_out.hpp): `test` holds leave-one-image-out counts
  // when there were labelled images enough, else the point has no figures (judged = false).
  bool leave_one_out = false;
  bool judged = true;
};

class AutoTrainJob {
 public:
  void start(AutoTrainInput input);
  bool running() const { return job_.running(); }
  // UI thread: the finished retraining, once (nullopt while running or when none finished).
  // A failed run leaves its reason in error().
  std::optional<AutoTrainResult> poll();
  void wait() { job_.wait(); }  // tests and shutdown
  const std::string& error() const { return error_; }

 private:
  Job<int, AutoTrainResult> job_;
  std::string error_;
};

// Live retraining's state: on or off, whether labels changed since the last start, the one
// background run, and the learning curve and one-line summary of what the runs did. The
// controller marks label changes, starts a run with its labels when due(), and adopts what
// poll() returns.
class LiveRetraining {
 public:
  explicit LiveRetraining(bool on) : on_(on) {}
  bool on() const { return on_; }
  // On: retrains the current labels at the next chance (the labels made while it was off).
  void set_on(bool on);
  void labels_changed() { pending_ = on_; }
  // A run is wanted: on, labels changed since the last start, none running.
  bool due() const { return on_ && pending_ && !job_.running(); }
  void start(AutoTrainInput input);
  // Labels changed, but there is nothing to learn from yet: no run, no longer due.
  void skip() { pending_ = false; }
  bool busy() const { return job_.running() || pending_; }
  // Once per frame: a finished run's result while on (added to the curve and the summary);
  // nothing while running, after a failure (the summary says why) or when turned off meanwhile.
  std::optional<AutoTrainResult> poll();
  void wait() { job_.wait(); }

  const std::vector<CurvePoint>& curve() const { return curve_; }
  const std::string& summary() const { return summary_; }

 private:
  bool on_;
  bool pending_ = false;
  AutoTrainJob job_;
  std::vector<CurvePoint> curve_;
  std::string summary_;
};

}  // namespace fieldlines::studio
