// PSO, the feature table, training optimality (brute force), metrics and splits.
// Long (~500 lines) because every case shares the synthetic segment sets and brute-force
// optimum at the top; split by topic, each file would repeat them.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <random>
#include <set>
#include <stop_token>
#include <string>
#include <thread>
#include <utility>

#include <gtest/gtest.h>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/train/feature_table.hpp"
#include "fieldlines/data/labelled_set.hpp"
#include "fieldlines/train/metrics.hpp"
#include "fieldlines/train/protocols.hpp"
#include "fieldlines/train/pso.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "fieldlines/train/splits.hpp"
#include "fieldlines/train/sweep.hpp"
#include "fieldlines/train/training.hpp"
#include "shared_data.hpp"

namespace fl = fieldlines;

namespace {

// Segments resembling the real ones: white lines (either gradient sign, on x or y), black-to-
// green boundaries, clutter; labels mostly agree with the look, with some noise.
std::vector<fl::Segment> synthetic(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<fl::Segment> out;
  for (int i = 0; i < n; ++i) {
    fl::Segment s;
    s.x0 = 100 * u(rng), s.y0 = 100 * u(rng), s.x1 = s.x0 + 200 * u(rng), s.y1 = s.y0 + 50 * u(rng);
    s.saliency = std::round(20 + 300 * u(rng));
    const int kind = static_cast<int>(u(rng) * 3);
    const float mag = 10 + 120 * u(rng);
    fl::Rgb g{};
    if (kind == 0) g = {mag * (u(rng) < .5f ? 1 : -1), 0, mag};  // white-ish vs green, on R and B
    if (kind == 1) g = {0, mag, 0};                             // black above green
    if (kind == 2) g = {mag * (u(rng) - .5f), mag * (u(rng) - .5f), mag * (u(rng) - .5f)};
    for (float& c : g) c += 15 * (u(rng) - .5f);
    (u(rng) < .5f ? s.grad_x : s.grad_y) = g;
    const fl::Label look = kind == 0 ? fl::Label::Marking : kind == 1 ? fl::Label::Boundary : fl::Label::None;
    s.label = u(rng) < .85f ? look : static_cast<fl::Label>(static_cast<int>(u(rng) * 3));
    out.push_back(s);
  }
  return out;
}

// Every threshold value that can change a classification inside the bounds: the bounds and the
// features that fall inside them. Exhaustive over the product, this is the true optimum.
std::vector<float> grid(std::vector<float> values, fl::Range r) {
  values.push_back(r.lo);
  values.push_back(r.hi);
  std::erase_if(values, [&](float v) { return !(v >= r.lo && v <= r.hi); });
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

double brute_force(const std::vector<fl::Segment>& segs, const fl::Thresholds& start, const fl::TrainParams& p) {
  std::vector<fl::SegmentFeatures> feats;
  for (const auto& s : segs) feats.push_back(fl::compute_features(s, start));
  const bool boundary = p.target == fl::TrainClass::Boundary;
  const fl::ThresholdBounds& b = boundary ? p.boundary_bounds : p.marking_bounds;
  std::vector<float> proj, ang, len;
  for (const auto& f : feats) {
    len.push_back(f.length);
    if (boundary) {
      proj.push_back(f.boundary.projection), ang.push_back(f.boundary.angle_deg);
    } else {
      for (int k = 0; k < f.marking_count; ++k)
        proj.push_back(f.marking[k].projection), ang.push_back(f.marking[k].angle_deg);
    }
  }
  double best = -INFINITY;
  fl::Thresholds t = start;
  fl::ClassThresholds& c = boundary ? t.boundary.thresholds : t.marking.thresholds;
  for (const float pv : grid(proj, b.projection))
    for (const float av : grid(ang, b.angle_deg))
      for (const float lv : grid(len, b.length)) {
        c = {pv, av, lv};
        fl::Counts counts;
        for (std::size_t i = 0; i < segs.size(); ++i) fl::tally(counts, segs[i].label, fl::classify(feats[i], t));
        best = std::max(best, p.objective.score(fl::target_counts(counts, p.target)));
      }
  return best;
}

fl::TrainParams small_params(fl::TrainClass target, std::uint64_t seed) {
  fl::TrainParams p;
  p.target = target;
  p.pso.seed = seed;
  return p;
}

}  // namespace

TEST(Pso, FindsTheMaximumOfASmoothFunctionAndIsDeterministic) {
  fl::PsoParams p;
  p.particles = 30;
  p.iterations = 80;
  p.seed = 42;
  const auto f = [](std::span<const double> x, std::span<double> s) {
    for (std::size_t i = 0; i < s.size(); ++i)
      s[i] = -std::pow(x[2 * i] - 0.3, 2) - std::pow(x[2 * i + 1] - 0.8, 2);
  };
  const fl::PsoResult a = fl::pso_maximise(2, p, f);
  const fl::PsoResult b = fl::pso_maximise(2, p, f);
  EXPECT_NEAR(a.best_position[0], 0.3, 1e-3);
  EXPECT_NEAR(a.best_position[1], 0.8, 1e-3);
  EXPECT_EQ(a.best_position, b.best_position);
  EXPECT_EQ(a.best_score, b.best_score);
  p.seed = 43;
  EXPECT_NE(fl::pso_maximise(2, p, f).best_position, a.best_position);
}

TEST(Pso, ReportsEveryIterationAndStopsOnRequest) {
  fl::PsoParams p;
  p.particles = 7;
  p.iterations = 50;
  std::stop_source stop;
  std::vector<double> bests;
  const auto f = [](std::span<const double> x, std::span<double> s) {
    for (std::size_t i = 0; i < s.size(); ++i) s[i] = x[i];
  };
  const auto r = fl::pso_maximise(1, p, f, [&](const fl::PsoIteration& it) {
    EXPECT_EQ(it.iteration, static_cast<int>(bests.size()) + 1);
    EXPECT_EQ(it.positions.size(), 7u);
    EXPECT_EQ(it.scores.size(), 7u);
    for (const double x : it.positions) EXPECT_TRUE(x >= 0 && x <= 1);
    bests.push_back(it.best_score);
    if (it.iteration == 5) stop.request_stop();
  }, stop.get_token());
  EXPECT_TRUE(r.cancelled);
  EXPECT_EQ(r.iterations_run, 5);
  ASSERT_EQ(bests.size(), 5u);
  EXPECT_TRUE(std::is_sorted(bests.begin(), bests.end()));
  p.particles = 0;
  EXPECT_THROW(fl::pso_maximise(1, p, f), fl::Error);
}

TEST(FeatureTable, CountsMatchTheClassifierInBothGradientModes) {
  const auto segs = synthetic(400, 3);
  for (const fl::GradientMode mode : {fl::GradientMode::Axes, fl::GradientMode::Normal}) {
    fl::Thresholds base;
    base.mode = mode;
    const fl::FeatureTable table(segs, base);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 1);
    for (int k = 0; k < 50; ++k) {
      fl::Thresholds t = base;
      t.boundary.thresholds = {100 * u(rng), 90 * u(rng), 300 * u(rng)};
      t.marking.thresholds = {100 * u(rng), 90 * u(rng), 300 * u(rng)};
      fl::LabelledSet set;
      for (const auto& s : segs) set.add("x", s);
      EXPECT_EQ(table.count(t.boundary.thresholds, t.marking.thresholds), fl::evaluate(set, t).total);
    }
  }
}

