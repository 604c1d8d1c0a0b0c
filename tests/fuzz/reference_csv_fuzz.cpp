// Fuzzes the reference annotation CSV reader; whatever it accepts must survive a write/read
// round trip unchanged.
#include <filesystem>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "fuzz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto in = fieldlines::fuzz::write_input("csv-in.csv", data, size);
  try {
    const auto rows = fieldlines::read_reference_csv(in);
    const auto out = fieldlines::fuzz::write_input("csv-out.csv", nullptr, 0);
    fieldlines::write_reference_csv(out, rows);
    const auto again = fieldlines::read_reference_csv(out);
    if (again.size() != rows.size()) __builtin_trap();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto& a = rows[i].segment;
      const auto& b = again[i].segment;
      if (rows[i].image != again[i].image || a.x0 != b.x0 || a.saliency != b.saliency || a.label != b.label ||
          a.grad_y != b.grad_y)
        __builtin_trap();
    }
  } catch (const fieldlines::Error&) {
  }
  return 0;
}
