#pragma once
// Private: how the edge drawer moves from pixel to pixel.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "elsed_types.hpp"

namespace fieldlines::elsed {

// Follows the ridge of the gradient magnitude one pixel. Along the edge it checks the three
// pixels ahead (straight or either diagonal) and takes the strongest; when the edge has just
// turned (the previous step was across the edge's direction) it checks the two diagonals.
// `last` is the previous pixel on entry and becomes `px`'s old value. Returns false at the image
// border or when the new pixel has no gradient.
//
// With `request_state`, the cache lines of g.state, which the caller reads at the new pixel
// next, are requested with the magnitudes' at each candidate, not after the choice (the walk is
// bound by memory latency, one dependent step after another).
inline bool step_along_gradient(EdgeDir dir, const GradientMaps& g, Pixel& px, Pixel& last,
                                bool request_state = false) {
  // The four cases (along or turning, horizontal or vertical edge) are one: a step of one pixel
  // on one axis, then a choice among the pixels beside on the other. Written as one path of
  // selects rather than branches: the choices depend on the data and would be mispredicted,
  // delaying the next step's loads.
  const int w = g.width, h = g.height;
  const std::int16_t* m = g.mag.data();
  const Pixel prev = last;
  last = px;
  const bool horizontal = dir == EdgeDir::Horizontal;
  const bool three = horizontal ? prev.x != px.x : prev.y != px.y;  // along: three candidates
  const bool step_x = horizontal == three;
  int a = step_x ? px.x : px.y;
  const int c = step_x ? px.y : px.x, pa = step_x ? prev.x : prev.y;
  const int na = step_x ? w : h, nc = step_x ? h : w;
  const int s = pa < a ? 1 : -1;
  if ((s > 0 ? a == na - 1 : a == 0) || c == 0 || c == nc - 1) return false;
  a += s;
  const int cross = step_x ? w : 1;  // index step to the pixel beside
  const int i = step_x ? c * w + a : a * w + c;
  if (request_state) {
    __builtin_prefetch(g.state.data() + i - cross);
    __builtin_prefetch(g.state.data() + i);
    __builtin_prefetch(g.state.data() + i + cross);
  }
  const int lo = m[i - cross], mid = m[i], hi = m[i + cross];
  // Along: the strictly strongest of the three, the middle one on ties. Turning: the stronger
  // diagonal, the +1 one on ties.
  const int off = three ? static_cast<int>(hi > mid && hi > lo) - static_cast<int>(lo > mid && lo > hi)
                        : (lo > hi ? -1 : 1);
  const int nc_new = c + off;
  px = step_x ? Pixel{a, nc_new} : Pixel{nc_new, a};
  return m[i + off * cross] != 0;
}

// The pixel one step behind `px` when starting to draw in direction `s`.
inline Pixel pixel_behind(Pixel px, Step s) {
  switch (s) {
    case Step::Up: return {px.x, px.y + 1};
    case Step::Down: return {px.x, px.y - 1};
    case Step::Left: return {px.x + 1, px.y};
    case Step::Right: break;
  }
  return {px.x - 1, px.y};
}

// The dominant drawing direction of a line a x + b y + c = 0 oriented along (-b, a).
inline Step step_of_line(const std::array<double, 3>& eq) {
  const double lx = -eq[1], ly = eq[0];
  if (std::abs(lx) > std::abs(ly)) return lx > 0 ? Step::Right : Step::Left;
  return ly > 0 ? Step::Down : Step::Up;
}

// Jumps `step` pixels along the line from the projection of `px` on it (backwards when
// `backwards`), then snaps to the strongest of the 2x2 pixels there. Returns false outside the
// image or on a pixel without gradient.
inline bool jump_along_line(const GradientMaps& g, const std::array<double, 3>& eq_d, bool backwards,
                            int step, Pixel& px) {
  const int w = g.width, h = g.height;
  const float a = static_cast<float>(eq_d[0]), b = static_cast<float>(eq_d[1]), c = static_cast<float>(eq_d[2]);
  // Foot of the perpendicular from px, as the intersection of the line with its normal through px.
  float fx = static_cast<float>(px.x), fy = static_cast<float>(px.y);
  if (a * fx + b * fy + c != 0.f) {
    const float r0 = b, r1 = -a, r2 = a * fy - b * fx;  // the normal line through px
    const float hx = b * r2 - c * r1, hy = c * r0 - a * r2, hz = a * r1 - b * r0;
    fx = hx / hz;
    fy = hy / hz;
  }
  const float sign = backwards ? -1.f : 1.f;
  const float ex = fx - sign * step * b, ey = fy + sign * step * a;
  if (!(ex >= 0 && ex < w && ey >= 0 && ey < h)) return false;
  const int x = static_cast<int>(ex), y = static_cast<int>(ey);
  const int x1 = std::min(x + 1, w - 1), y1 = std::min(y + 1, h - 1);
  const std::int16_t* m = g.mag.data();
  const int g1 = m[y * w + x], g2 = m[y * w + x1], g3 = m[y1 * w + x], g4 = m[y1 * w + x1];
  // Ties favour, in order: the top-left, then the top-right / bottom-left, the bottom-right last.
  int best = g1;
  Pixel pick{x, y};
  if (g2 > g1) best = g2, pick = {x1, y};
  if (g3 > best) best = g3, pick = {x, y1};
  if (g4 > best) best = g4, pick = {x1, y1};
  px = pick;
  return best != 0;
}

// The pixels of the digital line from a to b, both included (Bresenham), appended to `out`.
inline void line_pixels(Pixel a, Pixel b, std::vector<Pixel>& out) {
  int dx = b.x - a.x, dy = b.y - a.y;
  const int sx = dx < 0 ? -1 : 1, sy = dy < 0 ? -1 : 1;
  dx = std::abs(dx);
  dy = std::abs(dy);
  int x = a.x, y = a.y;
  if (dx >= dy) {
    int err = 2 * dy - dx;
    for (; x != b.x; x += sx) {
      out.push_back({x, y});
      if (err >= 0) y += sy, err += 2 * (dy - dx);
      else err += 2 * dy;
    }
  } else {
    int err = 2 * dx - dy;
    for (; y != b.y; y += sy) {
      out.push_back({x, y});
      if (err >= 0) x += sx, err += 2 * (dx - dy);
      else err += 2 * dx;
    }
  }
  out.push_back(b);
}

}  // namespace fieldlines::elsed
