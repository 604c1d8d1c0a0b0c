// Over ~400 lines on purpose: the exact polish (Polisher) and train() share the threshold
// encoding (Dim, ref, to_thresholds) and are one algorithm; split, each half would need the other.
#include "fieldlines/train/training.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <thread>

#include "fieldlines/detect/enum_names.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/train/feature_table.hpp"

namespace fieldlines {
namespace {

enum class Which { Projection, Angle, Length };

// One trained threshold: which class, which of its three thresholds, and its search range.
struct Dim {
  bool boundary = false;
  Which which = Which::Projection;
  Range range;
};

std::vector<Dim> dims_for(const TrainParams& p) {
  std::vector<Dim> d;
  const auto add = [&](bool boundary, const ThresholdBounds& b) {
    d.push_back({boundary, Which::Projection, b.projection});
    d.push_back({boundary, Which::Angle, b.angle_deg});
    d.push_back({boundary, Which::Length, b.length});
  };
  if (p.target != TrainClass::Marking) add(true, p.boundary_bounds);
  if (p.target != TrainClass::Boundary) add(false, p.marking_bounds);
  return d;
}

float& ref(Thresholds& t, const Dim& d) {
  ClassThresholds& c = d.boundary ? t.boundary.thresholds : t.marking.thresholds;
  return d.which == Which::Projection ? c.min_projection
         : d.which == Which::Angle    ? c.max_angle_deg
                                      : c.min_length;
}

Thresholds to_thresholds(const Thresholds& start, const std::vector<Dim>& dims, const double* x) {
  Thresholds t = start;
  for (std::size_t k = 0; k < dims.size(); ++k) {
    const Range r = dims[k].range;
    ref(t, dims[k]) = static_cast<float>(r.lo + x[k] * (static_cast<double>(r.hi) - r.lo));
  }
  return t;
}

// Adds (sign +1) or removes (-1) one segment's outcome from the counts.
void tally_signed(Counts& c, Label truth, Label predicted, long sign) {
  for (const Label cls : {Label::Marking, Label::Boundary}) {
    ClassCounts& cc = cls == Label::Marking ? c.marking : c.boundary;
    if (predicted == cls && truth == cls) cc.tp += sign, cc.fn -= sign;
    else if (predicted == cls) cc.fp += sign;
  }
}

class Polisher {
 public:
  Polisher(const FeatureTable& f, const TrainParams& p, std::vector<Dim> dims)
      : f_(f), p_(p), dims_(std::move(dims)) {
    // Every sweep visits segments in the order of one feature; sorting once here keeps each
    // sweep linear. Marking orders hold (segment, test) pairs as 2 * segment + test.
    const auto n = static_cast<std::uint32_t>(f_.size());
    const auto sorted = [](std::uint32_t count, auto value) {
      std::vector<std::uint32_t> o(count);
      std::iota(o.begin(), o.end(), 0u);
      std::stable_sort(o.begin(), o.end(), [&](std::uint32_t a, std::uint32_t b) { return value(a) > value(b); });
      return o;
    };
    by_length_ = sorted(n, [&](std::uint32_t i) { return f_.length[i]; });
    by_boundary_proj_ = sorted(n, [&](std::uint32_t i) { return f_.boundary_proj[i]; });
    by_boundary_angle_ = sorted(n, [&](std::uint32_t i) { return -f_.boundary_angle[i]; });
    by_marking_proj_ = sorted(2 * n, [&](std::uint32_t e) { return f_.marking_proj[e & 1][e >> 1]; });
    by_marking_angle_ = sorted(2 * n, [&](std::uint32_t e) { return -f_.marking_angle[e & 1][e >> 1]; });
  }

  double score(const Thresholds& t) const {
    return p_.objective.score(target_counts(f_.count(t.boundary.thresholds, t.marking.thresholds), p_.target));
  }