TEST(Training, ReachesTheBruteForceOptimumOnSmallCases) {
  for (unsigned seed = 1; seed <= 12; ++seed) {
    const auto segs = synthetic(45, seed);
    for (const fl::TrainClass target : {fl::TrainClass::Marking, fl::TrainClass::Boundary}) {
      for (const char* objective : {"tp-fp", "f1", "fbeta:0.5"}) {
        fl::TrainParams p = small_params(target, seed);
        p.objective = fl::parse_objective(objective);
        fl::Thresholds start;
        start.mode = seed % 2 ? fl::GradientMode::Axes : fl::GradientMode::Normal;
        const fl::TrainResult r = fl::train(segs, start, p);
        EXPECT_DOUBLE_EQ(r.score, brute_force(segs, start, p))
            << "seed " << seed << " class " << fl::to_string(target) << " " << objective;
        EXPECT_GE(r.score, r.pso_score);
        // The score reported is the score of the thresholds returned.
        fl::LabelledSet set;
        for (const auto& s : segs) set.add("x", s);
        EXPECT_EQ(fl::evaluate(set, r.thresholds).total, r.counts);
        const fl::ClassThresholds& c =
            target == fl::TrainClass::Marking ? r.thresholds.marking.thresholds : r.thresholds.boundary.thresholds;
        const fl::ThresholdBounds& b = p.marking_bounds;
        EXPECT_TRUE(c.min_projection >= b.projection.lo && c.min_projection <= b.projection.hi);
        EXPECT_TRUE(c.max_angle_deg >= b.angle_deg.lo && c.max_angle_deg <= b.angle_deg.hi);
        EXPECT_TRUE(c.min_length >= b.length.lo && c.min_length <= b.length.hi);
        // The untrained class keeps its thresholds.
        if (target == fl::TrainClass::Marking) EXPECT_EQ(r.thresholds.boundary, start.boundary);
        else EXPECT_EQ(r.thresholds.marking, start.marking);
      }
    }
  }
}

