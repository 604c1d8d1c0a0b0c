#pragma once
// Private: the ELSED pipeline (smoothing, gradients, anchors, drawing, validation) with the
// method's colour-gradient extraction. Owns every buffer so repeated calls do not allocate.
#include <span>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "band_workers.hpp"
#include "colour_gradients.hpp"
#include "edge_drawer.hpp"
#include "elsed_types.hpp"
#include "gradient_pass.hpp"
#include "gradient_rows_avx2.hpp"
#include "ridge_pass.hpp"
#include "fieldlines/detect/detector.hpp"

#pragma GCC visibility push(hidden)  // private to the library (see line_model.hpp)

namespace fieldlines {

class ElsedEngine {
 public:
  // bgr: 8-bit, 3 channels, at least 3x3. Appends unclassified segments to `out`.
  // `gradient_threshold` stands for params.gradient_threshold: the frame's own (a dark field's
  // is lower, light.hpp), so that a caller need not copy the parameters per frame.
  // With `ridge` (another engine's ridge_target()), the gradient pass also writes that engine's
  // ridge maps.
  void run(const cv::Mat& bgr, const DetectorParams& params, int gradient_threshold, std::vector<Segment>& out,
           const elsed::RidgeTarget* ridge = nullptr);
  // This engine as the thin-line pass (ridge_pass.hpp): readies its ridge maps for the first
  // `rows` rows of a frame `width` wide, for lines up to 2 reach - 1 px wide, and says where the
  // frame's run() (another engine's) writes them. Then draw_ridges(): the same anchors, drawing
  // and validation on them; segments along the lines' centres, with the lines' colours
  // (colour_gradients.hpp), appended to `out`.
  elsed::RidgeTarget ridge_target(int width, int first_row, int rows, int reach, int threshold);
  void draw_ridges(const cv::Mat& bgr, const DetectorParams& params, int reach, std::vector<Segment>& out);
  // The first stage alone (what run() starts with): fills gradients().
  void compute_gradients(const cv::Mat& bgr, const DetectorParams& params, int gradient_threshold,
                         const elsed::RidgeTarget* ridge = nullptr);
  const elsed::GradientMaps& gradients() const { return maps_; }
  // Where anchors may lie, in square cells of `cell` px (a coarse mask: cheap to clear and fill).
  struct AnchorCells {
    int cell = 8, columns = 0, rows = 0;
    std::vector<std::uint8_t> allowed;  // row-major, columns x rows
    void reset(int width, int height) {
      columns = (width + cell - 1) / cell, rows = (height + cell - 1) / cell;
      allowed.assign(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), 0);
    }
    // Allows every cell that the box with corners (x0, y0) and (x1, y1), in either order and
    // widened by `margin` on every side (px, clamped to the frame), touches.
    void allow(float x0, float y0, float x1, float y1, float margin);
    bool allows(int x, int y) const {
      return allowed[static_cast<std::size_t>(y / cell) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(x / cell)];
    }
  };
  // After run() on the same frame: draws it again from anchors every `scan_interval` px, keeping
  // segments from `min_line_length` px (the short pieces of curves), into `out` (cleared first).
  // `limits` keeps anchors from where no piece is wanted (edges drawn from the others may still
  // run there).
  struct AnchorLimits {
    std::span<const int> first_rows;  // one per column: anchors from that row down; empty: all
    int min_bright_sum = 0;           // a pixel this bright (B + G + R) within 5 px across...
    float max_chroma = 2;             // ...and this grey (near_grey, field_pixel.hpp); 2: any
    const AnchorCells* cells = nullptr;  // anchors only in the cells it allows; null: anywhere
    int lattice = 1;  // the grid kept on every lattice-th of its columns and rows only (ridge_pass.hpp); 1: all
  };
  // `keep` drops segments by their colours before their validation (colour_gradients.hpp).
  void redraw(const cv::Mat& bgr, const DetectorParams& params, int scan_interval, int min_line_length,
              const AnchorLimits& limits, elsed::SegmentFilter keep, std::vector<Segment>& out);

 private:
  void draw_and_validate(const cv::Mat& bgr, const DetectorParams& params, int min_line_length,
                         elsed::SegmentFilter keep, std::vector<Segment>& out, int ridge_reach = 0);
  void find_anchors(int scan_interval, int threshold, const cv::Mat& bgr, const AnchorLimits& limits);

  // One pass per thread (each its own scratch rows), all configured alike; passes_[0] runs on
  // the calling thread.
  std::vector<elsed::GradientPass> passes_;
  std::vector<elsed::RidgeBlocks> ridge_blocks_;  // as the thin-line pass: per band, what the frame's pass wrote
  bool ridge_avx2_ = elsed::avx2::wanted();
  elsed::BandWorkers workers_;  // started when a frame first splits into bands
  int pass_kernel_ = -1, pass_threshold_ = -1;  // what passes_ are configured for
  double pass_sigma_ = -1;
  elsed::DrawerParams drawer_params_;  // a member so its junction_sizes keeps its capacity
  elsed::GradientMaps maps_;
  std::vector<elsed::Pixel> anchors_;      // in the method's order: column by column, top-down
  std::vector<elsed::Pixel> row_anchors_;  // find_anchors' scratch: the same, row by row
  std::vector<int> column_first_;          // find_anchors' scratch: each grid column's first row
  std::vector<int> column_start_;          // ...and where its anchors start in anchors_
  elsed::EdgeDrawer drawer_;
};

}  // namespace fieldlines

#pragma GCC visibility pop
