#include "fieldlines/detect/field_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <optional>

#include "features/field_pixel.hpp"
#include "fieldlines/detect/light.hpp"

namespace fieldlines {
namespace {

using Point = FieldBoundary::Point;

// > 0 when a lies above the chord o-b on screen (y down): a point the upper hull keeps.
double cross(const Point& o, const Point& a, const Point& b) {
  return double(a.x - o.x) * (b.y - o.y) - double(a.y - o.y) * (b.x - o.x);
}

// `out.points` from `out.columns`: their tops median-filtered, the upper hull over them, its
// steep ends dropped.
void hull_of_columns(FieldBoundary& out, const FieldBoundaryParams& params, float fall) {
  out.points.clear();
  // Median of each column's top with its neighbours (a fixed window: no allocation). The
  // filtered tops go into `points` first, then the hull is built in place over them.
  const int half = std::clamp(params.median_columns, 1, 15) / 2;
  const int n = static_cast<int>(out.columns.size());
  for (int i = 0; i < n; ++i) {
    std::array<float, 15> window{};
    int k = 0;
    for (int j = std::max(0, i - half); j <= std::min(n - 1, i + half); ++j) window[k++] = out.columns[j].y;
    std::nth_element(window.begin(), window.begin() + k / 2, window.begin() + k);
    out.points.push_back({out.columns[i].x, window[k / 2]});
  }
  // Upper hull (Andrew's monotone chain over x): drop a point that lies below the chord of its
  // neighbours, so notches close and the outline stays convex from above.
  std::size_t kept = 0;
  for (int i = 0; i < n; ++i) {
    const Point p = out.points[i];
    while (kept >= 2 && cross(out.points[kept - 2], out.points[kept - 1], p) <= 0) --kept;
    out.points[kept++] = p;
  }
  out.points.resize(kept);
  // Steep ends fall to an occluder or unrecognised turf at the side, not to the field's edge.
  const auto steeper = [](const Point& end, const Point& inner, float slope) {
    return end.y > inner.y && end.y - inner.y > slope * std::abs(end.x - inner.x);
  };
  const auto at = [&](int i) -> const Point& { return out.points[static_cast<std::size_t>(i)]; };
  int lo = 0, hi = static_cast<int>(kept) - 1;  // the points kept
  // From end `e` inwards (`dir` +1 from the left, -1 from the right) past the pieces steeper than
  // `slope`, keeping at least two points.
  const auto inwards = [&](int e, int dir, float slope) {
    int i = e;
    while (hi - lo - std::abs(i - e) >= 2 && steeper(at(i), at(i + dir), slope)) i += dir;
    return i;
  };
  for (const int dir : {1, -1}) {
    int& e = dir > 0 ? lo : hi;
    // A shoulder: pieces steeper than `shoulder_slope` that together fall by at least `fall`
    // px. A field's edge falls as steeply only for a few columns at the frame's side.
    if (const int i = inwards(e, dir, params.shoulder_slope); at(e).y - at(i).y >= fall) e = i;
    e = inwards(e, dir, params.max_end_slope);
  }
  if (lo > 0) std::copy(out.points.begin() + lo, out.points.begin() + hi + 1, out.points.begin());
  out.points.resize(static_cast<std::size_t>(hi - lo + 1));
}

// The column's top, settled: scanning down from `top`, each field sample (or turf chained from
// one: FieldBoundaryParams::settle_chain_step) weighs +1 and a band
// without field -cost per sample, when it is at least `band` px long, or `paint_band` px with at
// least a third of it paint: a light floor strip before the next field behind this one reads as
// paint, which the scan crosses (a painted line has this field beyond it, which pays for it).
// Not when the column's field reaches the frame's top: what lies above it is unseen, and a wide
// line under the top edge is no floor. The top moves to the field sample above which the weight
// is least, the lowest on a tie (nothing moves when all that lies above pays for itself). Stops
// once one more band inside the field (shorter than the gap) could no longer bring the weight
// back below its least.
int settle_top(const cv::Mat& bgr8, const FieldPixel& pixel, int x, int top, int bottom, int row_step, int band,
               int paint_band, float cost, int gap, const FieldBoundaryParams& params) {
  const float give_up = cost * float(gap / row_step);
  float weight = 0, least = 0;
  int settled = top, bare = 0, painted = 0;  // the current band's samples without field
  ChainedTurf turf(pixel, params.settle_chain_step, params.settle_chain_saturation);
  for (int y = top; y <= bottom; y += row_step) {
    const std::uint8_t* p = bgr8.ptr<std::uint8_t>(y) + 3 * x;
    if (turf.field(p)) {
      const bool floor_strip = top >= row_step && 2 * painted >= bare && (bare + painted) * row_step >= paint_band;
      if (bare * row_step >= band || floor_strip) weight -= cost * float(bare + painted);
      bare = painted = 0;
      if (weight <= least) least = weight, settled = y;
      if ((weight += 1) - least > give_up) break;
    } else {
      ++(pixel.paint(p) ? painted : bare);
    }
  }
  return settled;
}

// The column's top raised to the top of a line painted along the turf's edge: scanning up from
// the top, at most kBlurSamples samples in all that are neither paint nor dark, paint at most
// `line` px long in one run, then a dark sample (the field's dark surround, a wall's foot). A
// touchline often lies right at the turf's edge with nothing of the turf beyond it in view; paint
// never raises the top elsewhere, since a white wall or a light floor reads as paint too (those
// are wider, or not followed by dark). `top` when there is no such line.
int edge_line_top(const cv::Mat& bgr8, const FieldPixel& pixel, int x, int top, int row_step, int line) {
  constexpr int kBlurSamples = 4;
  int blur = 0, painted = 0;
  bool in_paint = false;  // the sample below y is paint
  for (int y = top - row_step; y >= 0; y -= row_step) {
    const std::uint8_t* p = bgr8.ptr<std::uint8_t>(y) + 3 * x;
    const bool paint = pixel.paint(p);
    if (paint) {
      if ((painted > 0 && !in_paint) || (painted += row_step) > line) return top;  // two runs, or too wide
    } else if (pixel.dark(p)) {
      return painted > 0 ? y + row_step : top;
    } else if (pixel.field(p) || ++blur > kBlurSamples) {
      return top;
    }
    in_paint = paint;
  }
  return top;
}

}  // namespace

float FieldBoundary::y_at(float x) const {
  if (points.empty()) return -1;
  if (x <= points.front().x) return points.front().y;
  if (x >= points.back().x) return points.back().y;
  const auto it = std::lower_bound(points.begin(), points.end(), x, [](const Point& p, float v) { return p.x < v; });
  const Point& b = *it;
  const Point& a = *(it - 1);
  return b.x > a.x ? a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x) : b.y;
}