TEST(Training, BothClassesNeverScoreBelowTheStartAndAreDeterministic) {
  const auto segs = synthetic(600, 11);
  fl::TrainParams p = small_params(fl::TrainClass::Both, 9);
  p.pso.particles = 40;
  p.pso.iterations = 40;
  const auto a = fl::train(segs, {}, p);
  const auto b = fl::train(segs, {}, p);
  EXPECT_EQ(a.thresholds, b.thresholds);
  p.threads = 2;
  EXPECT_EQ(fl::train(segs, {}, p).thresholds, a.thresholds);  // threads change nothing
  fl::LabelledSet set;
  for (const auto& s : segs) set.add("x", s);
  const fl::Counts before = fl::evaluate(set, fl::Thresholds{}).total;
  EXPECT_GE(a.score, p.objective.score(fl::target_counts(before, fl::TrainClass::Both)));
}

TEST(Training, RunsOnAWorkerThreadAndCancels) {
  const auto segs = synthetic(2000, 4);
  fl::TrainParams p;
  p.pso.iterations = 100000;
  std::atomic<int> seen{0};
  std::stop_source stop;
  fl::TrainResult r;
  std::jthread worker([&] {
    r = fl::train(segs, {}, p, [&](const fl::TrainingProgress& prog) {
      EXPECT_EQ(prog.particles.size(), 100u);
      EXPECT_EQ(prog.scores.size(), 100u);
      seen = prog.iteration;
    }, stop.get_token());
  });
  while (seen < 3) std::this_thread::yield();
  stop.request_stop();
  worker.join();
  EXPECT_TRUE(r.cancelled);
  EXPECT_LT(r.iterations_run, 100000);
  EXPECT_GE(r.iterations_run, 3);
}

