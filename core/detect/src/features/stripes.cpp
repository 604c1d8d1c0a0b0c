#include "fieldlines/detect/stripes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <utility>

#include "edge_lines.hpp"
#include "field_pixel.hpp"
#include "paint_profile.hpp"

namespace fieldlines {
namespace {

using Candidate = StripeWorkspace::Candidate;
using namespace paint;

// Between paint and turf only blur (paint::kMaxBlurPx), none darker than this share of the turf
// on its side (of the field colour where that turf is brighter): a lens's colour fringe along a
// wide line (blue or yellow, 0.75 to 0.85 of the turf) is blur; a robot's dark body (0.3 to 0.5)
// is not. Held-out MSL venues, calibrated: recall 0.730
// -> 0.757 (De Locht), 0.578 -> 0.610 (Bangkok), 0.729 -> 0.739 (Bordeaux) against 0.85, no
// precision lost; Humanoid and SSL unchanged. Against the turf's own brightness instead of the
// field colour's alone (a vignetted corner): Bangkok 0.981 / 0.643 -> 0.983 / 0.676, Humanoid's
// precision 0.941 -> 0.935 (one goal's ground bar, shaded turf inside the goal beside it).
constexpr float kBlurShade = 0.7f;
constexpr float kShadedTurf = 0.8f;      // paint's contrast is against turf down to this share of the field colour
constexpr float kTwinCos = 0.9962f;      // cos(5 degrees): twins are this parallel...
constexpr float kTwinWidthShare = 0.35f; // ...their distance within this share of the width...
constexpr float kTwinMinSlackPx = 2;     // ...or this many pixels, whichever is more
// ThinLines::Level takes thin paint on segments at least this long and this level (sin 30
// degrees). Held-out venues, calibrated: Humanoid recall 0.755 -> 0.838, the MSL venues +0.007
// to +0.012, no precision lost; 25 px costs Humanoid 0.034 of precision, any angle De Locht 0.017.
constexpr float kLevelMinLengthPx = 40, kLevelMaxSin = 0.5f;
constexpr float kThinMaxWidthPx = 4;  // the widest paint that stays in the field colour
constexpr float kRimShare = 0.1f;     // the frame's rim reaches its border within this share of the height
// A marking segment is moved onto its paint's measured edge when that lies at least this far
// off (beyond a sharp edge's ridge) and every profile's edge within kMaxEdgeSpreadPx of the
// line through them (stripes.hpp).
constexpr float kMinEdgeShiftPx = 2, kMaxEdgeSpreadPx = 1;
// A segment whose paint's measured edge lies more than half the fade the check allows off it,
// and that cannot be moved there, is no edge of that paint: a ghost step inside a motion-blurred
// line, a chord of a bent one. Held-out SSL P / R 0.939 / 0.776 -> 0.963 / 0.776 (3 of its 5
// wrong markings; 0.962 / 0.769 at 3.5-5 px inclusive, no effect from 7 px); the other venues
// unchanged.
constexpr float kMaxOffEdgePx = 0.5f * kMaxBlurPx;

// With the frame's turf colours (DetectorParams::stripe_turf_colours), turf darker than this
// share of the field colour is none: the robot's own body panels and plates at a fisheye frame's
// bottom mirror the turf's chromaticity at a third of its brightness. Held-out Bangkok precision
// 0.950 -> 0.966 with the turf colours on; 0.5 costs Bordeaux 0.014 of recall. The field colour
// alone keeps the field boundary's floor (a floor there turns a robot's plate into the frame's
// rim: Bangkok 0.983 -> 0.966).
constexpr float kTurfColoursMinBrightness = 0.4f;

FieldPixel stripe_pixel(const FieldColours& field) {
  FieldBoundaryParams p;
  if (field.turf && !field.turf->empty()) p.brightness.min = kTurfColoursMinBrightness;
  return FieldPixel(*field.median, p, field.turf);
}

// How far a width may stray from a stripe's `width` and still be its own: twins' distance, a
// profile's width for the bow.
float width_slack(float width) { return std::max(kTwinMinSlackPx, kTwinWidthShare * width); }

// A profile that leaves the image through its bottom or sides while still in paint is cut: it
// says nothing either way (a line near the camera, running out of the frame). One leaving
// through the top says no: above the field are walls, not paint.
enum class Verdict { Stripe, No, Cut };
struct Profile {
  Verdict verdict = Verdict::No;
  float width = 0, offset = 0;
  bool thin = false;  // a stripe only as paint too thin to leave the field colour (ThinLines)
};

// Whether two pixels show the same turf: chromaticity within the field pixel rule's tolerance,
// brightness within a fifth.
bool same_turf(const std::uint8_t* a, const std::uint8_t* b) {
  const float sa = std::max(brightness(a), 1.f), sb = std::max(brightness(b), 1.f);
  if (sb < 0.8f * sa || sb > 1.2f * sa) return false;
  return std::abs(a[2] / sa - b[2] / sb) + std::abs(a[1] / sa - b[1] / sb) <= FieldBoundaryParams{}.chroma_tolerance;
}

// One profile from (px, py) along the unit vector (sx, sy) towards the paint. Step i reads the
// pixel nearest to (px, py) + (i - back) (sx, sy), back = kOuterPx + kMaxBlurPx; the profile
// ends at the image border.
Profile measure_profile(const cv::Mat& bgr, const FieldPixel& pixel, float px, float py, float sx, float sy,
                        float max_width, bool take_thin, StripeWorkspace& work) {
  constexpr int back = kOuterPx + kMaxBlurPx;
  const int steps = back + static_cast<int>(std::ceil(max_width)) + kMaxBlurPx + 2;
  work.brightness.resize(static_cast<std::size_t>(steps));
  work.is_field.resize(static_cast<std::size_t>(steps));
  work.pixels.resize(static_cast<std::size_t>(steps));
  // Steps are read as the walk below reaches them: most profiles find the far turf a few pixels
  // past the paint, long before the widest plausible width.
  int read = 0;        // steps read so far, each inside the image
  bool ended = false;  // the profile ends after `read` steps (the border, or all steps)
  bool cut = false;    // it ended at the image's bottom or side border while past the edge
  const auto inside = [&](int i) {  // reads up to step i; whether step i lies in the image
    for (; read <= i && !ended; ++read) {
      if (read == steps) {
        ended = true;
        break;
      }
      const float t = float(read - back);
      const long x = std::lround(px + t * sx), y = std::lround(py + t * sy);
      if (x < 0 || y < 0 || x >= bgr.cols || y >= bgr.rows) {
        cut = y >= 0 && read > back;
        ended = true;
        break;
      }
      const std::uint8_t* p = bgr.ptr<std::uint8_t>(static_cast<int>(y)) + 3 * x;
      work.brightness[static_cast<std::size_t>(read)] = brightness(p);
      work.is_field[static_cast<std::size_t>(read)] = pixel.field(p);
      work.pixels[static_cast<std::size_t>(read)] = p;
    }
    return i < read;
  };
  const std::vector<float>& b = work.brightness;
  const std::vector<std::uint8_t>& turf = work.is_field;
  // The frame's own rim: dark at step i, then no field and mostly dark from there along `dir`
  // (+1 into the paint side, -1 out past the edge) to the frame's bottom or side border, close
  // by. A line near the camera runs along the lens's dark corner or the robot's own body at the
  // frame's bottom, which takes the turf's place on that side; a robot's dark body beside its
  // white bar has turf beyond it, or stands off the border.
  const auto rim_from = [&](int i, int dir) {
    const float dark = kBlurShade * pixel.field_sum();
    if (b[static_cast<std::size_t>(i)] >= dark) return false;
    const float reach = kRimShare * float(bgr.rows);
    int seen = 0, dark_seen = 0;
    for (float t = 0; t <= reach; t += 1.f) {
      const float at = float(i - back) + float(dir) * t;
      const long x = std::lround(px + at * sx), y = std::lround(py + at * sy);
      if (y < 0) return false;  // out through the top: walls, not the frame's rim
      if (x < 0 || x >= bgr.cols || y >= bgr.rows) return 4 * dark_seen >= 3 * seen;  // mostly dark
      const std::uint8_t* p = bgr.ptr<std::uint8_t>(static_cast<int>(y)) + 3 * x;
      if (pixel.field(p)) return false;
      ++seen, dark_seen += brightness(p) < dark;
    }
    return false;
  };
  // Turf outside the edge, in the frame's field colour, or the frame's rim just past the edge's
  // blur (a near line's edge along the robot's own body: the line's other edge has the rim on
  // its far side, below).
  inside(back);
  int outside = std::min(back, read - 1);
  while (outside >= 0 && !turf[outside]) --outside;
  const bool rim_outside = outside < 0 && read > back - kOuterPx && rim_from(back - kOuterPx, -1);
  if (rim_outside) outside = back - kOuterPx;
  if (outside < 0) return {};
  // Turf returns on the paint side: the first pixel past the edge in the field colour or in the
  // colour of the turf outside (far turf in haze or in another light misses the frame's
  // colour), and darker than half-way to the paint (blurred paint can pass the colour test).
  // Without it the bright side is a wall, a board or a post, not paint. The paint's peak lies
  // between the edge (give or take its blur) and that turf, or the frame's rim.
  const std::uint8_t* const outside_pixel = work.pixels[static_cast<std::size_t>(outside)];
  int far_turf = back, peak = std::max(back - kOuterPx, outside + 1);
  float level = 0;
  bool rim = false;  // far_turf is the frame's rim, not turf
  float beyond = 0;  // the turf's brightness past the paint: the turf outside's against the rim
  float near_side = 0;  // ...and outside the edge: the turf past the paint's against the rim
  // With the rim outside, only turf in the field colour returns (there is no turf outside to
  // match), and the rim again is no line on turf.
  const auto turf_returns = [&](int i) {
    if (turf[i]) return true;
    if (rim_outside) return false;
    return same_turf(outside_pixel, work.pixels[i]) || (rim = rim_from(i, 1));
  };
  for (;;) {
    do ++far_turf;
    while (inside(far_turf) && !turf_returns(far_turf));
    if (!inside(far_turf)) return {cut ? Verdict::Cut : Verdict::No};
    for (int i = peak + 1; i <= far_turf; ++i)
      if (b[i] > b[peak]) peak = i;
    if (peak == far_turf) continue;  // brighter than all before it: faint paint, not turf
    // Half-way between the paint and the turf on either side, so blur widens nothing; against
    // the rim, the turf on the other side alone.
    beyond = rim ? b[outside] : b[far_turf];
    near_side = rim_outside ? beyond : b[outside];
    level = 0.5f * (b[peak] + 0.5f * (near_side + beyond));
    if (b[far_turf] < level) break;
  }
  // Brighter than the turf beside it, or than the field colour where that is darker: turf in a
  // wall's shade is darker than the frame's field colour, and a thin far line on it less bright
  // than that (SSL: 4 of the 129 markings of the authors' 41 frames). Not below kShadedTurf of
  // the field colour: dim frames' turf texture would pass (docs/detector.md).
  const float turf_beside = std::clamp(0.5f * (near_side + beyond), kShadedTurf * pixel.field_sum(), pixel.field_sum());
  if (b[peak] < kPaintContrast * turf_beside) return {};
  // Paint leaves the field colour; a line too thin to fill a pixel may not, and is taken only
  // when asked: its peak is turf with grey blended in, against the turf on both sides.
  if (turf[peak] && (rim || rim_outside || !(take_thin && blended_paint(work.pixels[peak], work.pixels[outside]) &&
                               blended_paint(work.pixels[peak], work.pixels[far_turf]))))
    return {};
  // The paint's near side: turf below the level, or the rim outside.
  int near_turf = peak - 1;
  while (near_turf >= 0 && !(turf[near_turf] && b[near_turf] < level) && !(rim_outside && near_turf == outside))
    --near_turf;
  if (near_turf < 0) return {};
  int lo = peak, hi = peak;
  while (b[lo - 1] >= level) --lo;  // stops after near_turf, stays below it
  while (b[hi + 1] >= level) ++hi;  // stops before far_turf, stays above it
  // Between paint and turf only blur: a short fade, never darker than turf. A robot's black
  // body beside its white bar, or a dark gap before the turf, says the bright part is no paint.
  // Darker than the turf on that side, or than the field colour where that turf is brighter: a
  // fisheye's vignette darkens the turf past a near line and the lens's fringe along it alike.
  const auto fades = [&](int from, int to, float turf_side) {
    if (to - from > kMaxBlurPx) return false;
    const float floor = kBlurShade * std::min(turf_side, pixel.field_sum());
    for (int i = from; i < to; ++i)
      if (b[i] < floor) return false;
    return true;
  };
  // Against the rim outside only the fade's length: the rim is dark by what it is.
  if (rim_outside ? lo - near_turf > kMaxBlurPx : !fades(near_turf + 1, lo, b[near_turf])) return {};
  if (!fades(hi + 1, far_turf, beyond)) return {};
  const float near_edge = crossing(b, lo - 1, level), far_edge = crossing(b, hi, level);
  const float width = far_edge - near_edge;
  if (width < kMinWidthPx || width > max_width) return {};
  // Paint that stays in the field colour is thinner than a pixel: blur spreads it over a few at
  // most. A wider band of brighter turf in that colour is light (a sun stripe), not paint.
  if (turf[peak] && width > kThinMaxWidthPx) return {};
  return {Verdict::Stripe, width, 0.5f * (near_edge + far_edge) - float(back), static_cast<bool>(turf[peak])};
}

// The centre offsets at the segment's ends (f = 0 and 1) of the line through (f[i], offset[i]):
// the median of the pairwise slopes and the median intercept (Theil-Sen), so one profile that
// crossed a robot's foot or a neighbouring line does not tilt it.
std::pair<float, float> offset_line(const std::array<float, 32>& f, const std::array<float, 32>& offset, int n,
                                    std::array<float, 32>& scratch) {
  std::array<float, 32 * 31 / 2> slopes;  // NOLINT: filled below, n <= 32
  int m = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const float df = f[static_cast<std::size_t>(j)] - f[static_cast<std::size_t>(i)];
      if (df > 0) slopes[static_cast<std::size_t>(m++)] = (offset[static_cast<std::size_t>(j)] - offset[static_cast<std::size_t>(i)]) / df;
    }
  float slope = 0;
  if (m > 0) {
    std::nth_element(slopes.begin(), slopes.begin() + m / 2, slopes.begin() + m);
    slope = slopes[static_cast<std::size_t>(m / 2)];
  }
  for (int i = 0; i < n; ++i)
    scratch[static_cast<std::size_t>(i)] = offset[static_cast<std::size_t>(i)] - slope * f[static_cast<std::size_t>(i)];
  const float at0 = median(scratch, n);
  return {at0, at0 + slope};
}

// How far the centres of the profiles a quarter to three quarters along (at f) lie off the line
// from offset0 to offset1, less how far the outer ones do, on average: a chord of a curve bows
// (its middle on one side of the paint's centre, its ends on the other); 0 without both kinds.
// A profile whose width is off the median by more than a twin's slack crossed other paint (a
// short line between two others, near a corner) and is left out: its centre is no centre.
float bow(const std::array<float, 32>& f, const std::array<float, 32>& offset, const std::array<float, 32>& width, int n,
          float offset0, float offset1, float median_width) {
  float middle = 0, outer = 0;
  int n_middle = 0, n_outer = 0;
  const float slack = width_slack(median_width);
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
    if (std::abs(width[i] - median_width) > slack) continue;  // it crossed other paint: no say
    const float off = offset[i] - (offset0 + f[i] * (offset1 - offset0));
    const bool in_middle = f[i] > 0.25f && f[i] < 0.75f;
    (in_middle ? middle : outer) += off;
    ++(in_middle ? n_middle : n_outer);
  }
  return n_middle > 0 && n_outer > 0 ? middle / static_cast<float>(n_middle) - outer / static_cast<float>(n_outer) : 0.f;
}