  // Coordinate ascent with exact 1-D optimisation per threshold, then centring of each
  // threshold in its interval of equal score (a max-margin choice that generalises better
  // than sitting on a data point).
  double polish(Thresholds& t) {
    double best = score(t);
    // Best-improvement: of all single-threshold moves take the best one, which avoids
    // committing early to the first axis that happens to improve.
    for (int pass = 0; pass < 1000; ++pass) {
      const Dim* best_dim = nullptr;
      float best_value = 0;
      for (const Dim& d : dims_) {
        const Sweep s = sweep(t, d);
        for (std::size_t i = 0; i < s.score.size(); ++i) {
          if (s.score[i] > best + 1e-9) {
            best = s.score[i];
            best_dim = &d;
            best_value = s.value(i);
          }
        }
      }
      if (best_dim == nullptr) break;
      ref(t, *best_dim) = best_value;
    }
    for (const Dim& d : dims_) centre(t, d);
    return best;
  }

 private:
  // Candidate values of one threshold, best-first order irrelevant: cand[i] (in the sweep's
  // internal "min-type" orientation, descending) with its score.
  struct Sweep {
    bool negated = false;        // max-type thresholds (angle) are swept as -value
    std::vector<float> cand;     // descending, internal orientation
    std::vector<double> score;
    float lo = 0;                // internal lower bound (inclusive)
    float value(std::size_t i) const { return negated ? -cand[i] : cand[i]; }
  };

  Sweep sweep(const Thresholds& t, const Dim& d) const {
    const ClassThresholds& b = t.boundary.thresholds;
    const ClassThresholds& m = t.marking.thresholds;
    const std::size_t n = f_.size();
    struct Item {
      float key;
      Label in, out;
      Label truth;
    };
    std::vector<Item> items;
    items.reserve(n);
    std::vector<float> keys(n, NAN);
    std::vector<Label> ins(n), outs(n);
    Counts base{};
    base.marking.fn = f_.positives_marking;
    base.boundary.fn = f_.positives_boundary;
    const bool negated = d.which == Which::Angle;
    for (std::size_t i = 0; i < n; ++i) {
      const float len = f_.length[i];
      const bool pb = len >= b.min_length && f_.boundary_proj[i] >= b.min_projection &&
                      f_.boundary_angle[i] <= b.max_angle_deg;
      bool pm_tuple[2];
      for (int k = 0; k < 2; ++k)
        pm_tuple[k] = f_.marking_proj[k][i] >= m.min_projection && f_.marking_angle[k][i] <= m.max_angle_deg;
      const bool pm_raw = len >= m.min_length && (pm_tuple[0] || pm_tuple[1]);
      // key: the threshold value at which this segment switches from `out` to `in`
      // (in iff key >= threshold, in the internal orientation); NaN = never switches.
      float key = NAN;
      Label in = Label::None, out = Label::None;
      if (d.boundary) {
        in = Label::Boundary;
        out = pm_raw ? Label::Marking : Label::None;
        const bool pj = f_.boundary_proj[i] >= b.min_projection;
        const bool an = f_.boundary_angle[i] <= b.max_angle_deg;
        const bool ln = len >= b.min_length;
        if (d.which == Which::Projection && an && ln) key = f_.boundary_proj[i];
        if (d.which == Which::Angle && pj && ln) key = -f_.boundary_angle[i];
        if (d.which == Which::Length && pj && an) key = len;
      } else {
        in = Label::Marking;
        out = pb ? Label::Boundary : Label::None;
        if (!pb) {
          if (d.which == Which::Projection && len >= m.min_length) {
            for (int k = 0; k < 2; ++k)
              if (f_.marking_angle[k][i] <= m.max_angle_deg && !(f_.marking_proj[k][i] <= key))
                key = f_.marking_proj[k][i];  // the largest qualifying projection
          } else if (d.which == Which::Angle && len >= m.min_length) {
            for (int k = 0; k < 2; ++k)
              if (f_.marking_proj[k][i] >= m.min_projection && !(-f_.marking_angle[k][i] <= key))
                key = -f_.marking_angle[k][i];  // the smallest qualifying angle, negated
          } else if (d.which == Which::Length && (pm_tuple[0] || pm_tuple[1])) {
            key = len;
          }
        }
      }
      tally_signed(base, f_.truth[i], out, +1);
      keys[i] = key, ins[i] = in, outs[i] = out;
    }
    // Emit the segments in descending key order by walking the matching presorted order; a
    // segment's key is the value of its first qualifying entry there.
    const bool tuples = !d.boundary && d.which != Which::Length;
    const std::vector<std::uint32_t>& order =
        d.which == Which::Length ? by_length_
        : d.boundary             ? (d.which == Which::Projection ? by_boundary_proj_ : by_boundary_angle_)
                                 : (d.which == Which::Projection ? by_marking_proj_ : by_marking_angle_);
    std::vector<char> emitted(n, 0);
    for (const std::uint32_t e : order) {
      const std::uint32_t i = tuples ? e >> 1 : e;
      if (emitted[i] || std::isnan(keys[i])) continue;
      const float v = !tuples ? keys[i]
                      : d.which == Which::Projection ? f_.marking_proj[e & 1][i]
                                                     : -f_.marking_angle[e & 1][i];
      if (v != keys[i]) continue;  // the other, non-qualifying test of this segment
      emitted[i] = 1;
      items.push_back({keys[i], ins[i], outs[i], f_.truth[i]});
    }
    Sweep s;
    s.negated = negated;
    const float lo = negated ? -d.range.hi : d.range.lo;
    const float hi = negated ? -d.range.lo : d.range.hi;
    s.lo = lo;
    std::size_t i = 0;
    const auto take_while = [&](auto pred) {
      for (; i < items.size() && pred(items[i].key); ++i) {
        tally_signed(base, items[i].truth, items[i].out, -1);
        tally_signed(base, items[i].truth, items[i].in, +1);
      }
    };
    take_while([&](float k) { return k >= hi; });
    s.cand.push_back(hi);
    s.score.push_back(p_.objective.score(target_counts(base, p_.target)));
    while (i < items.size() && items[i].key >= lo) {
      const float k = items[i].key;
      take_while([&](float kk) { return kk == k; });
      s.cand.push_back(k);
      s.score.push_back(p_.objective.score(target_counts(base, p_.target)));
    }
    return s;
  }