// The polish is reported as its own last step, carrying the result's score and thresholds, so a
// progress display never ends on the PSO's (lower) best while the result says more.
TEST(Training, ReportsThePolishAsItsOwnPhaseWithTheResultsScore) {
  const auto segs = synthetic(800, 5);
  for (const fl::TrainClass target : {fl::TrainClass::Marking, fl::TrainClass::Both}) {
    fl::TrainParams p;
    p.target = target;
    p.pso.particles = 6;
    p.pso.iterations = 3;  // a short swarm, so the polish has something left to gain
    std::vector<fl::TrainingPhase> phases;
    std::optional<fl::TrainingProgress> polish;
    std::vector<fl::Thresholds> polished;
    double last_pso_best = 0;
    const fl::TrainResult r = fl::train(segs, {}, p, [&](const fl::TrainingProgress& prog) {
      phases.push_back(prog.phase);
      if (prog.phase == fl::TrainingPhase::Pso) last_pso_best = prog.best_score;
      if (prog.phase != fl::TrainingPhase::Polish) return;
      polish = prog;
      polished.assign(prog.particles.begin(), prog.particles.end());
      polish->particles = {}, polish->scores = {};  // only valid during the call
      EXPECT_EQ(prog.particles.size(), prog.scores.size());
    });
    SCOPED_TRACE(std::string(fl::to_string(target)));
    ASSERT_EQ(phases.size(), 4u);  // three iterations, then the polish
    EXPECT_EQ(std::count(phases.begin(), phases.end(), fl::TrainingPhase::Pso), 3);
    EXPECT_EQ(phases.back(), fl::TrainingPhase::Polish);
    ASSERT_TRUE(polish.has_value());
    EXPECT_EQ(polish->best_score, r.score);
    EXPECT_EQ(polish->best, r.thresholds);
    EXPECT_EQ(polish->iteration, r.iterations_run);
    EXPECT_EQ(polish->iterations, 3);
    // The case the studio's line got wrong: the polish gained on the swarm's last best.
    EXPECT_GT(r.score, last_pso_best);
    // Polished starts: the PSO best, the corners and the particle bests, each with the untrained
    // class's thresholds as given (not the search's switched-off boundary test).
    EXPECT_GE(polished.size(), 1u + static_cast<std::size_t>(r.polished_particle_bests));
    if (target == fl::TrainClass::Marking) {
      for (const fl::Thresholds& t : polished) EXPECT_EQ(t.boundary.thresholds, fl::Thresholds{}.boundary.thresholds);
    }
  }
  // Without the polish, or stopped, there is no polish step.
  fl::TrainParams p;
  p.pso.iterations = 3;
  p.polish = false;
  int polish_reports = 0;
  fl::train(segs, {}, p, [&](const fl::TrainingProgress& prog) { polish_reports += prog.phase == fl::TrainingPhase::Polish; });
  EXPECT_EQ(polish_reports, 0);
  p.polish = true;
  std::stop_source stop;
  stop.request_stop();
  const fl::TrainResult stopped = fl::train(segs, {}, p, [&](const fl::TrainingProgress& prog) {
    polish_reports += prog.phase == fl::TrainingPhase::Polish;
  }, stop.get_token());
  EXPECT_TRUE(stopped.cancelled);
  EXPECT_EQ(polish_reports, 0);
}

// polish_starts particle bests are polished on top of the PSO best and the box corners, for one
// class as for both (the corners once filled the start list and crowded them out).
TEST(Training, PolishesTheRequestedNumberOfParticleBests) {
  const auto segs = synthetic(600, 3);
  for (const fl::TrainClass target : {fl::TrainClass::Marking, fl::TrainClass::Boundary, fl::TrainClass::Both}) {
    for (const int starts : {0, 3, 8, 20}) {
      fl::TrainParams p = small_params(target, 2);
      p.pso.iterations = 20;
      p.polish_starts = starts;
      std::size_t polish_starts_run = 0;  // the polish phase reports one result per start
      const fl::TrainResult r = fl::train(segs, {}, p, [&](const fl::TrainingProgress& prog) {
        if (prog.phase == fl::TrainingPhase::Polish) polish_starts_run = prog.particles.size();
      });
      EXPECT_EQ(r.polished_particle_bests, starts) << fl::to_string(target) << " " << starts;
      // What ran, counted from outside: the box corners (8 for one class's 3 thresholds, 2 for
      // both) and the particle bests, plus the PSO best unless it sits on a corner. The old list
      // stopped at 11 starts for one class and 5 for both, whatever polish_starts said.
      const std::size_t corners = target == fl::TrainClass::Both ? 2 : 8;
      EXPECT_GE(polish_starts_run, corners + static_cast<std::size_t>(starts)) << fl::to_string(target) << " " << starts;
      EXPECT_LE(polish_starts_run, 1 + corners + static_cast<std::size_t>(starts)) << fl::to_string(target) << " " << starts;
      // More starts only add candidates: the best of them can never score lower.
      if (starts > 0) {
        p.polish_starts = 0;
        EXPECT_GE(r.score, fl::train(segs, {}, p).score) << fl::to_string(target) << " " << starts;
      }
    }
  }
  fl::TrainParams p = small_params(fl::TrainClass::Marking, 2);
  p.polish = false;
  EXPECT_EQ(fl::train(segs, {}, p).polished_particle_bests, 0);
}

