#pragma once
// Which of the segments under the cursor is the hovered one. Overlapping segments (the two edges
// of a painted line can lie within a pixel) are all reachable: Space cycles through them, and
// after one of them is labelled the hover moves on to the next unlabelled one, so a second key
// press never silently re-labels the same segment.
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "fieldlines/detect/segment.hpp"

namespace fieldlines::studio {

class HoverCycle {
 public:
  // Once per frame: `under` = the segments under the cursor, nearest first (segments_under), on
  // image `image` whose segments are `segments` (for their labels). Returns the hovered one:
  // the nearest, unless Space or a label picked another of the same set. A different set (the
  // cursor moved on, or another image) starts again from the nearest. If the hovered segment was
  // given a label since the last update (not cleared) and the set is the same, the hover moves
  // to the next unlabelled segment of the set (in cycling order), when there is one.
  std::optional<std::size_t> update(std::size_t image, std::span<const std::size_t> under,
                                    std::span<const Segment> segments);
  // Space: the next segment of the set (by distance, wrapping), hovered from the next update.
  // Nothing with fewer than two (returns false).
  bool next();

  std::optional<std::size_t> hovered() const { return hovered_; }
  std::span<const std::size_t> candidates() const { return candidates_; }
  // 0-based rank of the hovered segment among the candidates (0 when none).
  std::size_t position() const { return rank(hovered_); }

 private:
  std::size_t rank(std::optional<std::size_t> segment) const;

  std::size_t image_ = 0;
  std::vector<std::size_t> candidates_;  // nearest first, as last given
  std::vector<std::size_t> previous_;    // the update before's, to tell a new set
  std::optional<std::size_t> pinned_;    // chosen by next() or a label; kept while the set is
  std::optional<std::size_t> hovered_;
  Label hovered_label_ = Label::Unlabelled;  // its label at the last update
};

}  // namespace fieldlines::studio