// Whether a candidate is straight enough for Shape::Straight (stripes.hpp). Tuning seeds, the
// junctions from the detector's own segments: precision 0.897 -> 0.975 at recall 0.772 -> 0.734
// (1 px alone: 0.975 / 0.728; 0.75 px: 0.983 / 0.722; 1.5 px: 0.935 / 0.734).
bool straight(const Candidate& c) {
  constexpr float kMaxBowPx = 1, kMaxBowWidths = 0.2f;
  return std::abs(c.bow) <= std::max(kMaxBowPx, kMaxBowWidths * c.width);
}

// Whether the segment may move onto its paint's measured edge: off it beyond a sharp edge's
// ridge, the profiles agreeing on a line, the move within the fade the check allows.
bool movable(const Candidate& c) {
  const float limit = kMaxBlurPx;
  return std::abs(c.edge_median) >= kMinEdgeShiftPx && c.edge_spread <= kMaxEdgeSpreadPx &&
         std::abs(c.edge0) <= limit && std::abs(c.edge1) <= limit;
}

// Whether a candidate lies too far off its paint's edge to be that edge (kMaxOffEdgePx).
bool off_its_edge(const Candidate& c) { return std::abs(c.edge_median) > kMaxOffEdgePx && !movable(c); }

// Whether ThinLines::Level takes thin paint on a segment `len` px long, `uy` its unit direction's
// y: long and nearly level.
bool level(float len, float uy) { return len >= kLevelMinLengthPx && std::abs(uy) <= kLevelMaxSin; }