TEST(Training, RejectsBadInput) {
  fl::TrainParams p;
  EXPECT_THROW(fl::train({}, {}, p), fl::Error);
  p.marking_bounds.angle_deg = {70, 20};
  EXPECT_THROW(fl::train(synthetic(10, 1), {}, p), fl::Error);
  EXPECT_THROW(fl::parse_objective("fbeta:-1"), fl::Error);
  EXPECT_THROW(fl::parse_objective("accuracy"), fl::Error);
  EXPECT_EQ(fl::parse_objective("fbeta:2").name(), "fbeta:2");
  EXPECT_THROW(fl::parse_objective("tp-fp:0"), fl::Error);
  EXPECT_THROW(fl::parse_objective("tp-fp:"), fl::Error);
  EXPECT_THROW(fl::parse_objective("tp-fp:1.5x"), fl::Error);
}

// TP - C FP: "tp-fp" is C = 1; the name round-trips; the ours protocol weighs a FP 1.5 TPs.
TEST(Training, CostWeightedObjective) {
  const fl::Objective o = fl::parse_objective("tp-fp:1.5");
  EXPECT_EQ(o.kind, fl::Objective::Kind::TpMinusFp);
  EXPECT_DOUBLE_EQ(o.score({10, 4, 3}), 10 - 1.5 * 4);
  EXPECT_EQ(o.name(), "tp-fp:1.5");
  EXPECT_EQ(fl::parse_objective(o.name()).fp_cost, 1.5);
  EXPECT_EQ(fl::parse_objective("tp-fp").name(), "tp-fp");
  EXPECT_DOUBLE_EQ(fl::parse_objective("tp-fp").score({10, 4, 3}), 6);
  EXPECT_EQ(fl::protocol_spec(fl::Protocol::Ours).train.objective.name(), "tp-fp:1.5");
  EXPECT_EQ(fl::protocol_spec(fl::Protocol::Paper).train.objective.name(), "tp-fp");
  // A cluster of 5 true and 4 false short segments is admitted by TP - FP (precision 0.56 > 1/2,
  // +1) and left out by TP - 1.5 FP (0.56 < 3/5, -1): the min length moves above it.
  std::vector<fl::Segment> segs;
  fl::Segment marking;
  marking.grad_y = {-100, -60, -100};  // passes the default marking projection and angle
  for (int i = 0; i < 10; ++i) {
    marking.saliency = 200, marking.label = fl::Label::Marking;
    segs.push_back(marking);
  }
  for (int i = 0; i < 9; ++i) {
    marking.saliency = 30, marking.label = i < 5 ? fl::Label::Marking : fl::Label::None;
    segs.push_back(marking);
  }
  fl::TrainParams p = fl::protocol_spec(fl::Protocol::Ours).train;
  p.pso.particles = 20, p.pso.iterations = 10;
  EXPECT_GT(fl::train(segs, {}, p).thresholds.marking.thresholds.min_length, 30);
  p.objective = fl::parse_objective("tp-fp");
  EXPECT_LE(fl::train(segs, {}, p).thresholds.marking.thresholds.min_length, 30);
}

