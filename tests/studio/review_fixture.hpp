#pragma once
// A project of three images sharing the known synthetic features (tests/known_features.hpp),
// all unlabelled, with the true labels kept aside: what the review-loop tests label from.
#include <optional>
#include <string>
#include <vector>

#include "fieldlines/data/project.hpp"
#include "fixtures.hpp"
#include "gui/model/studio_controller.hpp"
#include "tests/known_features.hpp"

namespace studio_test {

struct ReviewProject {
  explicit ReviewProject(fieldlines::studio::ControllerOptions options = {}) : dir("review") {
    const fieldlines::test::KnownField k = fieldlines::test::known_field(9);
    fieldlines::Project p;
    for (int img = 0; img < 3; ++img) p.images.push_back({"img" + std::to_string(img) + ".png", {}, 1.0, {}});
    for (std::size_t i = 0; i < k.segments.size(); ++i) {
      fieldlines::Segment s = k.segments[i];
      truth.push_back(s.label);
      s.label = fieldlines::Label::Unlabelled;
      p.images[i % 3].segments.push_back(s);
    }
    file = dir.path() / "project.json";
    p.save(file);
    options.load_pixels = false;
    controller.emplace(fieldlines::Project::load(file), file, options);
  }
  fieldlines::Label true_label(std::size_t image, std::size_t segment) const { return truth[segment * 3 + image]; }
  TempDir dir;
  std::filesystem::path file;
  std::vector<fieldlines::Label> truth;
  std::optional<fieldlines::studio::StudioController> controller;
};

}  // namespace studio_test
