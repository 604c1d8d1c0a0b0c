#pragma once
// Private: ELSED's edge drawing with on-line line fitting and junction jumps.
//
// From an anchor, pixels are followed along the gradient ridge. Once `min_line_length` pixels
// fit a line (mean squared error below the threshold), the drawing only accepts pixels close to
// that line and keeps refitting. Where the edge leaves the line (several outliers in a row, or a
// pixel already owned by another edge), the drawer tries to jump the discontinuity along the
// line's own direction (junction sizes), checking on the far side that the edge goes on with the
// same orientation (gradient structure tensor). Pending work is a stack of branches.
#include <cstdint>
#include <vector>

#include "elsed_types.hpp"
#include "line_model.hpp"

#pragma GCC visibility push(hidden)  // private to the library (see line_model.hpp)

namespace fieldlines::elsed {

// The first five are DetectorParams' fields of the same names (ElsedEngine copies them in).
struct DrawerParams {
  double line_fit_error = 0;
  double px_to_segment_dist = 0;
  int min_line_length = 0;
  bool treat_junctions = false;
  std::vector<int> junction_sizes;
  double junction_eigen_ratio = 10;         // dominant / minor singular value of the tensor
  double junction_max_angle = 0.174532925;  // 10 degrees, tensor orientation vs the line normal
};

class EdgeDrawer {
 public:
  // Prepares for a new image; every pixel's mark in maps.state must be Free (as the gradient
  // pass leaves it). The drawing marks pixels there.
  void reset(GradientMaps& maps, const DrawerParams& params);
  void draw_from_anchor(Pixel anchor);

  // Finished segments, in the order they were completed; their pixels index into chain().
  const std::vector<LineModel>& segments() const { return segments_; }
  const std::vector<Pixel>& chain() const { return chain_; }

 private:
  struct Branch {
    Step step;
    Pixel px;
    bool first_side;  // pixels extend the segment's first side (its end)
    // Pixels to put on the chain before drawing: prefixes_[prefix_begin, prefix_end). A range
    // in one pool rather than a vector per branch, so pushing a branch never allocates.
    std::uint32_t prefix_begin = 0, prefix_end = 0;
  };

  void draw_tree(Pixel anchor, std::vector<Pixel>& anchor_pixels, bool first_call);
  bool can_extend(const LineModel& seg, bool at_end, std::vector<Pixel>& extension);
  void add_junction_pixels(const std::vector<Pixel>& extension, LineModel& seg, bool first_side);
  void push_or_reuse(bool& reuse_top, Step step, Pixel px, bool first_side);
  Mark mark(int i) const { return mark_of(state_[i]); }
  Mark mark(Pixel p) const { return mark(p.y * maps_->width + p.x); }
  void set_mark(int i, Mark m) { state_[i] = with_mark(state_[i], m); }
  void set_mark(Pixel p, Mark m) { set_mark(p.y * maps_->width + p.x, m); }

  const GradientMaps* maps_ = nullptr;
  PixelState* state_ = nullptr;  // maps_->state, written
  DrawerParams params_;
  std::vector<LineModel> segments_;
  std::vector<Branch> stack_;
  std::vector<Pixel> prefixes_;  // every branch's prefix for this image, appended, cleared by reset
  std::vector<Pixel> chain_;
  // Scratch reused between calls.
  std::vector<Pixel> outliers_, extension_, to_validate_, anchor_pixels_;
};

}  // namespace fieldlines::elsed

#pragma GCC visibility pop