// The candidate's paint side, profiles and medians under `thin`; false when it is no stripe
// (off_its_edge included).
// `as_level`, when given (with ThinLines::Accepted), gets the candidate as ThinLines::Level
// would measure it from the same profiles (those taken only as thin paint left out unless the
// segment is level), and `*level_stripe` whether it is a stripe then.
bool measure_candidate(const cv::Mat& bgr, const FieldPixel& pixel, const Segment& s, const DetectorParams& params,
                       ThinLines thin, StripeWorkspace& work, Candidate& c, Candidate* as_level = nullptr,
                       bool* level_stripe = nullptr) {
  const float dx = s.x1 - s.x0, dy = s.y1 - s.y0, len = std::hypot(dx, dy);
  if (!(len > 0.f)) return false;
  c.ux = dx / len, c.uy = dy / len;
  const bool thin_when_level = level(len, c.uy);
  // The paint is on the side the colour gradient points to (brighter along it).
  const auto [nx, ny] = bright_side(bgr, s, c.ux, c.uy);
  c.sx = nx, c.sy = ny;
  const int samples = std::clamp(params.stripe_samples, 1, 32);
  // Index 0: the profiles `thin` takes; 1: those ThinLines::Level takes.
  std::array<std::array<float, 32>, 2> widths{}, offsets{}, at{};
  std::array<int, 2> stripes{};
  int decided = 0;
  for (int k = 0; k < samples; ++k) {
    const float f = (float(k) + 0.5f) / float(samples);
    const float px = s.x0 + f * dx, py = s.y0 + f * dy;
    const float max_width = static_cast<float>(params.stripe_max_width) * width_scale(py, bgr.rows);
    const Profile p =
        measure_profile(bgr, pixel, px, py, nx, ny, max_width, thin == ThinLines::Accepted || thin_when_level, work);
    decided += p.verdict != Verdict::Cut;  // a thin profile that Level would not take is a No: decided
    if (p.verdict != Verdict::Stripe) continue;
    // Set 1 only when asked for: the detector's own pass keeps one set.
    for (std::size_t m = 0; m < (as_level && (!p.thin || thin_when_level) ? 2u : 1u); ++m) {
      const auto i = static_cast<std::size_t>(stripes[m]++);
      widths[m][i] = p.width, offsets[m][i] = p.offset, at[m][i] = f;
    }
  }
  // The medians and the centre line of one set of profiles; false when they make no stripe.
  const auto finish = [&](std::size_t m, Candidate& out) {
    const int n = stripes[m];
    if (2 * n < decided || n == 0) return false;
    std::array<float, 32> sorted = widths[m];
    out.width = median(sorted, n);
    std::tie(out.offset0, out.offset1) = offset_line(at[m], offsets[m], n, sorted);  // sorted: scratch now
    out.bow = bow(at[m], offsets[m], widths[m], n, out.offset0, out.offset1, out.width);
    std::array<float, 32> edges;
    const auto count = static_cast<std::size_t>(n);
    for (std::size_t i = 0; i < count; ++i) edges[i] = offsets[m][i] - 0.5f * widths[m][i];
    std::tie(out.edge0, out.edge1) = offset_line(at[m], edges, n, sorted);
    out.edge_spread = 0;
    for (std::size_t i = 0; i < count; ++i)
      out.edge_spread = std::max(out.edge_spread, std::abs(edges[i] - (out.edge0 + at[m][i] * (out.edge1 - out.edge0))));
    out.edge_median = median(edges, n);
    return !off_its_edge(out);
  };
  if (as_level) {
    *as_level = c;
    *level_stripe = finish(1, *as_level);
  }
  return finish(0, c);
}

