#include "fieldlines/synth/centre_line_score.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "segment_distance.hpp"

namespace fieldlines::synth {
namespace {

// One straight piece of a truth line's centre, with its width at both ends.
struct Piece {
  float ax, ay, bx, by, wa, wb;
  bool visible;
};

bool parallel(float ax, float ay, float bx, float by, float cx, float cy, float dx, float dy, float cos_max) {
  const float ux = bx - ax, uy = by - ay, vx = dx - cx, vy = dy - cy;
  const float norms = std::hypot(ux, uy) * std::hypot(vx, vy);
  return norms > 0 && std::abs(ux * vx + uy * vy) >= cos_max * norms;
}

// Calls f(x, y, step) at the midpoints of 1 px steps along a-b.
template <class F>
void along(float ax, float ay, float bx, float by, F f) {
  const float len = std::hypot(bx - ax, by - ay);
  const int n = std::max(1, static_cast<int>(std::ceil(len)));
  for (int i = 0; i < n; ++i) {
    const float t = (static_cast<float>(i) + 0.5f) / static_cast<float>(n);
    f(ax + t * (bx - ax), ay + t * (by - ay), len / static_cast<float>(n));
  }
}

}  // namespace

CentreLineScore& CentreLineScore::operator+=(const CentreLineScore& o) {
  truth_px += o.truth_px, covered_px += o.covered_px, detected_px += o.detected_px, on_line_px += o.on_line_px;
  return *this;
}

CentreLineScore score_centre_lines(const GroundTruth& truth, std::span<const Marking> markings,
                                   const GtMatchParams& params, float margin_px) {
  validate(params);
  std::vector<Piece> pieces;
  for (const TruthFeature& f : truth.features) {
    if (f.label != Label::Marking) continue;
    for (std::size_t i = 1; i < f.points.size(); ++i) {
      const TruthPoint& p = f.points[i - 1];
      const TruthPoint& q = f.points[i];
      pieces.push_back({p.x, p.y, q.x, q.y, p.width, q.width, (p.width + q.width) / 2 >= params.min_width_px});
    }
  }
  const float cos_max = std::cos(params.max_angle_deg * 3.14159265f / 180.0f);
  CentreLineScore out;
  for (const Piece& piece : pieces) {
    if (!piece.visible) continue;
    along(piece.ax, piece.ay, piece.bx, piece.by, [&](float x, float y, float step) {
      const float t = nearest_on_piece(x, y, piece.ax, piece.ay, piece.bx, piece.by).t;
      const float reach = 0.5f * (piece.wa + t * (piece.wb - piece.wa)) + margin_px;
      out.truth_px += step;
      const bool near = std::any_of(markings.begin(), markings.end(), [&](const Marking& m) {
        return parallel(piece.ax, piece.ay, piece.bx, piece.by, m.x0, m.y0, m.x1, m.y1, cos_max) &&
               nearest_on_piece(x, y, m.x0, m.y0, m.x1, m.y1).distance <= reach;
      });
      if (near) out.covered_px += step;
    });
  }
  for (const Marking& m : markings)
    along(m.x0, m.y0, m.x1, m.y1, [&](float x, float y, float step) {
      out.detected_px += step;
      const bool on = std::any_of(pieces.begin(), pieces.end(), [&](const Piece& piece) {
        if (!parallel(piece.ax, piece.ay, piece.bx, piece.by, m.x0, m.y0, m.x1, m.y1, cos_max)) return false;
        const Nearest n = nearest_on_piece(x, y, piece.ax, piece.ay, piece.bx, piece.by);
        return n.distance <= 0.5f * (piece.wa + n.t * (piece.wb - piece.wa)) + margin_px;
      });
      if (on) out.on_line_px += step;
    });
  return out;
}

}  // namespace fieldlines::synth