  void centre(Thresholds& t, const Dim& d) const {
    const Sweep s = sweep(t, d);
    const float cur = s.negated ? -ref(t, d) : ref(t, d);
    // The candidate whose interval holds the current value: the last one >= cur.
    std::size_t j = 0;
    while (j + 1 < s.cand.size() && s.cand[j + 1] >= cur) ++j;
    std::size_t a = j, z = j;
    while (a > 0 && s.score[a - 1] == s.score[j]) --a;
    while (z + 1 < s.cand.size() && s.score[z + 1] == s.score[j]) ++z;
    const float upper = s.cand[a];
    float v;
    if (z + 1 == s.cand.size()) {
      v = 0.5f * (s.lo + upper);  // interval [lo, upper]
    } else {
      const float lower = s.cand[z + 1];  // interval (lower, upper]
      v = 0.5f * (lower + upper);
      if (!(v > lower)) v = upper;
    }
    ref(t, d) = s.negated ? -v : v;
  }

  const FeatureTable& f_;
  const TrainParams& p_;
  std::vector<Dim> dims_;
  std::vector<std::uint32_t> by_length_, by_boundary_proj_, by_boundary_angle_, by_marking_proj_, by_marking_angle_;
};

}  // namespace

// Namespace-scope constexpr: internal linkage.
constexpr EnumNames<TrainClass, 3> kClassNames{
    {{{TrainClass::Marking, "marking"}, {TrainClass::Boundary, "boundary"}, {TrainClass::Both, "both"}}}};

std::string_view to_string(TrainClass c) { return kClassNames.name(c); }
bool parse_train_class(std::string_view text, TrainClass& out) { return kClassNames.parse(text, out); }

double Objective::score(const ClassCounts& c) const {
  switch (kind) {
    case Kind::TpMinusFp: return static_cast<double>(c.tp) - fp_cost * static_cast<double>(c.fp);
    case Kind::F1: return c.f1();
    case Kind::FBeta: break;
  }
  return c.fbeta(beta);
}

std::string Objective::name() const {
  char buf[32];
  if (kind == Kind::TpMinusFp) {
    if (fp_cost == 1.0) return "tp-fp";
    std::snprintf(buf, sizeof buf, "tp-fp:%g", fp_cost);
    return buf;
  }
  if (kind == Kind::F1) return "f1";
  std::snprintf(buf, sizeof buf, "fbeta:%g", beta);
  return buf;
}

Objective parse_objective(std::string_view text) {
  Objective o;
  if (text == "tp-fp") return o;
  if (text.starts_with("tp-fp:")) {
    const std::string num(text.substr(6));
    char* end = nullptr;
    const double c = std::strtod(num.c_str(), &end);
    if (!num.empty() && end == num.c_str() + num.size() && std::isfinite(c) && c > 0 && c <= 100) {
      o.fp_cost = c;
      return o;
    }
  }
  if (text == "f1") return o.kind = Objective::Kind::F1, o;
  if (text.starts_with("fbeta:")) {
    const std::string num(text.substr(6));
    char* end = nullptr;
    const double b = std::strtod(num.c_str(), &end);
    if (!num.empty() && end == num.c_str() + num.size() && std::isfinite(b) && b > 0 && b <= 100) {
      o.kind = Objective::Kind::FBeta;
      o.beta = b;
      return o;
    }
  }
  throw Error("objective must be tp-fp, tp-fp:C, f1 or fbeta:B with 0 < B, C <= 100, got '" + std::string(text) + "'");
}

ClassCounts target_counts(const Counts& c, TrainClass target) {
  if (target == TrainClass::Marking) return c.marking;
  if (target == TrainClass::Boundary) return c.boundary;
  ClassCounts both = c.marking;
  both += c.boundary;
  return both;
}

void validate(const ThresholdBounds& b) {
  const auto check = [](const Range& r, const char* name, float max) {
    if (!(std::isfinite(r.lo) && std::isfinite(r.hi) && r.lo <= r.hi && r.lo >= -1e6f && r.hi <= max))
      throw Error(std::string("bounds for ") + name + " must be finite with lo <= hi <= " +
                  std::to_string(static_cast<int>(max)));
  };
  check(b.projection, "min projection", 1e6f);
  check(b.angle_deg, "max angle", 180.f);
  check(b.length, "min length", 1e6f);
}

TrainResult train(std::span<const Segment> labelled, const Thresholds& start, const TrainParams& params,
                  const TrainingCallback& on_progress, std::stop_token stop,
                  const LabelledCandidates& candidates) {
  validate(params.pso);
  validate(params.marking_bounds);
  validate(params.boundary_bounds);
  if (params.threads < 1 || params.threads > 256) throw Error("threads must be in 1..256");
  const FeatureTable full(labelled, start, candidates);
  if (full.size() == 0) throw Error("no labelled segments to train on");
  // Marking only: rows the fixed boundary thresholds claim can never become markings, so they
  // are dropped from the hot loop and the boundary test is switched off inside it.
  Thresholds inner_start = start;
  FeatureTable reduced;
  if (params.target == TrainClass::Marking) {
    reduced = full.without_boundary_hits(start.boundary.thresholds);
    inner_start.boundary.thresholds.min_length = INFINITY;
  }
  const FeatureTable& table = params.target == TrainClass::Marking ? reduced : full;
  const std::vector<Dim> dims = dims_for(params);
  const int nd = static_cast<int>(dims.size());

  const auto score_range = [&](std::span<const double> x, std::span<double> scores, std::size_t begin,
                               std::size_t end) {
    for (std::size_t p = begin; p < end; ++p) {
      const Thresholds t = to_thresholds(inner_start, dims, x.data() + p * dims.size());
      scores[p] = params.objective.score(
          target_counts(table.count(t.boundary.thresholds, t.marking.thresholds), params.target));
    }
  };
  const SwarmObjective objective = [&](std::span<const double> x, std::span<double> scores) {
    const std::size_t n = scores.size();
    const std::size_t workers = std::min<std::size_t>(static_cast<std::size_t>(params.threads), n);
    if (workers <= 1) return score_range(x, scores, 0, n);
    std::vector<std::jthread> pool;
    for (std::size_t w = 1; w < workers; ++w)
      pool.emplace_back([&, w] { score_range(x, scores, n * w / workers, n * (w + 1) / workers); });
    score_range(x, scores, 0, n / workers);
  };
  std::vector<Thresholds> particle_thresholds;
  const PsoCallback report = [&](const PsoIteration& it) {
    if (!on_progress) return;
    particle_thresholds.clear();
    for (std::size_t p = 0; p < it.scores.size(); ++p)
      particle_thresholds.push_back(to_thresholds(start, dims, it.positions.data() + p * dims.size()));
    TrainingProgress prog;
    prog.iteration = it.iteration;
    prog.iterations = params.pso.iterations;
    prog.best_score = it.best_score;
    prog.best = to_thresholds(start, dims, it.best_position.data());
    prog.particles = particle_thresholds;
    prog.scores = it.scores;
    on_progress(prog);
  };
  const PsoResult pso = pso_maximise(nd, params.pso, objective, report, stop);

  TrainResult r;
  r.iterations_run = pso.iterations_run;
  r.cancelled = pso.cancelled;
  r.thresholds = to_thresholds(inner_start, dims, pso.best_position.data());
  r.pso_score = pso.best_score;
  r.score = pso.best_score;
  std::vector<Thresholds> polished;  // where each polish start ended, for the Polish report
  std::vector<double> polished_scores;
  if (params.polish && !r.cancelled) {
    Polisher polisher(table, params, dims);
    // Several starts cost little (each polish is a few sorts) and escape the odd local optimum
    // of coordinate ascent.
    std::vector<std::size_t> order(pso.personal_best_scores.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return pso.personal_best_scores[a] > pso.personal_best_scores[b];
    });
    std::vector<Thresholds> starts;
    const auto add_start = [&](const Thresholds& t) {
      if (std::find(starts.begin(), starts.end(), t) != starts.end()) return false;
      starts.push_back(t);
      return true;
    };
    add_start(r.thresholds);
    // Corners of the box (all of them for one class; for both, the most permissive and the most
    // restrictive): optima often sit on a bound (everything passes on one axis), where
    // coordinate ascent from the interior can stall.
    const std::size_t corners = dims.size() <= 3 ? std::size_t{1} << dims.size() : 2;
    for (std::size_t c = 0; c < corners; ++c) {
      std::vector<double> x(dims.size());
      for (std::size_t k = 0; k < dims.size(); ++k)
        x[k] = corners == 2 ? ((dims[k].which == Which::Angle) == (c == 0) ? 1.0 : 0.0) : double((c >> k) & 1);
      add_start(to_thresholds(inner_start, dims, x.data()));
    }
    // Counted apart from the corners, so their number never eats into the particle bests.
    for (const std::size_t p : order) {
      if (r.polished_particle_bests >= params.polish_starts) break;
      if (add_start(to_thresholds(inner_start, dims, pso.personal_best_positions.data() + p * dims.size())))
        ++r.polished_particle_bests;
    }
    double best = -INFINITY;
    polished.reserve(starts.size());
    for (Thresholds t : starts) {
      const double s = polisher.polish(t);
      if (s > best) best = s, r.thresholds = t;
      polished.push_back(t);
      polished_scores.push_back(s);
    }
    r.score = best;
  }
  // Marking only: the search ran with the boundary test switched off; put the fixed one back.
  const auto with_start_boundary = [&](Thresholds& t) {
    if (params.target == TrainClass::Marking) t.boundary.thresholds = start.boundary.thresholds;
  };
  with_start_boundary(r.thresholds);
  r.counts = full.count(r.thresholds.boundary.thresholds, r.thresholds.marking.thresholds);
  r.score = params.objective.score(target_counts(r.counts, params.target));
  if (on_progress && !polished.empty()) {
    std::for_each(polished.begin(), polished.end(), with_start_boundary);
    TrainingProgress prog;
    prog.phase = TrainingPhase::Polish;
    prog.iteration = r.iterations_run;
    prog.iterations = params.pso.iterations;
    prog.best_score = r.score;
    prog.best = r.thresholds;
    prog.particles = polished;
    prog.scores = polished_scores;
    on_progress(prog);
  }
  return r;
}

}  // namespace fieldlines