Marking centre_of(const Segment& s, const Candidate& c) {
  return {s.x0 + c.offset0 * c.sx, s.y0 + c.offset0 * c.sy, s.x1 + c.offset1 * c.sx, s.y1 + c.offset1 * c.sy, c.width};
}

// Whether two candidates' edges are as parallel as twins are.
bool parallel(const Candidate& ca, const Candidate& cb) { return std::abs(ca.ux * cb.ux + ca.uy * cb.uy) >= kTwinCos; }

// b's ends in a's frame: how far along a (t, from a's first end) and off a's line towards a's
// paint (n).
struct Ends {
  float t0, t1, n0, n1;
};
Ends ends_of(const Segment& b, const Segment& a, const Candidate& ca) {
  return {(b.x0 - a.x0) * ca.ux + (b.y0 - a.y0) * ca.uy, (b.x1 - a.x0) * ca.ux + (b.y1 - a.y0) * ca.uy,
          (b.x0 - a.x0) * ca.sx + (b.y0 - a.y0) * ca.sy, (b.x1 - a.x0) * ca.sx + (b.y1 - a.y0) * ca.sy};
}

// How far b's edge lies from a's along a's paint normal, when b is a's twin: parallel, its
// paint facing a's, overlapping along a; negative otherwise.
float twin_distance(const Segment& a, const Candidate& ca, const Segment& b, const Candidate& cb) {
  if (!parallel(ca, cb)) return -1;
  if (ca.sx * cb.sx + ca.sy * cb.sy >= 0) return -1;  // the two paints must face each other
  const float mx = 0.5f * (b.x0 + b.x1) - a.x0, my = 0.5f * (b.y0 + b.y1) - a.y0;
  const float distance = mx * ca.sx + my * ca.sy;
  const float len = std::hypot(a.x1 - a.x0, a.y1 - a.y0);
  const Ends e = ends_of(b, a, ca);
  if (std::max(e.t0, e.t1) <= 0 || std::min(e.t0, e.t1) >= len) return -1;
  return distance > 0 ? distance : -1;
}

