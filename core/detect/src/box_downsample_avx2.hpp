#pragma once
// Private: box_downsample's cells of 3 x 3 pixels in AVX2, chosen at run time on x86-64 CPUs that
// have it (elsed::avx2::wanted()); elsewhere it does nothing and the portable kernel runs. Same
// bits: each cell's rounded mean.
#include <cstdint>

namespace fieldlines::avx2 {

// One output row from the three input rows of its cells (8-bit BGR): the number of leading
// output pixels it wrote (whole blocks of 64, at most w); the caller finishes the row.
int cells3_row(const std::uint8_t* r0, const std::uint8_t* r1, const std::uint8_t* r2, int w, std::uint8_t* out);

}  // namespace fieldlines::avx2
