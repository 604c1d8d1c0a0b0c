#pragma once
// Private: the thin-line pass's ridge rows (ridge_pass.cpp) in AVX2 (32 columns at a time),
// chosen at run time on x86-64 CPUs that have it (gradient_rows_avx2.hpp's available());
// everywhere else it does nothing and ridge_pass.cpp's universal-intrinsics kernel (SSE2 / NEON)
// runs. Same arithmetic, same bits (tests/thin_pass_test.cpp compares what they draw).
#include <cstddef>
#include <cstdint>

namespace fieldlines::elsed {

// One row of the ridge maps being written, and the list of the blocks written (each at most
// kRidgeBlock px from its start, within the row), which the next frame clears.
struct RidgeRow {
  std::int16_t *dx, *dy, *mag;
  std::uint8_t* state;
  std::uint32_t first;       // the row's first pixel's index in the maps
  std::uint32_t* blocks;     // room for every block of the row
  std::size_t* block_count;  // blocks written so far
};
inline constexpr int kRidgeBlock = 16;
// The diagonal steps that set dy's sign for lines up to 2 R - 1 px wide: R / sqrt(2), at least 1.
template <int R>
inline constexpr int kRidgeDiagonal = R * 7 / 10 > 1 ? R * 7 / 10 : 1;

}  // namespace fieldlines::elsed

namespace fieldlines::elsed::avx2 {

// Columns [x0, x1) of a row, from 2 reach + 1 rows of the smoothed grey (`rows[reach]` the row
// itself, rows[reach - d] and rows[reach + d] d rows above and below), for lines up to
// 2 reach - 1 px wide (reach 1..8), kept at `threshold` (1..32767), 32 columns at a time: each
// block of 16 columns whose ridges' byte sum reaches `least` somewhere (ridge_pass.cpp) is written
// whole (zeros where none is kept) and listed. Returns x1, or x0 when the row is shorter than 32
// columns (the caller does it).
int ridge_row(const std::uint8_t* const* rows, int reach, int x0, int x1, int threshold, int least, const RidgeRow& out);

}  // namespace fieldlines::elsed::avx2
