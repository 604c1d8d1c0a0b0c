#pragma once
// Private: orientations (angles modulo pi) as ELSED compares them.
#include <algorithm>
#include <cmath>
#include <numbers>

namespace fieldlines::elsed {

inline double wrap_half_turn(double a) {
  constexpr double pi = std::numbers::pi;
  while (a < 0) a += pi;
  while (a >= pi) a -= pi;
  return a;
}

// Distance between two orientations in [0, pi).
inline double orientation_distance(double a, double b) {
  const double d = std::abs(a - b);
  return std::min(d, std::numbers::pi - d);
}

}  // namespace fieldlines::elsed