// What the detector drops whatever its colours (a marking that is no stripe, a boundary edge
// off the field boundary) is never predicted that class: the counts are the robot's.
TEST(FeatureTable, CandidatesGateEachClassAsTheDetectorDoes) {
  const auto segs = synthetic(400, 7);
  std::vector<std::uint8_t> may_mark(segs.size()), may_bound(segs.size());
  for (std::size_t i = 0; i < segs.size(); ++i) may_mark[i] = i % 3 != 0, may_bound[i] = i % 5 != 0;
  const fl::Thresholds t;
  const fl::FeatureTable table(segs, t, {may_mark, may_bound});
  fl::Counts expected;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    fl::Thresholds own = t;  // the class the segment may not be switched off for it alone
    if (!may_bound[i]) own.boundary.thresholds.min_length = INFINITY;
    if (!may_mark[i]) own.marking.thresholds.min_length = INFINITY;
    fl::tally(expected, segs[i].label, fl::classify(segs[i], own));
  }
  EXPECT_EQ(table.count(t.boundary.thresholds, t.marking.thresholds), expected);
  EXPECT_NE(fl::FeatureTable(segs, t).count(t.boundary.thresholds, t.marking.thresholds), expected);
  const std::vector<std::uint8_t> short_flags(segs.size() - 1, 1);
  EXPECT_THROW(fl::FeatureTable(segs, t, {short_flags, {}}), fl::Error);
  EXPECT_THROW(fl::train(segs, t, fl::TrainParams{}, {}, {}, {{}, short_flags}), fl::Error);
}

// A short cluster of 5 markings and 4 nones is left out by TP - 1.5 FP; when the detector's
// stripes check drops the 4 nones anyway, training that knows it admits the cluster.
TEST(Training, NonesTheDetectorDropsDoNotShrinkTheBox) {
  std::vector<fl::Segment> segs;
  std::vector<std::uint8_t> may_mark;
  fl::Segment marking;
  marking.grad_y = {-100, -60, -100};
  for (int i = 0; i < 19; ++i) {
    marking.saliency = i < 10 ? 200 : 30;
    marking.label = i < 15 ? fl::Label::Marking : fl::Label::None;
    segs.push_back(marking);
    may_mark.push_back(i < 15);
  }
  fl::TrainParams p = fl::protocol_spec(fl::Protocol::Ours).train;
  p.pso.particles = 20, p.pso.iterations = 10;
  const fl::TrainResult blind = fl::train(segs, {}, p);
  const fl::TrainResult gated = fl::train(segs, {}, p, {}, {}, {may_mark, {}});
  EXPECT_GT(blind.thresholds.marking.thresholds.min_length, 30);
  EXPECT_LE(gated.thresholds.marking.thresholds.min_length, 30);
  EXPECT_EQ(gated.counts.marking.tp, 15);
  EXPECT_EQ(gated.counts.marking.fp, 0);
}