// One marking from two twin edges: over the union of their lengths along a, the line half-way
// between a and b's line at each end (twins may converge by their few degrees, as a line's
// width shrinks with distance), and their mean measured width.
Marking merge(const Segment& a, const Candidate& ca, const Segment& b, const Candidate& cb) {
  const float len = std::hypot(a.x1 - a.x0, a.y1 - a.y0);
  const Ends e = ends_of(b, a, ca);
  const float t0 = e.t0, t1 = e.t1, n0 = e.n0, n1 = e.n1;
  const float lo = std::min({0.f, t0, t1}), hi = std::max({len, t0, t1});
  // Half of b's distance from a's line at t along a; beyond b's ends, its distance there (b may
  // be short, and its few degrees carried along all of a would tilt the centre line).
  const auto centre = [&](float t) {
    const float u = t1 != t0 ? std::clamp((t - t0) / (t1 - t0), 0.f, 1.f) : 0.5f;
    const float n = n0 + u * (n1 - n0);
    return cv::Point2f(a.x0 + t * ca.ux + 0.5f * n * ca.sx, a.y0 + t * ca.uy + 0.5f * n * ca.sy);
  };
  const cv::Point2f p = centre(lo), q = centre(hi);
  return {p.x, p.y, q.x, q.y, 0.5f * (ca.width + cb.width)};
}

