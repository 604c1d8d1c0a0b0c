#include "edge_drawer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "angles.hpp"
#include "pixel_steps.hpp"

namespace fieldlines::elsed {
namespace {

constexpr int kMaxOutliers = 3;  // consecutive off-line pixels tolerated before leaving a line
constexpr double kPi = std::numbers::pi;

}  // namespace

void EdgeDrawer::reset(GradientMaps& maps, const DrawerParams& params) {
  maps_ = &maps;
  state_ = maps.state.data();
  params_ = params;
  segments_.clear();
  stack_.clear();
  prefixes_.clear();
  chain_.clear();
}

void EdgeDrawer::draw_from_anchor(Pixel anchor) {
  const EdgeDir dir = dir_of(state_[anchor.y * maps_->width + anchor.x]);
  const Step first = dir == EdgeDir::Horizontal ? Step::Right : Step::Down;
  set_mark(anchor, Mark::Anchor);
  // Only this anchor's own first-branch pixels may seed its other side: never a previous
  // anchor's (or a previous image's, whose pixels may lie outside this one).
  anchor_pixels_.clear();
  stack_.push_back({first, anchor, true});
  chain_.push_back(anchor);
  draw_tree(anchor, anchor_pixels_, true);
  // The second direction starts with the first direction's unused pixels (reversed) so a line
  // through the anchor can be fitted across it.
  const auto begin = static_cast<std::uint32_t>(prefixes_.size());
  prefixes_.insert(prefixes_.end(), anchor_pixels_.begin(), anchor_pixels_.end());
  stack_.push_back({opposite(first), anchor, true, begin, static_cast<std::uint32_t>(prefixes_.size())});
  draw_tree(anchor, anchor_pixels_, false);
}

void EdgeDrawer::push_or_reuse(bool& reuse_top, Step step, Pixel px, bool first_side) {
  if (reuse_top) {
    reuse_top = false;
    Branch& b = stack_.back();
    b.step = step;
    b.px = px;
    b.first_side = first_side;
    b.prefix_begin = b.prefix_end = 0;
  } else {
    stack_.push_back({step, px, first_side});
  }
}

void EdgeDrawer::draw_tree(Pixel anchor, std::vector<Pixel>& anchor_pixels, bool first_call) {
  const int width = maps_->width;
  const int min_len = params_.min_line_length;
  bool on_segment = false;
  bool first_branch = true;
  // Extending the anchor's first side: the anchor itself is the first pixel of the branch.
  const bool anchor_is_first_px = first_call && chain_.back() == anchor;

  segments_.emplace_back();
  std::size_t cur = segments_.size() - 1;

  while (!stack_.empty()) {
    bool pop = true;
    int branch_start = static_cast<int>(chain_.size());
    if (first_branch && anchor_is_first_px) --branch_start;
    Branch& top = stack_.back();
    const Step step = top.step;
    Pixel px = top.px;
    const bool first_side = top.first_side;
    chain_.insert(chain_.end(), prefixes_.begin() + top.prefix_begin, prefixes_.begin() + top.prefix_end);

    int checked = branch_start;  // chain index where the next fit attempt starts
    outliers_.clear();
    bool hit_owned = false;
    Pixel last = pixel_behind(px, step);
    EdgeDir dir = (step == Step::Down || step == Step::Up) ? EdgeDir::Vertical : EdgeDir::Horizontal;
    bool model_started = false;
    int idx = px.y * width + px.x;

    while (static_cast<int>(outliers_.size()) <= kMaxOutliers) {
      if (!step_along_gradient(dir, *maps_, px, last, true)) break;
      idx = px.y * width + px.x;
      const PixelState state = state_[idx];
      const Mark m = mark_of(state);
      hit_owned = m == Mark::Inlier || m == Mark::Junction || m == Mark::Edge;
      if (hit_owned) break;

      LineModel& seg = segments_[cur];
      if (on_segment) {
        if (seg.is_inlier(px.x, px.y, params_.px_to_segment_dist)) {
          set_mark(idx, Mark::Inlier);
          chain_.push_back(px);
          outliers_.clear();
          seg.add(px, static_cast<int>(chain_.size()) - 1, first_side);
          (first_side ? seg.first_side_done : seg.second_side_done) = false;
        } else {
          outliers_.push_back(px);
          set_mark(idx, Mark::Outlier);
        }
      } else {
        chain_.push_back(px);
        set_mark(idx, Mark::Edge);
        if (static_cast<int>(chain_.size()) - checked >= min_len) {
          if (model_started) {
            seg.slide_two(chain_);
          } else {
            model_started = true;
            seg.init(chain_, checked);
          }
          if (seg.fits(chain_, params_.line_fit_error)) {
            on_segment = true;
            for (int i = checked; i < checked + min_len; ++i) set_mark(chain_[i], Mark::Inlier);
          } else {
            checked += 2;
          }
        }
      }
      dir = dir_of(state);
    }

    // Remember the first branch's pixels next to the anchor for the anchor's other side.
    if (first_branch && mark(anchor) != Mark::Inlier) {
      anchor_pixels.clear();
      const int n = std::min(static_cast<int>(chain_.size()) - branch_start, min_len - 1);
      for (int i = branch_start + n - 1; i >= branch_start; --i) {
        const Mark m = mark(chain_[i]);
        if (m == Mark::Inlier || m == Mark::Junction) break;
        anchor_pixels.push_back(chain_[i]);
      }
    }

    if (on_segment) {
      LineModel* seg = &segments_[cur];
      if (!outliers_.empty() && (first_side || seg->has_second_side())) {
        // The last inlier before the outliers is usually the start of the turn: drop it.
        const Pixel drop = first_side ? seg->last() : seg->first();
        set_mark(drop, Mark::Free);
        seg->remove_endpoint(first_side);
        outliers_.insert(outliers_.begin(), chain_.back());
        chain_.pop_back();
        if (!first_side && seg->first() == anchor) seg->second_side_done = true;
      }

      if (static_cast<int>(outliers_.size()) > kMaxOutliers) {
        // The edge turned: draw on from here as a new, free edge once this segment is done.
        for (const Pixel& o : outliers_) set_mark(o, Mark::Free);
        Step predicted;
        if (dir_of(state_[idx]) == EdgeDir::Horizontal) predicted = last.x < px.x ? Step::Right : Step::Left;
        else predicted = last.y < px.y ? Step::Down : Step::Up;
        push_or_reuse(pop, predicted, px, true);  // `pop` is still true here: reuses the top
        Branch& turn = stack_.back();
        turn.prefix_begin = static_cast<std::uint32_t>(prefixes_.size());
        prefixes_.push_back(chain_.back());
        prefixes_.insert(prefixes_.end(), outliers_.begin(), outliers_.end());
        turn.prefix_end = static_cast<std::uint32_t>(prefixes_.size());
      }

      const bool blocked = static_cast<int>(outliers_.size()) > kMaxOutliers || hit_owned;
      if (blocked && !seg->first_side_done && params_.treat_junctions && can_extend(*seg, true, extension_)) {
        // Jump the discontinuity and keep drawing straight on.
        const Step line_step = step_of_line(seg->equation());
        add_junction_pixels(extension_, *seg, first_side);
        push_or_reuse(pop, line_step, extension_.back(), true);
      } else {
        seg->first_side_done = true;
        if (!seg->second_side_done && seg->first() == anchor) {
          // Draw the other side of the segment from the anchor, without jumping.
          seg->second_side_done = true;
          push_or_reuse(pop, opposite(step_of_line(seg->equation())), anchor, false);
        } else if (!seg->second_side_done && params_.treat_junctions && can_extend(*seg, false, extension_)) {
          add_junction_pixels(extension_, *seg, false);
          push_or_reuse(pop, opposite(step_of_line(seg->equation())), extension_.back(), false);
        } else {
          seg->second_side_done = true;
          seg->finish();
          segments_.emplace_back();
          cur = segments_.size() - 1;
          on_segment = false;
        }
      }
    }

    if (pop) stack_.pop_back();
    first_branch = false;
    extension_.clear();
  }
  segments_.pop_back();  // the last one was never finished
}

void EdgeDrawer::add_junction_pixels(const std::vector<Pixel>& extension, LineModel& seg, bool first_side) {
  (first_side ? seg.first_side_done : seg.second_side_done) = true;
  const std::size_t half = extension.size() / 2;
  for (std::size_t i = 0; i < extension.size(); ++i) {
    const Pixel p = extension[i];
    if (seg.is_inlier(p.x, p.y, params_.px_to_segment_dist)) {
      // The half nearest the segment is the junction itself: owned, but not validated.
      set_mark(p, i < half ? Mark::Junction : Mark::Inlier);
      chain_.push_back(p);
      seg.add(p, static_cast<int>(chain_.size()) - 1, first_side);
    } else {
      set_mark(p, Mark::Outlier);
    }
  }
}

bool EdgeDrawer::can_extend(const LineModel& seg, bool at_end, std::vector<Pixel>& extension) {
  const int w = maps_->width, h = maps_->height;
  const Pixel start = at_end ? seg.last() : seg.first();
  // Accumulates over the tried jump sizes, as the method does.
  to_validate_.clear();
  for (const int size : params_.junction_sizes) {
    if (static_cast<int>(seg.count()) <= size) break;
    Pixel px = start;
    if (!jump_along_line(*maps_, seg.equation(), !at_end, size, px)) continue;
    extension.clear();
    line_pixels(start, px, extension);
    if (extension.size() < 2) continue;
    Pixel last = extension[extension.size() - 2];

    // Past the gap, the edge must go on for `size` pixels, all on the line.
    const EdgeDir along = seg.horizontal() ? EdgeDir::Horizontal : EdgeDir::Vertical;
    bool ok = true;
    for (int i = 0; i < size && ok; ++i) {
      ok = step_along_gradient(along, *maps_, px, last) &&
           seg.is_inlier(px.x, px.y, params_.px_to_segment_dist);
      if (ok) {
        extension.push_back(px);
        to_validate_.push_back(px);
      }
    }
    if (!ok) continue;

    // Structure tensor of the gradients around the new pixels: one dominant orientation,
    // perpendicular to the line.
    const auto& eq = seg.equation();
    const double normal = wrap_half_turn(std::atan2(eq[0], eq[1]) + kPi / 2);
    float a = 0, b = 0, d = 0;
    const bool across_y = std::abs(to_validate_.back().x - to_validate_.front().x) >=
                          std::abs(to_validate_.back().y - to_validate_.front().y);
    for (const Pixel& p : to_validate_) {
      for (const int off : {-1, 0, 1}) {
        const int x = std::clamp(p.x + (across_y ? 0 : off), 0, w - 1);
        const int y = std::clamp(p.y + (across_y ? off : 0), 0, h - 1);
        const int gx = maps_->dx[y * w + x], gy = maps_->dy[y * w + x];
        a += static_cast<float>(gx * gx);
        b += static_cast<float>(gx * gy);
        d += static_cast<float>(gy * gy);
      }
    }
    const float diff = a * a - d * d;
    const float s1 = a * a + 2 * b * b + d * d;
    const float s2 = std::sqrt(diff * diff + 4 * b * b * (a + d) * (a + d));
    const double tensor_angle = wrap_half_turn(-0.5f * std::atan2(2 * a * b + 2 * b * d, diff));
    const bool dominant = std::sqrt((s1 + s2) / (s1 - s2 + 0.00001f)) > params_.junction_eigen_ratio;
    const bool aligned = orientation_distance(normal, tensor_angle) < params_.junction_max_angle;
    if (dominant && aligned) return true;
  }
  return false;
}

}  // namespace fieldlines::elsed
