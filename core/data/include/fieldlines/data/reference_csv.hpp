#pragma once
// The reference implementation's annotation CSV (../shared/data/README.md).
//
// Columns: img_path,x0,y0,x1,y1,grad_Bx,grad_Gx,grad_Rx,grad_By,grad_Gy,grad_Ry,segment_length
// and optionally is_field_boundary,is_field_marking,is_not_a_field_feature. The file stores
// channels B,G,R and grad_y as row-above minus row-below; this is the ONLY place converting
// to our R,G,B, image-down convention.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

struct ReferenceRow {
  std::string image;  // img_path as written in the file (the image need not exist)
  Segment segment;    // segment.label: Unlabelled when the file has no label columns / no True
};

// Throws fieldlines::Error "file:line: ..." on a malformed row (missing columns, non-numbers,
// NaN/inf, bad booleans, several True) or a header without the required columns.
std::vector<ReferenceRow> read_reference_csv(const std::filesystem::path& path);
// Atomic. Always writes the three label columns (all False for an unlabelled segment). Floats
// are written with enough digits to read back bit for bit.
void write_reference_csv(const std::filesystem::path& path, std::span<const ReferenceRow> rows);

// True when the file starts with the reference header (used to tell a CSV from a project file).
bool looks_like_reference_csv(const std::filesystem::path& path);

}  // namespace fieldlines
