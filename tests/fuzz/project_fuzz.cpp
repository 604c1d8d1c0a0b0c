// Fuzzes the labelling-project reader; what it accepts must save and load back with the same
// images and labels.
#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/error.hpp"
#include "fuzz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto in = fieldlines::fuzz::write_input("project-in.json", data, size);
  try {
    const auto project = fieldlines::Project::load(in);
    const auto out = fieldlines::fuzz::write_input("project-out.json", nullptr, 0);
    std::filesystem::remove(out);
    project.save(out);
    const auto again = fieldlines::Project::load(out);
    if (again.images.size() != project.images.size() || again.labelled_count() != project.labelled_count())
      __builtin_trap();
  } catch (const fieldlines::Error&) {
  }
  return 0;
}