float FieldBoundary::highest() const {
  return points.empty() ? -1.f : std::ranges::min(points, {}, &Point::y).y;
}

bool FieldBoundary::fills_top() const {
  // A column's scan samples every row_step (2) rows from the bottom: its top sample is row 0 or 1.
  constexpr float kTopRow = 1;
  const auto at_top = std::ranges::count_if(columns, [](const Point& c) { return c.y <= kTopRow; });
  return !columns.empty() && 2 * static_cast<std::size_t>(at_top) >= columns.size();
}

namespace {
constexpr float kBlurPx = 4;  // a line's own blur: how far above the boundary still counts as on it
}  // namespace

bool lies_above(float x, float y, const FieldBoundary& boundary) {
  return !boundary.empty() && y < boundary.y_at(x) - kBlurPx;
}

float along_band_px(int image_height) {
  constexpr float kAlongShare = 0.03f, kMinAlongPx = 6;
  return std::max(kMinAlongPx, kAlongShare * float(image_height));
}

BoundaryPlace place_of(const Segment& s, const FieldBoundary& boundary) {
  if (boundary.empty()) return BoundaryPlace::Below;
  const float mx = 0.5f * (s.x0 + s.x1), my = 0.5f * (s.y0 + s.y1);
  const float d = my - boundary.y_at(mx);
  if (std::abs(d) <= along_band_px(boundary.image_height)) return BoundaryPlace::Along;
  return lies_above(mx, my, boundary) ? BoundaryPlace::Above : BoundaryPlace::Below;
}

Label gate_by_field_boundary(const Segment& s, const FieldBoundary& boundary) {
  if (boundary.empty()) return s.label;
  const BoundaryPlace place = place_of(s, boundary);
  if (s.label == Label::Marking && place == BoundaryPlace::Above) return Label::None;
  if (s.label == Label::Boundary && place != BoundaryPlace::Along) return Label::None;
  return s.label;
}

void find_field_boundary(const cv::Mat& bgr8, FieldBoundary& out, const FieldBoundaryParams& params) {
  out.clear();
  if (const std::optional<Rgb> field = estimate_field_colour(bgr8)) find_field_boundary(bgr8, *field, out, params);
}

