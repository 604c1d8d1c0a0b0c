// Fuzzes the robot's thresholds-file loader; what it accepts must save and load back equal.
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "fuzz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto in = fieldlines::fuzz::write_input("thresholds-in.json", data, size);
  try {
    const auto file = fieldlines::load_thresholds_file(in);
    const auto out = fieldlines::fuzz::write_input("thresholds-out.json", nullptr, 0);
    std::filesystem::remove(out);
    fieldlines::save_thresholds_file(out, file);
    const auto again = fieldlines::load_thresholds_file(out);
    if (!(again.thresholds == file.thresholds) || !(again.detector == file.detector)) __builtin_trap();
  } catch (const fieldlines::Error&) {
  }
  return 0;
}
