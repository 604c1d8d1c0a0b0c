#include "fieldlines/synth/gt_eval.hpp"

#include <algorithm>
#include <cmath>

#include "fieldlines/detect/error.hpp"
#include "segment_distance.hpp"

namespace fieldlines {
namespace {

using synth::direction;
using synth::Unit;

float distance_to_piece(float px, float py, const GtEdges::Edge& e) {
  return synth::nearest_on_piece(px, py, e.ax, e.ay, e.bx, e.by).distance;
}

float distance_to_segment(float px, float py, const Segment& s) {
  const GtEdges::Edge e{Label::None, s.x0, s.y0, s.x1, s.y1, false};
  return distance_to_piece(px, py, e);
}

}  // namespace

void validate(const GtMatchParams& p) {
  if (!(p.max_distance_px > 0 && p.max_distance_px <= 50)) throw Error("max_distance_px must be in (0, 50]");
  if (!(p.max_angle_deg >= 0 && p.max_angle_deg <= 90)) throw Error("max_angle_deg must be in [0, 90]");
  if (!(p.min_match > 0 && p.min_match <= 1)) throw Error("min_match must be in (0, 1]");
  if (!(p.min_width_px >= 0 && p.min_width_px <= 100)) throw Error("min_width_px must be in [0, 100]");
}

GtClassScore& GtClassScore::operator+=(const GtClassScore& o) {
  predicted += o.predicted, correct += o.correct;
  visible_px += o.visible_px, covered_px += o.covered_px;
  return *this;
}

GtScore& GtScore::operator+=(const GtScore& o) {
  marking += o.marking, boundary += o.boundary;
  none_predicted += o.none_predicted, none_correct += o.none_correct;
  images += o.images;
  return *this;
}

GtEdges::GtEdges(const synth::GroundTruth& truth, const GtMatchParams& params) : params_(params) {
  validate(params);
  for (const synth::TruthFeature& f : truth.features) {
    for (std::size_t i = 1; i < f.points.size(); ++i) {
      const synth::TruthPoint& p = f.points[i - 1];
      const synth::TruthPoint& q = f.points[i];
      if (f.label == Label::Boundary) {
        edges_.push_back({Label::Boundary, p.x, p.y, q.x, q.y, true});
        continue;
      }
      const Unit d = direction(p.x, p.y, q.x, q.y);
      const float nx = -d.y, ny = d.x;
      const bool visible = (p.width + q.width) / 2 >= params.min_width_px;
      for (const float side : {-0.5f, 0.5f})
        edges_.push_back({Label::Marking, p.x + side * p.width * nx, p.y + side * p.width * ny,
                          q.x + side * q.width * nx, q.y + side * q.width * ny, visible});
    }
  }
}

Label GtEdges::truth_label(const Segment& s) const {
  const float len = std::hypot(s.x1 - s.x0, s.y1 - s.y0);
  const int n = std::max(2, static_cast<int>(std::ceil(len)) + 1);
  const Unit ds = direction(s.x0, s.y0, s.x1, s.y1);
  const float cos_max = synth::cos_of_degrees(params_.max_angle_deg);
  // Edges parallel to the segment and near its bounding box: the only candidates.
  std::vector<const Edge*> near;
  const float pad = params_.max_distance_px;
  const float x0 = std::min(s.x0, s.x1) - pad, x1 = std::max(s.x0, s.x1) + pad;
  const float y0 = std::min(s.y0, s.y1) - pad, y1 = std::max(s.y0, s.y1) + pad;
  for (const Edge& e : edges_) {
    if (std::max(e.ax, e.bx) < x0 || std::min(e.ax, e.bx) > x1 || std::max(e.ay, e.by) < y0 ||
        std::min(e.ay, e.by) > y1)
      continue;
    if (!synth::parallel(direction(e.ax, e.ay, e.bx, e.by), ds, cos_max)) continue;
    near.push_back(&e);
  }
  if (near.empty()) return Label::None;
  // Far from the camera a painted line and the wall foot can be closer than the match distance;
  // when both classes match, the one nearer to the segment wins.
  int marking = 0, boundary = 0;
  double marking_dist = 0, boundary_dist = 0;
  const float far = 1e9f;
  for (int i = 0; i < n; ++i) {
    const float t = static_cast<float>(i) / static_cast<float>(n - 1);
    const float px = s.x0 + t * (s.x1 - s.x0), py = s.y0 + t * (s.y1 - s.y0);
    float dm = far, db = far;
    for (const Edge* e : near) {
      float& d = e->label == Label::Marking ? dm : db;
      d = std::min(d, distance_to_piece(px, py, *e));
    }
    if (dm <= params_.max_distance_px) ++marking, marking_dist += dm;
    if (db <= params_.max_distance_px) ++boundary, boundary_dist += db;
  }
  const float need = params_.min_match * static_cast<float>(n);
  const bool is_marking = static_cast<float>(marking) >= need, is_boundary = static_cast<float>(boundary) >= need;
  if (is_marking && is_boundary)
    return marking_dist / marking <= boundary_dist / boundary ? Label::Marking : Label::Boundary;
  if (is_marking) return Label::Marking;
  if (is_boundary) return Label::Boundary;
  return Label::None;
}

GtScore GtEdges::score(std::span<const Segment> detected) const {
  GtScore out;
  out.images = 1;
  std::vector<Label> truths;  // per detected segment
  truths.reserve(detected.size());
  for (const Segment& s : detected) {
    const Label truth = truths.emplace_back(truth_label(s));
    switch (s.label) {
      case Label::Marking:
        ++out.marking.predicted, out.marking.correct += truth == Label::Marking;
        break;
      case Label::Boundary:
        ++out.boundary.predicted, out.boundary.correct += truth == Label::Boundary;
        break;
      default:
        ++out.none_predicted, out.none_correct += truth == Label::None;
        break;
    }
  }
  for (const Edge& e : edges_)
    if (e.visible) (e.label == Label::Marking ? out.marking : out.boundary).visible_px += std::hypot(e.bx - e.ax, e.by - e.ay);
  walk(detected, truths, [&](const Edge& e, float, float, float step, Seen seen) {
    if (seen == Seen::Found) (e.label == Label::Marking ? out.marking : out.boundary).covered_px += step;
  });
  return out;
}

void GtEdges::walk(std::span<const Segment> detected, const EdgePointVisitor& visit) const {
  std::vector<Label> truths;
  truths.reserve(detected.size());
  for (const Segment& s : detected) truths.push_back(truth_label(s));
  walk(detected, truths, visit);
}

void GtEdges::walk(std::span<const Segment> detected, std::span<const Label> truths,
                   const EdgePointVisitor& visit) const {
  const float cos_max = synth::cos_of_degrees(params_.max_angle_deg);
  std::vector<const Segment*> parallel;
  std::vector<bool> counts;  // per parallel segment: predicted as the edge's class and truly of it
  for (const Edge& e : edges_) {
    if (!e.visible || !(std::hypot(e.bx - e.ax, e.by - e.ay) > 0)) continue;
    const Unit de = direction(e.ax, e.ay, e.bx, e.by);
    parallel.clear(), counts.clear();
    for (std::size_t k = 0; k < detected.size(); ++k) {
      const Segment& s = detected[k];
      if (!synth::parallel(de, direction(s.x0, s.y0, s.x1, s.y1), cos_max)) continue;
      parallel.push_back(&s);
      // Only correctly labelled segments cover a line: predicted as this class and true members.
      counts.push_back(s.label == e.label && truths[k] == e.label);
    }
    synth::along(e.ax, e.ay, e.bx, e.by, [&](float px, float py, float step) {
      Seen seen = Seen::Missed;
      for (std::size_t k = 0; k < parallel.size() && seen != Seen::Found; ++k)
        if (distance_to_segment(px, py, *parallel[k]) <= params_.max_distance_px)
          seen = counts[k] ? Seen::Found : Seen::OnSegment;
      visit(e, px, py, step, seen);
    });
  }
}

std::array<long, 3> label_from_truth(std::span<Segment> segments, const synth::GroundTruth& truth,
                                     const GtMatchParams& params) {
  const GtEdges edges(truth, params);
  std::array<long, 3> counts{0, 0, 0};
  for (Segment& s : segments) {
    s.label = edges.truth_label(s);
    ++counts[static_cast<std::size_t>(s.label)];
  }
  return counts;
}

}  // namespace fieldlines
