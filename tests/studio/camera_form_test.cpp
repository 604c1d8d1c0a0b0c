// The Camera tab's Save and Load: the camera file written atomically where the typed path
// points and read back the same; an unwritable path, a missing or bad file, or no camera says
// why and changes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>

#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/camera_file.hpp"
#include "fixtures.hpp"
#include "gui/model/camera_form.hpp"
#include "gui/model/studio_controller.hpp"

namespace fs = fieldlines::studio;
using fieldlines::GroundCamera;

namespace {

struct FormProject {
  FormProject() : dir("camera_form") {
    const auto file = studio_test::write_project(dir.path(), 1, 4);
    fs::ControllerOptions options;
    controller.emplace(fieldlines::Project::load(file), file, options);
    form.update(*controller);
  }
  void type(const std::filesystem::path& path) {
    form.path() = path.string();
    form.resolve();
  }
  studio_test::TempDir dir;
  std::optional<fs::StudioController> controller;
  fs::CameraForm form;
};

}  // namespace

TEST(CameraForm, SavesTheCameraAndLoadsItBack) {
  FormProject p;
  // Beside the folder of images, as the thresholds file: <folder>-camera.json.
  EXPECT_EQ(p.form.target().path, std::filesystem::path(p.dir.path().string() + "-camera.json"));
  p.form.save(*p.controller);
  EXPECT_TRUE(p.form.failed());  // no camera yet
  EXPECT_NE(p.form.message().find("no camera"), std::string::npos) << p.form.message();

  p.form.start_typical(*p.controller);  // the 320x240 picture's typical camera
  ASSERT_FALSE(p.form.failed()) << p.form.message();
  ASSERT_TRUE(p.controller->camera());
  EXPECT_EQ(p.controller->camera()->fx, 320);
  GroundCamera nudged = fs::with_pose(*p.controller->camera(), {31.25, -0.4, 55});
  p.controller->set_camera(nudged);
  p.type("cam.json");  // relative: from the project's folder
  p.form.save(*p.controller);
  ASSERT_FALSE(p.form.failed()) << p.form.message();
  const auto written = p.dir.path() / "cam.json";
  const GroundCamera back = fieldlines::load_camera_file(written);
  EXPECT_NEAR(back.pitch_rad, nudged.pitch_rad, 1e-12);
  EXPECT_NEAR(back.roll_rad, nudged.roll_rad, 1e-12);
  EXPECT_NEAR(back.height_m, 0.55, 1e-12);

  p.controller->set_camera(fs::typical_camera(320, 240));
  p.form.load(*p.controller);
  ASSERT_FALSE(p.form.failed()) << p.form.message();
  EXPECT_NEAR(p.controller->camera()->pitch_rad, nudged.pitch_rad, 1e-12);
}

TEST(CameraForm, AFailedSaveOrLoadSaysWhyAndChangesNothing) {
  FormProject p;
  p.form.start_typical(*p.controller);
  const GroundCamera camera = *p.controller->camera();
  p.type(p.dir.path() / "missing-folder" / "cam.json");
  p.form.save(*p.controller);
  EXPECT_TRUE(p.form.failed());
  EXPECT_NE(p.form.message().find("missing-folder"), std::string::npos) << p.form.message();
  EXPECT_FALSE(std::filesystem::exists(p.dir.path() / "missing-folder"));

  p.form.load(*p.controller);  // no such file
  EXPECT_TRUE(p.form.failed());
  EXPECT_NE(p.form.message().find("cam.json"), std::string::npos) << p.form.message();
  std::ofstream(p.dir.path() / "bad.json") << R"({"format": "fieldlines-camera", "version": 1, "fx": -3})";
  p.type("bad.json");
  p.form.load(*p.controller);
  EXPECT_TRUE(p.form.failed());
  EXPECT_NE(p.form.message().find("bad.json"), std::string::npos) << p.form.message();
  EXPECT_EQ(p.controller->camera()->pitch_rad, camera.pitch_rad);
  EXPECT_EQ(p.controller->camera()->fx, camera.fx);

  p.type("");
  p.form.save(*p.controller);
  EXPECT_TRUE(p.form.failed());
  EXPECT_FALSE(p.form.message().empty());
}

TEST(CameraForm, TheLineWidthAsksTheFitForTheHeight) {
  fs::CameraForm form;
  EXPECT_FALSE(form.fit_params().line_width_m);
  form.line_width_cm = 5;
  ASSERT_TRUE(form.fit_params().line_width_m);
  EXPECT_NEAR(*form.fit_params().line_width_m, 0.05, 1e-12);
}
