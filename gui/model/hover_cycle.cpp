#include "gui/model/hover_cycle.hpp"

#include <algorithm>

namespace fieldlines::studio {

namespace {
// A handful of segments at most, every frame: a permutation check needs no allocation.
bool same_set(std::span<const std::size_t> a, std::span<const std::size_t> b) {
  return a.size() == b.size() && std::is_permutation(a.begin(), a.end(), b.begin());
}
}  // namespace

std::optional<std::size_t> HoverCycle::update(std::size_t image, std::span<const std::size_t> under,
                                              std::span<const Segment> segments) {
  previous_.swap(candidates_);  // both keep their capacity: no allocation per frame
  candidates_.assign(under.begin(), under.end());
  // Indices past the image's segments would be stale (the image was re-detected).
  std::erase_if(candidates_, [&](std::size_t i) { return i >= segments.size(); });
  const bool same = image == image_ && same_set(candidates_, previous_);
  image_ = image;
  if (!same) pinned_.reset();
  const auto contains = [&](std::size_t i) { return std::find(candidates_.begin(), candidates_.end(), i) != candidates_.end(); };
  if (pinned_ && !contains(*pinned_)) pinned_.reset();

  std::optional<std::size_t> now = pinned_ ? pinned_ : (candidates_.empty() ? std::nullopt : std::optional(candidates_[0]));
  if (same && now && now == hovered_ && segments[*now].label != hovered_label_ &&
      segments[*now].label != Label::Unlabelled) {
    // Just labelled: on to the next unlabelled segment under the cursor, if any. A cleared label
    // (C, or an undo) stays hovered, to be labelled again.
    const std::size_t n = candidates_.size();
    const std::size_t at = rank(now);
    for (std::size_t k = 1; k < n; ++k) {
      const std::size_t other = candidates_[(at + k) % n];
      if (segments[other].label == Label::Unlabelled) {
        pinned_ = other;
        now = other;
        break;
      }
    }
  }
  hovered_ = now;
  hovered_label_ = now ? segments[*now].label : Label::Unlabelled;
  return hovered_;
}

bool HoverCycle::next() {
  if (candidates_.size() < 2) return false;
  // From the one chosen so far (two presses in one frame move twice). hovered_ itself changes at
  // the next update, so a cycled-to segment is not mistaken for one whose label just changed.
  const std::optional<std::size_t> from = pinned_ ? pinned_ : hovered_;
  pinned_ = candidates_[(rank(from) + 1) % candidates_.size()];
  return true;
}

std::size_t HoverCycle::rank(std::optional<std::size_t> segment) const {
  if (!segment) return 0;
  const auto it = std::find(candidates_.begin(), candidates_.end(), *segment);
  return it == candidates_.end() ? 0 : static_cast<std::size_t>(it - candidates_.begin());
}

}  // namespace fieldlines::studio