// The segment moved onto its paint's measured edge when it lies on a blur ramp (stripes.hpp).
void snap_to_edge(Segment& s, Candidate& c) {
  if (!movable(c)) return;
  s.x0 += c.edge0 * c.sx, s.y0 += c.edge0 * c.sy;
  s.x1 += c.edge1 * c.sx, s.y1 += c.edge1 * c.sy;
  c.moved = true;
}

// Whether `b` lies along `a` on the same side of the same paint: parallel as twins are, its
// paint on a's side, both ends within a line's blur of a's line and over half of it beside a.
bool along_same_edge(const Segment& a, const Candidate& ca, const Segment& b, const Candidate& cb) {
  constexpr float kNearPx = 2;
  if (!parallel(ca, cb) || ca.sx * cb.sx + ca.sy * cb.sy <= 0) return false;
  const float len_a = std::hypot(a.x1 - a.x0, a.y1 - a.y0), len_b = std::hypot(b.x1 - b.x0, b.y1 - b.y0);
  const Ends e = ends_of(b, a, ca);
  if (std::abs(e.n0) > kNearPx || std::abs(e.n1) > kNearPx) return false;
  return std::min(len_a, std::max(e.t0, e.t1)) - std::max(0.f, std::min(e.t0, e.t1)) > 0.5f * std::min(len_a, len_b);
}

// Two marking segments that a move put on one painted edge (a ghost's two drawn steps) are one:
// the longer, along its own line, spans both, and the shorter becomes none.
void merge_doubles(std::span<Segment> segments, const std::vector<Candidate>& cs) {
  const auto length = [](const Segment& s) { return std::hypot(s.x1 - s.x0, s.y1 - s.y0); };
  for (std::size_t i = 0; i < cs.size(); ++i) {
    if (!cs[i].moved) continue;
    for (std::size_t j = 0; j < cs.size() && segments[cs[i].segment].label == Label::Marking; ++j) {
      if (j == i || segments[cs[j].segment].label != Label::Marking ||
          !along_same_edge(segments[cs[i].segment], cs[i], segments[cs[j].segment], cs[j]))
        continue;
      const bool i_longer = length(segments[cs[i].segment]) >= length(segments[cs[j].segment]);
      Segment& keep = segments[(i_longer ? cs[i] : cs[j]).segment];
      Segment& drop = segments[(i_longer ? cs[j] : cs[i]).segment];
      const float dx = keep.x1 - keep.x0, dy = keep.y1 - keep.y0, len = std::hypot(dx, dy);
      if (!(len > 0.f)) continue;
      const float ux = dx / len, uy = dy / len;
      const auto along = [&](float x, float y) { return (x - keep.x0) * ux + (y - keep.y0) * uy; };
      const float t0 = std::min({0.f, along(drop.x0, drop.y0), along(drop.x1, drop.y1)});
      const float t1 = std::max({len, along(drop.x0, drop.y0), along(drop.x1, drop.y1)});
      const float x0 = keep.x0, y0 = keep.y0;
      keep.x0 = x0 + t0 * ux, keep.y0 = y0 + t0 * uy, keep.x1 = x0 + t1 * ux, keep.y1 = y0 + t1 * uy;
      drop.label = Label::None;
    }
  }
}

