#include "fieldlines/detect/detector.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string>

#include <opencv2/imgproc.hpp>

#include "along_boundary.hpp"
#include "box_downsample.hpp"
#include "elsed/elsed.hpp"
#include "features/field_pixel.hpp"
#include "features/paint_profile.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/centre_circle.hpp"
#include "fieldlines/detect/intersections.hpp"
#include "fieldlines/detect/stripes.hpp"

namespace fieldlines {

// Hidden like the engine it holds (see elsed/line_model.hpp).
struct [[gnu::visibility("hidden")]] LineDetector::Impl {
  ElsedEngine engine;
  ElsedEngine coarse_engine;    // the coarse pass (DetectorParams::coarse_scale)
  DetectorParams coarse_params;  // the parameters scaled to it, set with the parameters
  cv::Mat coarse_bgr;           // the band it reads, downsampled
  bool coarse_avx2 = elsed::avx2::wanted();  // box_downsample's kernel, chosen when built
  std::vector<Segment> coarse;  // its segments, in full-scale pixels
  ElsedEngine thin_engine;      // the thin-line pass (DetectorParams::thin_reach)
  std::vector<Segment> thin;    // its segments
  AlongBoundary along;          // its far lines along the field boundary (thin_along_boundary)...
  std::vector<Segment> along_found;  // ...and their segments
  cv::Mat eight, bgr8;  // the input normalised to 8-bit BGR, reused between calls
  std::optional<Rgb> field;  // of the last frame, when measured
  TurfColours turf;          // of the last frame, when the boundary or the stripes took them
  FieldFeatures features;  // its field_boundary is the one the gate and field_boundary() use
  StripeWorkspace stripes;
  IntersectionWorkspace intersections;
  std::vector<Segment> pieces;  // the second drawing (find_pieces)
  std::vector<int> piece_rows;  // per column, the first row it draws from
  ElsedEngine::AnchorCells near_paint;  // where the second drawing's anchors may lie
  StripeWorkspace piece_stripes;
  std::vector<Marking> arcs;    // the pieces that are stripes
  std::vector<Marking> lines;   // those of them not on the circle, and the unpieced lines
  std::vector<Segment> unpieced;  // the detector's own segments no piece lies along
  StripeWorkspace unpieced_stripes;
  std::vector<Marking> unpieced_lines;  // those of them that are stripes
  CircleWorkspace circle;
  GroundFeatures ground;  // `features` through the camera, when one is set
};

namespace {
// The parameters of the coarse pass: the minimum length in its own pixels. The anchors keep
// their spacing in its pixels (coarse_scale times sparser on the frame): the lines it is for are
// long, and a denser grid cost a third of a detect for no measured recall (docs/detector.md).
// Its line fit may stray from the edge at most twice as far as the full scale's, on the frame:
// at a third of the size, the full scale's tolerance in its own pixels let a segment run as a
// chord across a curved line (the centre circle) 4.5 px off its edge (docs/detector.md).
DetectorParams coarse_params_of(const DetectorParams& params) {
  DetectorParams p = params;
  const int f = std::max(params.coarse_scale, 1);
  p.min_line_length = std::max(3, params.min_line_length / f);
  const double tighter = std::min(1.0, 2.0 / f);
  p.px_to_segment_dist = params.px_to_segment_dist * tighter;
  p.line_fit_error = params.line_fit_error * tighter * tighter;  // px^2
  return p;
}

}  // namespace

LineDetector::LineDetector(DetectorParams params, Thresholds thresholds)
    : params_(std::move(params)), thresholds_(thresholds), impl_(std::make_unique<Impl>()) {
  validate(params_);
  impl_->coarse_params = coarse_params_of(params_);
}
LineDetector::~LineDetector() = default;
LineDetector::LineDetector(LineDetector&&) noexcept = default;
LineDetector& LineDetector::operator=(LineDetector&&) noexcept = default;

std::vector<Segment> LineDetector::detect(const cv::Mat& image) {
  std::vector<Segment> out;
  detect(image, out);
  return out;
}

const cv::Mat* LineDetector::normalise(const cv::Mat& image) {
  if (image.empty()) throw Error("empty image");
  const int depth = image.depth();
  if (depth != CV_8U && depth != CV_16U)
    throw Error("unsupported pixel depth (expected 8- or 16-bit unsigned, got OpenCV depth " +
                std::to_string(depth) + ")");
  const int channels = image.channels();
  if (channels != 1 && channels != 3 && channels != 4)
    throw Error("unsupported channel count " + std::to_string(channels) + " (expected 1, 3 or 4)");
  if (image.rows < 3 || image.cols < 3) return nullptr;  // too small for any 3x3 window

  // Normalise to 8-bit BGR into reused Mats. 16-bit is scaled (>> 8); grey is replicated so
  // every channel carries the same gradient; alpha is dropped.
  if (depth == CV_8U && channels == 3) return &image;
  const cv::Mat* eight = &image;
  if (depth == CV_16U) {
    image.convertTo(impl_->eight, CV_8U, 1.0 / 256.0);
    if (channels == 3) return &impl_->eight;
    eight = &impl_->eight;
  }
  cv::cvtColor(*eight, impl_->bgr8, channels == 1 ? cv::COLOR_GRAY2BGR : cv::COLOR_BGRA2BGR);
  return &impl_->bgr8;
}

namespace {
// The frame's light gain, the colour classes, then the field-boundary gate: one rule for the
// detector's segments and for the short pieces of the junctions and the circle.
void label(std::span<Segment> segments, std::optional<float> gain, const Thresholds& thresholds,
           const FieldBoundary& boundary) {
  if (gain) apply_light_gain(segments, *gain);
  classify_all(segments, thresholds);
  if (thresholds.field_boundary_gate)
    for (Segment& s : segments) s.label = gate_by_field_boundary(s, boundary);
}

// What label() needs to call a segment a marking and can tell before its validation: the marking
// class's colour test and the gate. The boundary class, which a marking must fail, also weighs
// the saliency, which only validation gives: a segment this passes may still not be a marking.
struct MarkingColours {
  std::optional<float> gain;
  const Thresholds& thresholds;  // with marking.thresholds.min_length 0: the length never decides
  const FieldBoundary& boundary;

