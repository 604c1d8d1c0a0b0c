#pragma once
// What counts as the field's green in a pixel: one rule for the light adaptation's field colour
// and the field boundary. Green above red and blue by `dominance`, and not too dark to say.
#include <cstdint>

namespace fieldlines {

struct FieldGreen {
  float dominance = 1.05f;  // green must exceed red and blue by this factor
  int min_green = 20;       // darker pixels say nothing
  bool operator()(std::uint8_t b, std::uint8_t g, std::uint8_t r) const {
    return g >= min_green && g >= dominance * r && g >= dominance * b;
  }
};

}  // namespace fieldlines