TEST(Metrics, CountsPerClassAndPerImage) {
  fl::LabelledSet set;
  fl::Segment marking;  // white above green on grad_y: passes the default marking thresholds
  marking.grad_y = {-100, -60, -100};
  marking.saliency = 200;
  fl::Segment clutter;  // no gradient: predicted none
  clutter.saliency = 200;
  marking.label = fl::Label::Marking;
  set.add("a", marking);  // TP
  clutter.label = fl::Label::Marking;
  set.add("a", clutter);  // FN
  marking.label = fl::Label::None;
  set.add("b", marking);  // FP
  clutter.label = fl::Label::Unlabelled;
  set.add("b", clutter);  // ignored
  const fl::Evaluation ev = fl::evaluate(set, {});
  EXPECT_EQ(ev.total.marking, (fl::ClassCounts{1, 1, 1}));
  EXPECT_EQ(ev.total.boundary, (fl::ClassCounts{0, 0, 0}));
  ASSERT_EQ(ev.per_image.size(), 2u);
  EXPECT_EQ(ev.per_image[0].counts.marking, (fl::ClassCounts{1, 0, 1}));
  EXPECT_EQ(ev.per_image[1].counts.marking, (fl::ClassCounts{0, 1, 0}));
  EXPECT_DOUBLE_EQ(ev.total.marking.precision(), 0.5);
  EXPECT_DOUBLE_EQ(ev.total.marking.recall(), 0.5);
  EXPECT_DOUBLE_EQ(ev.total.marking.f1(), 0.5);
  EXPECT_DOUBLE_EQ(ev.total.boundary.precision(), 0.0);  // 0/0 is reported as 0
  EXPECT_DOUBLE_EQ((fl::ClassCounts{3, 1, 2}).fbeta(2), 5.0 * 3 / (5.0 * 3 + 4 * 2 + 1));
}

TEST(Splits, ByImageKeepsImagesWholeAndIsSeeded) {
  fl::LabelledSet set;
  for (const auto& s : synthetic(500, 2)) set.add("img" + std::to_string(static_cast<int>(s.x0) % 23), s);
  const fl::Split a = fl::split_train_test(set, fl::SplitMode::ByImage, 0.4, 7);
  const fl::Split b = fl::split_train_test(set, fl::SplitMode::ByImage, 0.4, 7);
  EXPECT_EQ(a.train, b.train);
  EXPECT_EQ(a.train.size() + a.test.size(), set.size());
  std::set<std::uint32_t> train_images, test_images;
  for (const auto i : a.train) train_images.insert(set.image_of[i]);
  for (const auto i : a.test) test_images.insert(set.image_of[i]);
  EXPECT_EQ(train_images.size(), 9u);  // round(0.4 * 23)
  for (const auto im : train_images) EXPECT_EQ(test_images.count(im), 0u);
  EXPECT_NE(fl::split_train_test(set, fl::SplitMode::ByImage, 0.4, 8).train, a.train);
  const fl::Split rows = fl::split_train_test(set, fl::SplitMode::ByRow, 0.4, 7);
  EXPECT_EQ(rows.train.size(), 200u);
  EXPECT_EQ(rows.test.size(), 300u);
  EXPECT_THROW(fl::split_train_test(set, fl::SplitMode::ByRow, 0.0, 1), fl::Error);
  EXPECT_THROW(fl::split_train_test(set, fl::SplitMode::ByRow, 1.5, 1), fl::Error);
}

TEST(Splits, KFoldTestsEveryRowExactlyOnce) {
  fl::LabelledSet set;
  for (const auto& s : synthetic(103, 2)) set.add("img" + std::to_string(static_cast<int>(s.x0) % 11), s);
  for (const fl::SplitMode mode : {fl::SplitMode::ByRow, fl::SplitMode::ByImage}) {
    const auto folds = fl::k_fold(set, mode, 5, 3);
    ASSERT_EQ(folds.size(), 5u);
    std::vector<int> tested(set.size(), 0);
    for (const auto& f : folds) {
      EXPECT_EQ(f.train.size() + f.test.size(), set.size());
      for (const auto i : f.test) ++tested[i];
    }
    for (const int t : tested) EXPECT_EQ(t, 1);
  }
  EXPECT_THROW(fl::k_fold(set, fl::SplitMode::ByImage, 12, 1), fl::Error);
  EXPECT_THROW(fl::k_fold(set, fl::SplitMode::ByRow, 1, 1), fl::Error);
}