  static bool may_be_marking(const void* context, const Segment& segment) {
    const auto& m = *static_cast<const MarkingColours*>(context);
    Segment s = segment;
    if (m.gain) apply_light_gain({&s, 1}, *m.gain);
    const SegmentFeatures f = compute_features(s, m.thresholds);
    bool marking = false;
    for (int i = 0; i < f.marking_count; ++i)
      marking = marking || passes(f.marking[i], m.thresholds.marking.thresholds.min_length, m.thresholds.marking.thresholds);
    if (!marking) return false;
    return !m.thresholds.field_boundary_gate || m.boundary.empty() || place_of(s, m.boundary) != BoundaryPlace::Above;
  }
};

// Calls `at(k, offset, t)` for each of five points along `s` (k = 0..4, the point (k + 0.5) / 5
// of its length) and each `t` of `fine` that runs parallel to s (within 5 degrees) beside the
// point (between t's ends, or at most `reach` px past them) with the point at most `reach` px
// from t's line: `offset` is the point's signed distance from that line, its sign the same for
// every t on one side of s whichever way t runs. Each t's direction is tested once, and a t whose
// box lies farther from s's than such a point can be, not at all (the detector has hundreds).
template <class At>
void parallel_beside(const Segment& s, std::span<const Segment> fine, float reach, At&& at) {
  constexpr float kParallelCos = 0.9962f;  // cos(5 degrees)
  const float sx = s.x1 - s.x0, sy = s.y1 - s.y0, length = std::hypot(sx, sy);
  // A point beside t lies within sqrt(2) reach of it (past an end, and off its line).
  const float margin = 1.5f * reach;
  const float lo_x = std::min(s.x0, s.x1) - margin, hi_x = std::max(s.x0, s.x1) + margin;
  const float lo_y = std::min(s.y0, s.y1) - margin, hi_y = std::max(s.y0, s.y1) + margin;
  for (const Segment& t : fine) {
    if (std::max(t.x0, t.x1) < lo_x || std::min(t.x0, t.x1) > hi_x || std::max(t.y0, t.y1) < lo_y ||
        std::min(t.y0, t.y1) > hi_y)
      continue;
    const float tx = t.x1 - t.x0, ty = t.y1 - t.y0, tl = std::hypot(tx, ty);
    const float dot = sx * tx + sy * ty;
    if (!(tl > 0) || std::abs(dot) < kParallelCos * length * tl) continue;
    for (int k = 0; k < 5; ++k) {
      const float f = (float(k) + 0.5f) / 5, px = s.x0 + f * sx, py = s.y0 + f * sy;
      const float along = ((px - t.x0) * tx + (py - t.y0) * ty) / tl;
      if (along < -reach || along > tl + reach) continue;
      const float off = ((px - t.x0) * ty - (py - t.y0) * tx) / tl;
      if (std::abs(off) <= reach) at(k, dot < 0 ? -off : off, t);
    }
  }
}

// A segment's unit normal (its direction turned a quarter left), and which side of it a
// segment's colour gradient makes the brighter one.
struct Normal {
  float nx, ny;
  bool brighter(const Segment& t) const {  // t brightens towards the normal
    float along = 0;
    for (int c = 0; c < 3; ++c) along += t.grad_x[c] * nx + t.grad_y[c] * ny;
    return along >= 0;
  }
};
std::optional<Normal> normal_of(const Segment& s) {
  const float sx = s.x1 - s.x0, sy = s.y1 - s.y0, length = std::hypot(sx, sy);
  if (!(length > 0)) return std::nullopt;
  return Normal{-sy / length, sx / length};
}

// Whether some of `fine` lies along `s` (a coarse segment): at least three of five points along
// s lie within `reach` px of a fine segment parallel to it (within 5 degrees), between that
// one's ends, with its colour gradient on the same side. One painted edge, one segment: the
// full scale's is the more exact, the coarse one fills only where it has none.
bool covered(const Segment& s, std::span<const Segment> fine, float reach) {
  const std::optional<Normal> n = normal_of(s);
  if (!n) return true;
  const bool own = n->brighter(s);
  std::array<bool, 5> near{};
  parallel_beside(s, fine, reach, [&](int k, float, const Segment& t) { near[k] = near[k] || n->brighter(t) == own; });
  return std::count(near.begin(), near.end(), true) >= 3;
}

// Whether among `coarse` (full-scale pixels, drawn at `scale`) lies the other edge of the line `s`
// is one edge of: at three of five points along s, a parallel segment (within 5 degrees, beside
// it) whose colour gradient faces s's, at least two coarse pixels off and no farther than the
// stripes' widest paint at its row (stripes.hpp) and a coarse pixel.
bool has_twin(const Segment& s, std::span<const Segment> coarse, float scale, const DetectorParams& params, int rows) {
  const std::optional<Normal> n = normal_of(s);
  if (!n) return false;
  const bool own = n->brighter(s);
  const float widest = static_cast<float>(params.stripe_max_width) * paint::width_scale(0.5f * (s.y0 + s.y1), rows);
  const float nearest = 2 * scale, reach = std::max(widest, nearest) + scale;
  std::array<bool, 5> twin{};
  parallel_beside(s, coarse, reach, [&](int k, float off, const Segment& t) {
    // The paint lies between the two: on s's bright side, which is t's bright side too.
    if (&t != &s && std::abs(off) >= nearest && n->brighter(t) != own && (off > 0) == own) twin[k] = true;
  });
  return std::count(twin.begin(), twin.end(), true) >= 3;
}

// The first row the thin-line pass draws when the field boundary gates the markings: a band
// (along_band_px) above the boundary's highest point; 0 with no boundary.
int thin_band_start(const FieldBoundary& boundary, int rows) {
  if (boundary.empty()) return 0;
  return std::max(0, static_cast<int>(boundary.highest() - along_band_px(rows)));
}

// The rows [0, end) of a frame `rows` high that the thin-line pass draws (thin_to of them).
int thin_band_end(const DetectorParams& params, int rows) {
  return std::clamp(static_cast<int>(std::lround(params.thin_to * rows)), 0, rows);
}

// Whether `fine` holds both edges of the thin line `s` runs along the centre of: at three of five
// points along s, parallel segments (within 5 degrees, between their ends) lie within `reach` px
// on both sides of it, or one within a pixel of it.
bool edges_held(const Segment& s, std::span<const Segment> fine, float reach) {
  if (!normal_of(s)) return true;
  std::array<bool, 5> left{}, right{};
  parallel_beside(s, fine, reach, [&](int k, float off, const Segment&) {
    if (std::abs(off) <= 1) left[k] = right[k] = true;
    (off < 0 ? left : right)[k] = true;
  });
  int held = 0;
  for (int k = 0; k < 5; ++k) held += left[k] && right[k];
  return held >= 3;
}

// Into `out`, each of `segments` along which no piece lies: none parallel to it (within 5
// degrees) with its middle on it (within 2 px of its line, between its ends).
void collect_unpieced(std::span<const Segment> segments, std::span<const Segment> pieces, std::vector<Segment>& out) {
  constexpr float kParallelCos = 0.9962f;  // cos(5 degrees)
  constexpr float kOnLinePx = 2;
  out.clear();
  for (const Segment& s : segments) {
    const float sx = s.x1 - s.x0, sy = s.y1 - s.y0, length = std::hypot(sx, sy);
    if (!(length > 0)) continue;
    const bool pieced = std::any_of(pieces.begin(), pieces.end(), [&](const Segment& p) {
      const float px = p.x1 - p.x0, py = p.y1 - p.y0;
      if (std::abs(sx * px + sy * py) < kParallelCos * length * std::hypot(px, py)) return false;
      const float mx = 0.5f * (p.x0 + p.x1) - s.x0, my = 0.5f * (p.y0 + p.y1) - s.y0;
      const float along = (mx * sx + my * sy) / length;
      return along >= 0 && along <= length && std::abs(mx * sy - my * sx) / length <= kOnLinePx;
    });
    if (!pieced) out.push_back(s);
  }
}
}  // namespace

void LineDetector::detect(const cv::Mat& image, std::vector<Segment>& out) {
  out.clear();
  impl_->field.reset();
  impl_->features.clear();
  impl_->ground.clear();
  const cv::Mat* bgr = normalise(image);
  if (!bgr) return;
  const bool pieces = params_.intersections || params_.centre_circle;
  // The pieces of junctions and the circle are drawn below the boundary; they are stripes.
  const bool boundary = find_boundary_ || thresholds_.field_boundary_gate || pieces;
  const bool stripes = params_.stripes || pieces;
  if (thresholds_.light.enabled || boundary || stripes || params_.dark_field > 0)
    impl_->field = estimate_field_colour(*bgr);
  // The field boundary always takes the frame's turf colours; the stripes when asked.
  impl_->turf.clear();
  if (impl_->field && (boundary || (stripes && params_.stripe_turf_colours))) impl_->turf.measure(*bgr, *impl_->field);
  const FieldColours colours = stripe_colours();
  const int gradient_threshold =
      adapted_gradient_threshold(params_.gradient_threshold, params_.dark_field, impl_->field);
  // The boundary first: the coarse pass's band starts at the frame's top when the field fills it.
  FieldFeatures& f = impl_->features;
  if (boundary && impl_->field) find_field_boundary(*bgr, *impl_->field, f.field_boundary, {}, &impl_->turf);
  // The thin-line pass's ridge rows come out of the frame's own gradient pass (ridge_pass.hpp).
  // When the boundary gates the markings, they start a band above the field's top: a marking
  // above it would be none, and the walls, people and lights there cost the pass time.
  const bool thin = params_.thin_reach > 0;
  elsed::RidgeTarget ridge;
  if (thin) {
    const int first = thresholds_.field_boundary_gate ? thin_band_start(f.field_boundary, bgr->rows) : 0;
    ridge = impl_->thin_engine.ridge_target(bgr->cols, first, thin_band_end(params_, bgr->rows), params_.thin_reach,
                                            gradient_threshold);
  }
  impl_->engine.run(*bgr, params_, gradient_threshold, out, thin ? &ridge : nullptr);
  if (params_.coarse_scale > 1) add_coarse(*bgr, gradient_threshold, out);
  std::optional<float> gain;
  if (thresholds_.light.enabled && impl_->field)
    gain = light_gain(thresholds_.light.reference_field, *impl_->field);
  centre_lines_from_ = out.size();  // the thin-line pass's segments come last
  if (thin) add_thin(*bgr, out);
  const std::size_t along_from = out.size();  // the far lines along the boundary come last of all
  if (thin && params_.thin_along_boundary > 0 && !f.field_boundary.fills_top())
    add_along_boundary(*bgr, gradient_threshold, gain, out);
  label(out, gain, thresholds_, f.field_boundary);
  // A line's centre is no edge of the field: a thin-line segment is a marking or nothing.
  for (std::size_t i = centre_lines_from_; i < out.size(); ++i)
    if (out[i].label == Label::Boundary) out[i].label = Label::None;
  if (stripes)
    find_stripes(*bgr, colours, out, params_, impl_->stripes, f.markings, ThinLines::Level, Shape::Any,
                 thresholds_.field_boundary_gate ? &f.field_boundary : nullptr);
  // The junctions and the circle take no far line along the boundary: a line the drawing has in
  // part gets its centre there too, and the two made false junctions (held-out synthetic Kid,
  // calibrated: junction precision 0.852 -> 0.825).
  if (pieces) find_pieces(*bgr, gain, {out.data(), along_from});
  if (camera_) project_features(f, *camera_, ground_params_, impl_->ground);
}

// The coarse pass: the band from coarse_from down, cropped to whole cells of coarse_scale px and
// averaged over them (box_downsample.hpp), detected with the coarse parameters; its segments mapped to
// full-scale pixels (a cell's centre is f x + (f - 1) / 2) join `out` where none of them lies
// along one already there. Every buffer is reused: no allocation once warm.
void LineDetector::add_coarse(const cv::Mat& bgr, int gradient_threshold, std::vector<Segment>& out) {
  const int f = params_.coarse_scale;
  const auto row_of = [&](double share) { return std::clamp(static_cast<int>(std::lround(share * bgr.rows)), 0, bgr.rows); };
  // The band starts on a whole cell of the frame's grid: where its top lies does not move the cells.
  // A camera looking down at the turf (the field fills the frame's top) has no far rows.
  const bool near_only = impl_->features.field_boundary.fills_top();
  const int alone = near_only ? 0 : row_of(params_.coarse_from);
  const int top = std::min(alone, row_of(params_.coarse_twins_from)) / f * f;
  const int w = bgr.cols / f, h = (bgr.rows - top) / f;
  if (w < 3 || h < 3) return;
  box_downsample(bgr(cv::Rect(0, top, w * f, h * f)), f, impl_->coarse_bgr, impl_->coarse_avx2);
  std::vector<Segment>& coarse = impl_->coarse;
  coarse.clear();
  impl_->coarse_engine.run(impl_->coarse_bgr, impl_->coarse_params, gradient_threshold, coarse);
  const float scale = static_cast<float>(f), shift = 0.5f * static_cast<float>(f - 1);
  for (Segment& s : coarse) {
    s.x0 = scale * s.x0 + shift, s.x1 = scale * s.x1 + shift;
    s.y0 = scale * s.y0 + shift + static_cast<float>(top), s.y1 = scale * s.y1 + shift + static_cast<float>(top);
    s.saliency *= scale;  // validated pixels, counted at the full scale
  }
  const std::size_t fine = out.size();
  for (const Segment& s : coarse)
    if ((0.5f * (s.y0 + s.y1) >= static_cast<float>(alone) || has_twin(s, coarse, scale, params_, bgr.rows)) &&
        !covered(s, {out.data(), fine}, scale + 0.5f))
      out.push_back(s);
}

// The thin-line pass: the rows above thin_to drawn on the lines' ridge (ridge_pass.hpp), which
// the gradient pass wrote; a segment along a line's centre joins `out` unless the segments there
// already hold both of the line's edges. Every buffer is reused: no allocation once warm.
void LineDetector::add_thin(const cv::Mat& bgr, std::vector<Segment>& out) {
  std::vector<Segment>& thin = impl_->thin;
  thin.clear();
  impl_->thin_engine.draw_ridges(bgr, params_, params_.thin_reach, thin);
  const std::size_t fine = out.size();
  // A line as wide as the ridges' reach has its edges that far off its centre; the smoothing
  // and the edge pixels' rounding move them up to a pixel farther (a 3 px line's, sloped: 2.7 px).
  const float reach = static_cast<float>(params_.thin_reach) + 1.f;
  for (const Segment& s : thin)
    if (!edges_held(s, {out.data(), fine}, reach)) out.push_back(s);
}

// The thin-line pass's far lines along the field boundary (along_boundary.hpp): a segment joins
// `out` when its colours may be a marking's (MarkingColours: what label() will call it) and the
// segments there do not already hold both of the line's edges. A faint ridge the classes call
// none is the turf's texture as often as paint (synthetic turf's streaks of 6 grey levels): the
// review would show it and the label-free fit would count it. Averaged over a window of 16
// columns, the profile's noise is a quarter of a column's: its ridge threshold is 0.4 of the thin
// pass's (gradient_threshold / 4 grey levels). Held out, calibrated: on any segment SSL 0.797 ->
// 0.874, Bangkok 0.862 -> 0.90 (docs/detector.md).
void LineDetector::add_along_boundary(const cv::Mat& bgr, int gradient_threshold, std::optional<float> gain,
                                      std::vector<Segment>& out) {
  constexpr float kAveragedRidgeShare = 0.4f;
  const int depth = static_cast<int>(std::lround(params_.thin_along_boundary * bgr.rows));
  const float threshold = kAveragedRidgeShare * static_cast<float>(gradient_threshold) / 4;
  const FieldBoundary& boundary = impl_->features.field_boundary;
  find_lines_along_boundary(bgr, boundary, depth, threshold, impl_->along, impl_->along_found);
  const MarkingColours colours{gain, thresholds_, boundary};
  const std::size_t fine = out.size();
  const float reach = kAlongBoundaryReach + 1.f;
  for (const Segment& s : impl_->along_found)
    if (MarkingColours::may_be_marking(&colours, s) && !edges_held(s, {out.data(), fine}, reach)) out.push_back(s);
}

// The centre circle needs pieces shorter than the detector's minimum length (a curve has no
// long straight piece): the frame is drawn a second time from the same gradients, and those
// pieces that are stripes are its input. The junctions take the detector's own segments that are
// straight stripes, and those pieces when they are drawn (a line running into a crossing often
// stops short of it): the second drawing costs about what the first does on textured turf, so
// it runs only for the circle.
void LineDetector::find_pieces(const cv::Mat& bgr, std::optional<float> gain, std::span<const Segment> segments) {
  constexpr int kPieceScanInterval = 4;  // a short piece needs an anchor on it
  FieldFeatures& f = impl_->features;
  std::vector<Segment>& pieces = impl_->pieces;
  // Painted lines lie below the field boundary: anchors above it (walls, the room) only draw
  // pieces that are no stripes. A margin keeps lines along the far edge, which the boundary's
  // blur can cut.
  std::vector<int>& rows = impl_->piece_rows;
  rows.clear();
  if (params_.centre_circle && !f.field_boundary.empty()) {
    const float margin = along_band_px(bgr.rows);
    rows.resize(static_cast<std::size_t>(bgr.cols));
    for (int x = 0; x < bgr.cols; ++x)
      rows[static_cast<std::size_t>(x)] = static_cast<int>(f.field_boundary.y_at(float(x)) - margin);
  }
  // An anchor with no pixel beside it as bright as a stripe's paint and as grey as the field
  // boundary's paint (turf texture, shade, bright blades of real grass) draws no stripe.
  const int bright = impl_->field ? static_cast<int>(std::ceil(kPaintContrast * FieldPixel(*impl_->field, {}).field_sum())) : 0;
  const float grey = FieldBoundaryParams{}.paint_chroma;
  // The colour test without its length (shortness is what these pieces are for), its angle
  // reaching the grey edges' angle: every piece must be a stripe, and geometry keeps grey edges
  // out as the colour cut would. Held-out junction recall 0.366 -> 0.496 at precision 0.882 ->
  // 0.897; no colour test at all: 0.520 at 0.853 (docs/detector.md).
  Thresholds short_pieces = thresholds_;
  ClassThresholds& piece = short_pieces.marking.thresholds;
  piece.min_length = 0;
  piece.max_angle_deg = std::max(piece.max_angle_deg, static_cast<float>(achromatic_angle_deg(thresholds_.marking)));
  // Only the markings among the pieces are used (find_stripes): a piece whose colours rule that
  // out is dropped before its angle test, about half of its validation (most pieces on turf).
  const MarkingColours colours{gain, short_pieces, f.field_boundary};
  // Its anchors lie near the first drawing's segments whose colours may be a marking's (within
  // kNearPaint px of their bounding boxes): the circle's paint draws some chord there, and
  // textured turf away from the lines draws no pieces at all. Tuning seeds: circles 33/52
  // either way (10 to 60 px: 33-34), the Humanoid frames' second drawing a third cheaper.
  if (params_.centre_circle) {
    constexpr float kNearPaint = 30;
    ElsedEngine::AnchorCells& near = impl_->near_paint;
    near.reset(bgr.cols, bgr.rows);
    for (const Segment& s : segments)
      if (MarkingColours::may_be_marking(&colours, s)) near.allow(s.x0, s.y0, s.x1, s.y1, kNearPaint);
    impl_->engine.redraw(bgr, params_, kPieceScanInterval, params_.piece_length, {rows, bright, grey, &near},
                         {&MarkingColours::may_be_marking, &colours}, pieces);
  } else {
    pieces.clear();
  }
  label(pieces, gain, short_pieces, f.field_boundary);
  const FieldColours turf = stripe_colours();
  find_stripes(bgr, turf, pieces, params_, impl_->piece_stripes, impl_->arcs);
  std::vector<std::uint8_t>& on_ellipse = impl_->circle.on_ellipse;
  if (params_.centre_circle)
    find_centre_circle(impl_->arcs, impl_->circle, f.ellipses, bgr, impl_->field, camera_, params_.centre_circle_radius);
  else on_ellipse.assign(impl_->arcs.size(), 0);
  if (params_.intersections) {
    // The circle's chords bend into each other and cross the halfway line: no junctions.
    impl_->lines.clear();
    for (std::size_t i = 0; i < impl_->arcs.size(); ++i)
      if (!on_ellipse[i]) impl_->lines.push_back(impl_->arcs[i]);
    // The detector's own segments that no piece lies along, when the pieces' colour test and
    // the stripes check keep them as straight stripes, are lines too: all of them without the
    // second drawing, and with it a far line in haze, paint too green for the pieces' anchors
    // that the detector's own drawing (no such limit) has. A segment whose paint bows
    // (Shape::Straight) is a chord of the circle or an arc, whose neighbours and crossings make
    // false junctions (docs/detector.md).
    collect_unpieced(segments, pieces, impl_->unpieced);
    label(impl_->unpieced, gain, short_pieces, f.field_boundary);
    find_stripes(bgr, turf, impl_->unpieced, params_, impl_->unpieced_stripes, impl_->unpieced_lines,
                 ThinLines::Level, Shape::Straight);
    impl_->lines.insert(impl_->lines.end(), impl_->unpieced_lines.begin(), impl_->unpieced_lines.end());
    find_intersections(impl_->lines, params_, impl_->intersections, f.intersections, bgr.size());
    if (camera_ && params_.intersection_ground_tolerance > 0) {
      const GroundProjection ground(*camera_);
      std::erase_if(f.intersections, [&](const Intersection& j) {
        return !square_on_ground(j, ground, params_.intersection_ground_tolerance);
      });
    }
  }
  // The circle's pieces are markings too (arcs).
  for (std::size_t i = 0; i < impl_->arcs.size(); ++i)
    if (on_ellipse[i]) f.markings.push_back(impl_->arcs[i]);
}

void LineDetector::set_params(const DetectorParams& params) {
  validate(params);
  params_ = params;
  impl_->coarse_params = coarse_params_of(params_);
}

void LineDetector::set_camera(const std::optional<GroundCamera>& camera) {
  if (camera) validate(*camera);
  camera_ = camera;
}

const FieldBoundary& LineDetector::field_boundary() const { return impl_->features.field_boundary; }
const std::optional<Rgb>& LineDetector::field_colour() const { return impl_->field; }
FieldColours LineDetector::stripe_colours() const {
  return {impl_->field, params_.stripe_turf_colours ? &impl_->turf : nullptr};
}
const FieldFeatures& LineDetector::features() const { return impl_->features; }
const GroundFeatures& LineDetector::ground_features() const { return impl_->ground; }
void LineDetector::set_ground_params(const GroundFeatureParams& params) {
  validate(params);
  ground_params_ = params;
}

LineDetector::GradientViews LineDetector::compute_gradients(const cv::Mat& image) {
  const cv::Mat* bgr = normalise(image);
  if (!bgr) return {};
  impl_->engine.compute_gradients(*bgr, params_, params_.gradient_threshold);
  const elsed::GradientMaps& g = impl_->engine.gradients();
  // Views over the engine's buffers: the const_cast only satisfies cv::Mat's constructor.
  const auto view = [&](const std::vector<std::int16_t>& v) {
    return cv::Mat(g.height, g.width, CV_16SC1, const_cast<std::int16_t*>(v.data()));
  };
  return {view(g.dx), view(g.dy), view(g.mag)};
}

}  // namespace fieldlines
