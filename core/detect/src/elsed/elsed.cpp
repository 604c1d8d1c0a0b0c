#include "elsed.hpp"

#include <algorithm>
#include <bit>

#include <opencv2/core/hal/intrin.hpp>

#include "colour_gradients.hpp"
#include "features/field_pixel.hpp"

namespace fieldlines {

using elsed::EdgeDir;
using elsed::Mark;
using elsed::dir_of;
using elsed::mark_of;
using elsed::Pixel;

void ElsedEngine::compute_gradients(const cv::Mat& bgr, const DetectorParams& params, int gradient_threshold,
                                    const elsed::RidgeTarget* ridge) {
  const auto threads = static_cast<std::size_t>(params.threads);
  if (passes_.size() != threads || params.gaussian_kernel != pass_kernel_ || params.gaussian_sigma != pass_sigma_) {
    passes_.resize(threads);
    for (elsed::GradientPass& p : passes_) p.configure(params.gaussian_kernel, params.gaussian_sigma, gradient_threshold);
    pass_kernel_ = params.gaussian_kernel;
    pass_sigma_ = params.gaussian_sigma;
    pass_threshold_ = gradient_threshold;
    if (threads == 1) workers_.resize(0);
  }
  if (gradient_threshold != pass_threshold_) {  // a dark field's frame (light.hpp)
    for (elsed::GradientPass& p : passes_) p.set_threshold(gradient_threshold);
    pass_threshold_ = gradient_threshold;
  }
  const int h = bgr.rows, bands = passes_.front().band_count(h, params.threads);
  // One list of written ridge blocks per band (grows with the band count only).
  if (ridge) ridge->blocks->resize(std::max(ridge->blocks->size(), static_cast<std::size_t>(bands)));
  const auto blocks = [&](int i) { return ridge ? &(*ridge->blocks)[static_cast<std::size_t>(i)] : nullptr; };
  if (bands == 1) {
    passes_.front().run(bgr, maps_, ridge, blocks(0));
    return;
  }
  workers_.resize(params.threads - 1);  // once; later frames reuse the threads
  elsed::GradientPass::size_maps(bgr, maps_);
  auto band = [&](int i) {
    passes_[static_cast<std::size_t>(i)].run_rows(bgr, maps_, h * i / bands, h * (i + 1) / bands, ridge, blocks(i));
  };
  workers_.run(bands, band);
}

void ElsedEngine::AnchorCells::allow(float x0, float y0, float x1, float y1, float margin) {
  // Off the frame clamps to an edge cell, NaN to the first: never outside the mask.
  const auto cell_of = [&](float v, int count) {
    const float px = v >= 0 ? std::min(v, 1e6f) : 0.f;
    return std::min(static_cast<int>(px) / cell, count - 1);
  };
  if (columns <= 0 || rows <= 0) return;
  const int c0 = cell_of(std::min(x0, x1) - margin, columns), c1 = cell_of(std::max(x0, x1) + margin, columns);
  const int r0 = cell_of(std::min(y0, y1) - margin, rows), r1 = cell_of(std::max(y0, y1) + margin, rows);
  for (int r = r0; r <= r1; ++r)
    std::fill_n(allowed.begin() + static_cast<std::ptrdiff_t>(r) * columns + c0, c1 - c0 + 1, std::uint8_t{1});
}

void ElsedEngine::find_anchors(int scan_interval, int threshold, const cv::Mat& bgr, const AnchorLimits& limits) {
  constexpr int kBrightReach = 5;
  const int w = maps_.width, h = maps_.height;
  const std::int16_t* g = maps_.mag.data();
  const bool limited = static_cast<int>(limits.first_rows.size()) == w;
  // Whether a pixel within kBrightReach across the edge at (x, y) reaches min_bright_sum.
  const auto bright_beside = [&](int x, int y, bool across_rows) {
    for (int d = -kBrightReach; d <= kBrightReach; ++d) {
      const int px = across_rows ? x : x + d, py = across_rows ? y + d : y;
      if (px < 0 || py < 0 || px >= w || py >= h) continue;
      const std::uint8_t* p = bgr.ptr<std::uint8_t>(py) + 3 * px;
      const int sum = p[0] + p[1] + p[2];
      if (sum >= limits.min_bright_sum && near_grey(p, sum, limits.max_chroma)) return true;
    }
    return false;
  };
  // The method scans column by column, and that order decides which anchor draws an edge first.
  // Columns of a frame stride across cache lines: the grid is read row by row instead (each
  // row's cache lines shared by its columns and by bright_beside's windows), and the anchors are
  // then put in column order (within a column they arrive top-down, as the method finds them).
  const int columns = w > 2 ? (w - 3) / scan_interval + 1 : 0;  // grid columns 1 + k * scan_interval < w - 1
  column_first_.resize(static_cast<std::size_t>(columns));
  column_start_.assign(static_cast<std::size_t>(columns) + 1, 0);
  int top = h;
  for (int k = 0; k < columns; ++k) {
    // The first grid row (1 + k * scan_interval) at or below the column's first row.
    const int first = limited ? limits.first_rows[static_cast<std::size_t>(1 + k * scan_interval)] : 1;
    const int y0 = first <= 1 ? 1 : 1 + (first - 1 + scan_interval - 1) / scan_interval * scan_interval;
    column_first_[static_cast<std::size_t>(k)] = y0;
    top = std::min(top, y0);
  }
  // Grid column k of row y: an anchor when it is a local maximum across its edge by at least
  // `threshold` and within the limits.
  const auto consider = [&](int k, int y) {
    if (y < column_first_[static_cast<std::size_t>(k)]) return;
    const int x = 1 + k * scan_interval, i = y * w + x;
    if (g[i] == 0 || (limits.cells && !limits.cells->allows(x, y))) return;
    const bool across_rows = dir_of(maps_.state[i]) == EdgeDir::Horizontal;
    const int step = across_rows ? w : 1;
    if (g[i] >= g[i - step] + threshold && g[i] >= g[i + step] + threshold &&
        (limits.min_bright_sum <= 0 || bright_beside(x, y, across_rows))) {
      row_anchors_.push_back({x, y});
      ++column_start_[static_cast<std::size_t>(k) + 1];
    }
  };
  row_anchors_.clear();
  const int lattice = std::max(limits.lattice, 1);
  for (int y = top; y < h - 1; y += scan_interval) {
    if (lattice > 1 && (y - 1) / scan_interval % lattice != 0) {
      for (int k = 0; k < columns; k += lattice) consider(k, y);  // a lattice column's point
      continue;
    }
    int k = 0;
#if CV_SIMD128
    // The method's grid (every second column, the one calibration keeps): eight grid columns
    // at a time, of which only those that are a local maximum across either axis are tested
    // as above. Most of a textured field's grid has a gradient and is no maximum: the scalar
    // test alone mispredicted its branches on every other pixel (a sixth of a detect).
    if (scan_interval == 2) {
      const std::int16_t* row = g + y * w;
      const cv::v_int16x8 t = cv::v_setall_s16(static_cast<std::int16_t>(std::min(threshold, 32767)));
      const cv::v_int16x8 zero = cv::v_setzero_s16();
      // Columns x0 - 1 .. x0 + 16 are read: within the row.
      for (; k + 8 <= columns && 2 * k + 17 < w; k += 8) {
        const int x0 = 1 + 2 * k;
        cv::v_int16x8 left, c, right, skip, up, down;
        cv::v_load_deinterleave(row + x0 - 1, left, c);
        cv::v_load_deinterleave(row + x0 + 1, right, skip);
        cv::v_load_deinterleave(row - w + x0, up, skip);
        cv::v_load_deinterleave(row + w + x0, down, skip);
        // Saturating sums: a superset of the exact test's maxima.
        const cv::v_int16x8 across_x = (c >= left + t) & (c >= right + t);
        const cv::v_int16x8 across_y = (c >= up + t) & (c >= down + t);
        for (unsigned bits = static_cast<unsigned>(cv::v_signmask((across_x | across_y) & (c != zero))); bits;
             bits &= bits - 1)
          consider(k + std::countr_zero(bits), y);
      }
    }
#endif
    for (; k < columns; ++k) consider(k, y);
  }
  for (int k = 0; k < columns; ++k)
    column_start_[static_cast<std::size_t>(k) + 1] += column_start_[static_cast<std::size_t>(k)];
  anchors_.resize(row_anchors_.size());
  for (const Pixel& a : row_anchors_)
    anchors_[static_cast<std::size_t>(column_start_[static_cast<std::size_t>((a.x - 1) / scan_interval)]++)] = a;
}

void ElsedEngine::run(const cv::Mat& bgr, const DetectorParams& params, int gradient_threshold,
                      std::vector<Segment>& out, const elsed::RidgeTarget* ridge) {
  compute_gradients(bgr, params, gradient_threshold, ridge);

  // With no anchor at all, retry with a halved threshold (down to zero) like the method.
  int anchor_threshold = params.anchor_threshold;
  for (;;) {
    find_anchors(params.scan_interval, anchor_threshold, bgr, {});
    if (!anchors_.empty() || anchor_threshold == 0) break;
    anchor_threshold /= 2;
  }

  draw_and_validate(bgr, params, params.min_line_length, {}, out);
}

elsed::RidgeTarget ElsedEngine::ridge_target(int width, int first_row, int rows, int reach, int threshold) {
  elsed::ready_ridge_maps(width, rows, maps_, ridge_blocks_);
  return {std::clamp(reach, 1, elsed::kMaxRidgeReach), std::max(first_row, 0), std::clamp(threshold, 1, 32767),
          ridge_avx2_, &maps_, &ridge_blocks_};
}

void ElsedEngine::draw_ridges(const cv::Mat& bgr, const DetectorParams& params, int reach, std::vector<Segment>& out) {
  const cv::Mat band = bgr.rowRange(0, std::clamp(maps_.height, 0, bgr.rows));  // a view: no copy
  if (band.rows < 3 || maps_.width != bgr.cols) return;
  AnchorLimits lattice;
  const int min_length = elsed::thin_min_length(params.min_line_length);
  lattice.lattice = elsed::ridge_anchor_lattice(min_length, params.scan_interval);
  find_anchors(params.scan_interval, params.anchor_threshold, band, lattice);
  draw_and_validate(band, params, min_length, {}, out, reach);
}

void ElsedEngine::draw_and_validate(const cv::Mat& bgr, const DetectorParams& params, int min_line_length,
                                    elsed::SegmentFilter keep, std::vector<Segment>& out, int ridge_reach) {
  elsed::DrawerParams& dp = drawer_params_;
  dp.line_fit_error = params.line_fit_error;
  dp.px_to_segment_dist = params.px_to_segment_dist;
  dp.min_line_length = min_line_length;
  dp.treat_junctions = params.treat_junctions;
  dp.junction_sizes = params.junction_sizes;  // copy-assignment: reuses the capacity
  drawer_.reset(maps_, dp);  // run()'s gradient pass has left every mark Free; redraw() clears them
  const int w = maps_.width;
  for (const Pixel& a : anchors_) {
    if (mark_of(maps_.state[a.y * w + a.x]) != Mark::Free) continue;  // already part of an edge
    drawer_.draw_from_anchor(a);
  }

  const elsed::ValidationParams vp{params.validation_threshold, params.validate, ridge_reach};
  Segment s;
  for (const elsed::LineModel& seg : drawer_.segments()) {
    if (elsed::validate_segment(seg, drawer_.chain(), maps_, bgr, vp, s, keep)) out.push_back(s);
  }
}

void ElsedEngine::redraw(const cv::Mat& bgr, const DetectorParams& params, int scan_interval, int min_line_length,
                         const AnchorLimits& limits, elsed::SegmentFilter keep, std::vector<Segment>& out) {
  out.clear();
  if (maps_.width != bgr.cols || maps_.height != bgr.rows) return;  // run() has not seen this frame
  // The first drawing's marks would stop the new one at every pixel it owns: back to Free,
  // keeping each pixel's edge direction.
  for (elsed::PixelState& st : maps_.state) st = elsed::with_mark(st, Mark::Free);
  find_anchors(scan_interval, params.anchor_threshold, bgr, limits);
  draw_and_validate(bgr, params, min_line_length, keep, out);
}

}  // namespace fieldlines