// Whether `s` lies where the other edge of one of `cs`' stripes may: as parallel as twins, beside
// it along its length, its middle on that one's paint side no farther off than the widest paint
// of its row and the twins' slack (a superset of what pair_stripes pairs).
bool near_a_stripe(const Segment& s, std::span<const Segment> segments, std::span<const Candidate> cs,
                   const DetectorParams& params, int rows) {
  const float dx = s.x1 - s.x0, dy = s.y1 - s.y0, len = std::hypot(dx, dy);
  if (!(len > 0.f)) return false;
  const float mx = 0.5f * (s.x0 + s.x1), my = 0.5f * (s.y0 + s.y1);
  const float widest = static_cast<float>(params.stripe_max_width) * width_scale(my, rows);
  const float reach = widest + width_slack(widest);
  return std::any_of(cs.begin(), cs.end(), [&](const Candidate& c) {
    const Segment& a = segments[c.segment];
    if (std::abs(dx * c.ux + dy * c.uy) < kTwinCos * len) return false;
    const float d = (mx - a.x0) * c.sx + (my - a.y0) * c.sy;
    if (!(d > 0.f) || d > reach) return false;
    const Ends e = ends_of(s, a, c);
    return std::max(e.t0, e.t1) > 0 && std::min(e.t0, e.t1) < std::hypot(a.x1 - a.x0, a.y1 - a.y0);
  });
}

// The stripes among `cs` (measured candidates of `segments`) paired with their twins into `out`
// (cleared first); relabels the segments, moves those on a blur ramp (snap_to_edge) and merges
// the doubles that makes.
void pair_stripes(std::span<Segment> segments, std::vector<Candidate>& cs, const DetectorParams& params,
                  std::vector<Marking>& out) {
  out.clear();
  // Every marking that is not a stripe, and every stripe left without its twin when twins are
  // required, becomes none below; the rest are set back to Marking.
  for (Segment& s : segments)
    if (s.label == Label::Marking) s.label = Label::None;
  for (std::size_t i = 0; i < cs.size(); ++i) {
    if (cs[i].paired || cs[i].twin_only) continue;
    const Segment& a = segments[cs[i].segment];
    std::size_t best = cs.size();
    float best_error = 0;
    for (std::size_t j = i + 1; j < cs.size(); ++j) {
      if (cs[j].paired) continue;
      const float d = twin_distance(a, cs[i], segments[cs[j].segment], cs[j]);
      if (d < 0) continue;
      const float width = 0.5f * (cs[i].width + cs[j].width);
      const float error = std::abs(d - width);
      if (error > width_slack(width)) continue;
      if (best == cs.size() || error < best_error) best = j, best_error = error;
    }
    if (best < cs.size()) {
      cs[i].paired = cs[best].paired = true;
      out.push_back(merge(a, cs[i], segments[cs[best].segment], cs[best]));
      segments[cs[best].segment].label = Label::Marking;
      snap_to_edge(segments[cs[best].segment], cs[best]);
    } else if (params.stripe_require_twin) {
      continue;
    } else {
      out.push_back(centre_of(a, cs[i]));
    }
    segments[cs[i].segment].label = Label::Marking;
    snap_to_edge(segments[cs[i].segment], cs[i]);
  }
  merge_doubles(segments, cs);
}

}  // namespace

