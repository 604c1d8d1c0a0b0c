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
  Unit dir;
  float reach(float t, float margin_px) const { return 0.5f * (wa + t * (wb - wa)) + margin_px; }  // at t along it
};

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
      pieces.push_back({p.x, p.y, q.x, q.y, p.width, q.width, (p.width + q.width) / 2 >= params.min_width_px,
                        direction(p.x, p.y, q.x, q.y)});
    }
  }
  const float cos_max = cos_of_degrees(params.max_angle_deg);
  const auto dir_of = [](const Marking& m) { return direction(m.x0, m.y0, m.x1, m.y1); };
  CentreLineScore out;
  for (const Piece& piece : pieces) {
    if (!piece.visible) continue;
    along(piece.ax, piece.ay, piece.bx, piece.by, [&](float x, float y, float step) {
      const float reach = piece.reach(nearest_on_piece(x, y, piece.ax, piece.ay, piece.bx, piece.by).t, margin_px);
      out.truth_px += step;
      const bool near = std::any_of(markings.begin(), markings.end(), [&](const Marking& m) {
        return parallel(piece.dir, dir_of(m), cos_max) && nearest_on_piece(x, y, m.x0, m.y0, m.x1, m.y1).distance <= reach;
      });
      if (near) out.covered_px += step;
    });
  }
  for (const Marking& m : markings) {
    const Unit dir = dir_of(m);
    along(m.x0, m.y0, m.x1, m.y1, [&](float x, float y, float step) {
      out.detected_px += step;
      const bool on = std::any_of(pieces.begin(), pieces.end(), [&](const Piece& piece) {
        if (!parallel(piece.dir, dir, cos_max)) return false;
        const Nearest n = nearest_on_piece(x, y, piece.ax, piece.ay, piece.bx, piece.by);
        return n.distance <= piece.reach(n.t, margin_px);
      });
      if (on) out.on_line_px += step;
    });
  }
  return out;
}

}  // namespace fieldlines::synth