void find_field_boundary(const cv::Mat& bgr8, const Rgb& field, FieldBoundary& out, const FieldBoundaryParams& params,
                         const TurfColours* turf) {
  out.clear();
  out.image_height = bgr8.rows;
  if (bgr8.empty() || bgr8.type() != CV_8UC3) return;
  const FieldPixel pixel(field, params, turf);
  const int paint_cap = static_cast<int>(std::lround(params.max_paint_fraction * bgr8.rows));
  const int column_step = std::max(params.column_step, 1), row_step = std::max(params.row_step, 1);
  const int gap = std::max(params.min_gap_px, static_cast<int>(std::lround(params.gap_fraction * bgr8.rows)));
  // Between two field samples none changes anything when they are at most `gap` apart: the
  // upper one resets the counters, and a run shorter than the gap ends nothing. So inside the
  // field the sample up to `jump` steps up is tested first, and those between are skipped when
  // it is field: a few reads per column instead of one per step, and the same tops (nor does a
  // lone band, min_top_samples, fit between the two).
  const auto share_of_gap = [&](double f) { return std::max(row_step, static_cast<int>(std::lround(f * gap))); };
  const int band = share_of_gap(params.band_fraction), paint_band = share_of_gap(params.paint_band_fraction);
  const int lone_band = share_of_gap(params.lone_band_fraction);
  const int jump = std::clamp(std::min(gap / row_step, (lone_band - 1) / row_step), 0, std::max(params.max_jump, 0));
  const int edge_line = static_cast<int>(std::lround(params.edge_line_fraction * bgr8.rows));
  // One column's scan from row `from` up to row `ceiling`: the top of its field (-1: none), the
  // row where a stretch without field longer than the gap ended it (-1: none did) and the row of
  // the first field sample it met.
  struct Scan {
    int top = -1, stop = -1, first = -1;
  };
  const auto scan_column = [&](int x, int from, int ceiling) {
    Scan s;
    int top = -1, since_green = 0, paint = 0;
    // Samples: the run of field ending at the sample below y (0: that sample is none), the run
    // of none, the run of none below the current run of field.
    int run = 0, bare = 0, bare_below = 0;
    // Whether the current run of field may be the top (FieldBoundaryParams::min_top_samples).
    const auto trusted = [&] { return top < 0 || run >= params.min_top_samples || bare_below * row_step < lone_band; };
    for (int y = from; y >= ceiling; y -= row_step) {
      if (const int j = std::min(jump, (y - ceiling) / row_step);
          run > 0 && trusted() && j > 0 && pixel.field(bgr8.ptr<std::uint8_t>(y - j * row_step) + 3 * x)) {
        top = y -= j * row_step;
        since_green = paint = 0;
        continue;
      }
      const std::uint8_t* p = bgr8.ptr<std::uint8_t>(y) + 3 * x;
      if (pixel.field(p)) {
        if (run++ == 0) bare_below = bare;
        bare = 0;
        if (s.first < 0) s.first = y;
        if (trusted()) top = y;  // a lone sample carries the scan on, but is no top
        since_green = paint = 0;
        continue;
      }
      run = 0, ++bare;
      if (top >= 0 && pixel.paint(p) && (paint += row_step) <= paint_cap) {
        // A painted line, however wide near the camera, is part of the field: it neither
        // ends the field nor raises its top (unless it lies along the turf's edge: edge_line_top).
      } else if (top >= 0 && (since_green += row_step) > gap) {
        s.stop = y;
        break;  // the field ended above `top`; below the first field pixel (the robot's own
                // body, a lens's dark corner) nothing ends it
      }
    }
    if (top >= 0) {
      const int settled = settle_top(bgr8, pixel, x, top, from, row_step, band, paint_band, params.band_cost, gap, params);
      s.top = settled == top ? edge_line_top(bgr8, pixel, x, top, row_step, edge_line) : settled;
    }
    return s;
  };
  const int bottom = bgr8.rows - 1 - row_step / 2;
  int scanned = 0;
  for (int x = column_step / 2; x < bgr8.cols; x += column_step) {
    ++scanned;
    const Scan s = scan_column(x, bottom, 0);
    if (s.top < 0) continue;
    out.columns.push_back({float(x), float(s.top)});
    out.scan_ends.push_back(s.stop);
  }
  if (out.columns.size() < std::max<std::size_t>(2, static_cast<std::size_t>(params.min_columns * scanned))) return;
  const float shoulder_fall_px = float(gap) * params.shoulder_fall;
  hull_of_columns(out, params, shoulder_fall_px);
  if (!(params.past_occluder_run > 0)) return;
  // Turf past an occluder: a column whose scan ended at a robot standing on the field, with the
  // field's turf above it, takes the top of that turf when it is at least `past_occluder_run`
  // of the gap long (a robot's greenish panel is shorter) and lies no higher than the boundary's
  // highest point by more than `past_occluder_rise` of the gap. The next field beyond a floor
  // strip, a green poster over a wall, lie higher than that (their gap alone is longer).
  const double past_run = params.past_occluder_run * gap;
  const int limit = static_cast<int>(std::floor(out.highest() - params.past_occluder_rise * gap));
  // The scans go a gap above `limit`: turf still going on there has no top below `limit`.
  const int ceiling = std::max(0, limit - gap);
  bool raised = false;
  for (std::size_t i = 0; i < out.columns.size(); ++i) {
    const int x = static_cast<int>(out.columns[i].x);
    // Each scan's top lies above its start (rows count down) and must not lie above `limit`.
    for (int from = out.scan_ends[i]; from > limit;) {
      const Scan past = scan_column(x, from, ceiling);
      if (past.top < std::max(limit, 0)) break;  // no field, or it reaches above `limit`
      if (past.first - past.top >= past_run) {
        out.columns[i].y = float(past.top);
        raised = true;
        break;
      }
      from = past.stop;  // a few greenish samples on the occluder itself: look on above
    }
  }
  if (raised) hull_of_columns(out, params, shoulder_fall_px);
}

}  // namespace fieldlines