void find_stripes(const cv::Mat& bgr8, const FieldColours& field, std::span<Segment> segments,
                  const DetectorParams& params, StripeWorkspace& work, std::vector<Marking>& out, ThinLines thin,
                  Shape shape, const FieldBoundary* on_field) {
  work.candidates.clear();
  if (!bgr8.empty() && bgr8.type() == CV_8UC3 && field) {
    const FieldPixel pixel = stripe_pixel(field);
    // Segment i a candidate when its profiles measure a stripe (of the shape asked for) whose
    // paint lies on the field.
    const auto add_measured = [&](std::size_t i, bool twin_only) {
      Candidate c;
      c.segment = i;
      c.twin_only = twin_only;
      if (!measure_candidate(bgr8, pixel, segments[i], params, thin, work, c) || (shape == Shape::Straight && !straight(c)))
        return;
      if (on_field) {
        const Marking centre = centre_of(segments[i], c);
        if (lies_above(0.5f * (centre.x0 + centre.x1), 0.5f * (centre.y0 + centre.y1), *on_field)) return;
      }
      work.candidates.push_back(c);
    };
    for (std::size_t i = 0; i < segments.size(); ++i)
      if (segments[i].label == Label::Marking) add_measured(i, false);
    // Lines along the field's edge: segments the colours left as none (edge_lines.hpp); the
    // candidates become markings in pair_stripes.
    if (on_field && !on_field->empty())
      for (std::size_t i = 0; i < segments.size(); ++i) {
        if (segments[i].label != Label::None || place_of(segments[i], *on_field) != BoundaryPlace::Along) continue;
        Candidate c;
        c.segment = i;
        if (edge_line(bgr8, pixel, segments[i], params, c)) work.candidates.push_back(c);
      }
    // The other edge of a stripe the colours marked, which they left as none (its colour angle
    // off: a line's edge against the turf's other side, in another light): a candidate too, which
    // becomes a marking only as a marking's twin (pair_stripes). Its profiles are measured only
    // when it lies where such a twin may (near_a_stripe): most none segments of a textured field
    // lie nowhere near one.
    const std::size_t found = work.candidates.size();  // the pushes below may move them: spans per use
    const auto stripes = [&] { return std::span<const Candidate>(work.candidates.data(), found); };
    for (std::size_t i = 0; i < segments.size(); ++i) {
      if (segments[i].label != Label::None || !near_a_stripe(segments[i], segments, stripes(), params, bgr8.rows) ||
          std::ranges::any_of(stripes(), [i](const Candidate& c) { return c.segment == i; }))
        continue;
      add_measured(i, true);
    }
  }
  pair_stripes(segments, work.candidates, params, out);
}

float width_share(float width, float y, int rows) { return rows > 0 ? width / width_scale(y, rows) : 0.f; }

bool StripeCheck::run(const cv::Mat& bgr8, const FieldColours& field, std::span<const Segment> segments,
                      const DetectorParams& params, ThinLines thin) {
  flags_.clear();
  width_shares_.clear();
  if (!field || bgr8.type() != CV_8UC3) return false;
  checked_.assign(segments.begin(), segments.end());
  for (Segment& s : checked_) s.label = Label::Marking;
  find_stripes(bgr8, field, checked_, params, work_, stripes_, thin);
  for (const Segment& s : checked_) flags_.push_back(s.label == Label::Marking);
  width_shares_.assign(segments.size(), 0.f);
  for (const Candidate& c : work_.candidates) {
    if (!flags_[c.segment]) continue;
    const Marking centre = centre_of(segments[c.segment], c);  // the segment as given: a move shifts the offsets
    width_shares_[c.segment] = width_share(c.width, 0.5f * (centre.y0 + centre.y1), bgr8.rows);
  }
  return true;
}

bool StripeCheck::run_with_thin_lines(const cv::Mat& bgr8, const FieldColours& field,
                                      std::span<const Segment> segments, const DetectorParams& params) {
  flags_.clear();
  thin_flags_.clear();
  width_shares_.clear();  // run()'s alone
  if (!field || bgr8.type() != CV_8UC3) return false;
  // One set of profiles per segment, measured as ThinLines::Accepted; the candidates Level
  // would measure from them beside.
  work_.candidates.clear();
  level_.clear();
  const FieldPixel pixel = stripe_pixel(field);
  for (std::size_t i = 0; i < segments.size(); ++i) {
    Candidate c, l;
    c.segment = i;
    bool level_stripe = false;
    if (measure_candidate(bgr8, pixel, segments[i], params, ThinLines::Accepted, work_, c, &l, &level_stripe))
      work_.candidates.push_back(c);
    if (level_stripe) level_.push_back(l);
  }
  const auto flags_of = [&](std::vector<Candidate>& cs, std::vector<std::uint8_t>& flags) {
    checked_.assign(segments.begin(), segments.end());  // afresh: each pass moves some
    for (Segment& s : checked_) s.label = Label::Marking;
    pair_stripes(checked_, cs, params, stripes_);
    for (const Segment& s : checked_) flags.push_back(s.label == Label::Marking);
  };
  flags_of(level_, flags_);
  flags_of(work_.candidates, thin_flags_);
  return true;
}

}  // namespace fieldlines
