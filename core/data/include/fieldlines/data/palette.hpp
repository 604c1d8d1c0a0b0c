#pragma once
// The one palette of segment overlays, shared by the studio (gui/model/overlay_style) and the
// CLI's `--draw` (fieldlines/data/overlay.hpp), so a picture means the same in both.
//
// Every segment is drawn in its colour over a dark outline (kOutline, kOutlineExtra px wider).
// Legibility, as CIE76 Delta-E (sRGB D65), checked by tests/studio/overlay_style_test.cpp against
// turf greens (50,140,40) (90,180,60) (30,90,40) (130,200,90), white paint and dark walls
// (30,30,30) (60,55,50):
//  - the colour alone: marking, boundary and unlabelled >= 85 from every one of them (measured
//    minimum 86.5, boundary on (60,55,50)); none >= 55 (58.3 on the bleached turf): an agreed
//    non-feature need not shout;
//  - the colour against its own outline >= 90 (92.7, boundary), so it reads inside the outline
//    where the outline melts into the background (dark walls: 8.5 from (30,30,30));
//  - colour and outline together (the larger of the two differences) >= 75 on every background
//    (measured 79.95, "none" on the SSL carpet): the outline carries "none" on the bright turfs,
//    where its yellow alone is 58-64 and the outline 95.
#include <cstdint>

#include "fieldlines/detect/segment.hpp"

namespace fieldlines::palette {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

inline constexpr Rgb kMarking{255, 40, 200};    // magenta
inline constexpr Rgb kBoundary{30, 120, 255};   // blue
inline constexpr Rgb kNone{255, 210, 0};        // yellow
inline constexpr Rgb kUnlabelled{255, 70, 20};  // vermilion: still to do, must stand out on turf
inline constexpr Rgb kQuiet{150, 150, 150};     // grey (the studio's agreed "not a feature")
inline constexpr Rgb kOutline{10, 10, 10};      // under every segment
// Paint the detector found no segment for (fieldlines/data/missed_paint.hpp), tinted in the
// picture itself: a hue no label uses, far from turf (Delta-E ~69) and visible on white (~51).
inline constexpr Rgb kMissedPaint{0, 255, 255};  // cyan
inline constexpr Rgb kFieldBoundary{255, 255, 255};  // white over the outline: where the green ends
inline constexpr Rgb kFeature{255, 150, 0};     // orange: centre lines, junctions, the circle (detect --draw)
// The truth's line edges in `eval --draw`: found (a segment of their class lies on them, as
// recall counts), lost (only a segment of another label does: the classification dropped them)
// and missed (no segment: kMissedPaint, as in the studio); the hand-drawn field boundary found's.
inline constexpr Rgb kTruthFound{0, 255, 0};    // green
inline constexpr Rgb kTruthLost{255, 0, 0};     // red
// Segments above the field boundary (stands, walls, lights) are drawn at this opacity, so what
// lies on the field reads first (detect --draw unless --draw-all, the studio unless asked).
inline constexpr double kAboveFieldOpacity = 0.3;
inline constexpr float kOutlineExtra = 3;       // outline width = line width + this, pixels
// A junction's marker for lines `thickness` px wide: a ring of this radius, and a tick per ray
// from the ring out to the tick length; clear of the lines that meet there.
constexpr double junction_ring_radius(double thickness) { return 2 * thickness + 4; }
constexpr double junction_tick_length(double thickness) { return 6 * thickness + 12; }

constexpr Rgb label_rgb(Label label) {
  switch (label) {
    case Label::Marking: return kMarking;
    case Label::Boundary: return kBoundary;
    case Label::None: return kNone;
    case Label::Unlabelled: break;
  }
  return kUnlabelled;
}

// What each class is, by the colour transition the classifier looks for (legends of both faces).
// ASCII arrows: ImGui's default font has no arrow glyphs, OpenCV's Hershey fonts neither.
constexpr const char* label_transition(Label label) {
  switch (label) {
    case Label::Marking: return "green <-> white paint";
    case Label::Boundary: return "green -> black (field edge)";
    case Label::None: return "anything else";
    case Label::Unlabelled: break;
  }
  return "not labelled yet";
}

}  // namespace fieldlines::palette
