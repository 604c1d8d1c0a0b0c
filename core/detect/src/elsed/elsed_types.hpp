#pragma once
// Private: small types shared by the ELSED stages.
#include <cstdint>
#include <vector>

namespace fieldlines::elsed {

struct Pixel {
  int x = 0, y = 0;
  bool operator==(const Pixel&) const = default;
};

// Orientation of the EDGE at a pixel (not of the gradient): a vertical edge has |dx| >= |dy|
// and is drawn by stepping up/down; a horizontal one by stepping left/right.
enum class EdgeDir : std::uint8_t { Vertical = 0, Horizontal = 1 };

enum class Step : std::uint8_t { Left, Right, Up, Down };

constexpr Step opposite(Step s) {
  switch (s) {
    case Step::Left: return Step::Right;
    case Step::Right: return Step::Left;
    case Step::Up: return Step::Down;
    case Step::Down: break;
  }
  return Step::Up;
}

// What the drawing has made of each pixel. Drawing stops on pixels already owned by an edge or a
// segment; validation only counts Inlier pixels.
enum class Mark : std::uint8_t { Free = 0, Edge, Anchor, Inlier, Outlier, Junction };

// One byte per pixel: the edge direction in bit 0, written by the gradient pass, and the Mark in
// bits 1-3, written by the drawing. The walk reads both from one cache line, and the gradient
// pass, which writes every byte, clears the marks of the previous image for free.
using PixelState = std::uint8_t;
constexpr EdgeDir dir_of(PixelState s) { return static_cast<EdgeDir>(s & 1); }
constexpr Mark mark_of(PixelState s) { return static_cast<Mark>(s >> 1); }
constexpr PixelState with_mark(PixelState s, Mark m) {
  return static_cast<PixelState>((s & 1) | (static_cast<unsigned>(m) << 1));
}

// Gradient images of the smoothed grey image, row-major, width*height each.
struct GradientMaps {
  int width = 0, height = 0;
  std::vector<std::int16_t> dx, dy;   // Sobel 3x3
  std::vector<std::int16_t> mag;      // |dx| + |dy|, zero below the gradient threshold
  std::vector<PixelState> state;      // direction (Mark::Free until the drawing marks it)
};

}  // namespace fieldlines::elsed
