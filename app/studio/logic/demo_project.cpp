#include "demo_project.hpp"

#include <cstdlib>
#include <system_error>

#include "fieldlines/error.hpp"
#include "fieldlines/image_io.hpp"
#include "fieldlines/synth.hpp"

namespace fieldlines::studio {

std::filesystem::path default_demo_folder() {
  if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "fieldlines" / "demo";
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".local" / "share" / "fieldlines" / "demo";
  }
  throw Error("cannot place the demo project: neither XDG_DATA_HOME nor HOME is set");
}

std::filesystem::path ensure_demo_images(const std::filesystem::path& folder, int images) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) throw Error(folder.string() + ": cannot create the demo folder (" + ec.message() + ")");
  if (!list_images(folder).empty()) return folder;
  synth::SynthParams params;  // the default SSL field under artificial light
  for (int i = 0; i < images; ++i) synth::write_sample(synth::generate(params, /*seed*/ 2024, i), folder);
  return folder;
}

}  // namespace fieldlines::studio