// The authors' files: marking class, default boundary thresholds, reference bounds. The best
// TP - FP known for these files (443, 677, 608, 209, 147) excludes segments of saliency exactly
// 50; with the bound inclusive (our classifier's >=) D2, D3 and D4 gain 2 each.
TEST(TrainingShared, ReachesTheBestKnownTpMinusFpOnEveryFile) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl/annotations", dir);
  const std::pair<const char*, int> known[] = {{"D1_ssl_natural_light.csv", 443},
                                               {"D2_ssl_mixed_light.csv", 677},
                                               {"D3_ssl_artificial_light.csv", 608},
                                               {"D4_humanoid_kid.csv", 209},
                                               {"ssl_navigation.csv", 147}};
  for (const auto& [file, best] : known) {
    const auto rows = fl::read_reference_csv(dir / file);
    const fl::LabelledSet set = fl::labelled_set_from_rows(rows);
    fl::TrainParams p;
    p.objective = fl::parse_objective("tp-fp");  // the paper's objective, whose optima are known
    p.pso.seed = 1;
    p.marking_bounds.length.lo = std::nextafter(50.f, 51.f);
    EXPECT_EQ(fl::train(set.segments, {}, p).score, best) << file;
    p.marking_bounds.length.lo = 50;
    EXPECT_GE(fl::train(set.segments, {}, p).score, best) << file;
  }
}

TEST(TrainingShared, MatchesBruteForceOnASampleOfRealRows) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl/annotations/D4_humanoid_kid.csv", d4);
  const auto rows = fl::read_reference_csv(d4);
  std::vector<fl::Segment> segs;
  for (std::size_t i = 0; i < rows.size() && segs.size() < 60; i += 7) segs.push_back(rows[i].segment);
  fl::TrainParams p = small_params(fl::TrainClass::Marking, 5);
  EXPECT_DOUBLE_EQ(fl::train(segs, {}, p).score, brute_force(segs, {}, p));
}

// Table 3 at a 40% row split, median of 10 seeds: the paper's protocol lands near its published
// figures, and ours (TP - 1.5 FP) gains at least 0.10 recall for at most 0.03 precision on every file: against
// the published figure where there is one (D1-D4) and against the paper's protocol reproduced
// here on the same splits everywhere (ssl_navigation has no published figure).
TEST(TrainingShared, DefaultProtocolBeatsThePapersAtFortyPercent) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl/annotations", dir);
  struct Published {
    const char* file;
    std::optional<std::pair<double, double>> figure;  // precision, recall; none for nav
  };
  const Published published[] = {{"D1_ssl_natural_light.csv", {{0.98, 0.80}}},
                                 {"D2_ssl_mixed_light.csv", {{0.99, 0.82}}},
                                 {"D3_ssl_artificial_light.csv", {{0.98, 0.80}}},
                                 {"D4_humanoid_kid.csv", {{0.96, 0.56}}},
                                 {"ssl_navigation.csv", std::nullopt}};
  for (const Published& pub : published) {
    const fl::LabelledSet set = fl::labelled_set_from_rows(fl::read_reference_csv(dir / pub.file));
    fl::SweepParams sp;
    sp.fractions = {0.4};
    sp.split = fl::SplitMode::ByRow;
    sp.train = fl::protocol_spec(fl::Protocol::Paper).train;
    const fl::SweepCell paper = fl::run_sweep(set, sp)[0];
    sp.train = fl::protocol_spec(fl::Protocol::Ours).train;
    const fl::SweepCell ours = fl::run_sweep(set, sp)[0];
    if (pub.figure) {
      const auto [precision, recall] = *pub.figure;
      EXPECT_NEAR(paper.median_precision, precision, 0.05) << pub.file;
      EXPECT_NEAR(paper.median_recall, recall, 0.10) << pub.file;
      EXPECT_GE(ours.median_recall, recall + 0.10) << pub.file;
      EXPECT_GE(ours.median_precision, precision - 0.03) << pub.file;
    }
    EXPECT_GE(ours.median_recall, paper.median_recall + 0.10) << pub.file;
    EXPECT_GE(ours.median_precision, paper.median_precision - 0.03) << pub.file;
  }
}
