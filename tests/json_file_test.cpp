// The one format/version check of our JSON files: exact messages for every way a header fails.
#include <string>

#include <gtest/gtest.h>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/json_file.hpp"

namespace fl = fieldlines;
using nlohmann::json;

namespace {

constexpr fl::JsonFileFormat kKept{"format", "fieldlines-project", "project file", "project", 2,
                                   fl::JsonFileFormat::Newer::NotModified};
constexpr fl::JsonFileFormat kRead{"schema", "fieldlines-synth-truth", "synthetic ground truth", "ground-truth", 2,
                                   fl::JsonFileFormat::Newer::UpdateFieldlines};

std::string error_of(const json& j, const fl::JsonFileFormat& f) {
  try {
    fl::require_json_file_format(j, f, "f.json");
  } catch (const fl::Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(JsonFile, AcceptsVersionsOneToCurrentAndWritesTheHeaderItChecks) {
  EXPECT_EQ(fl::json_file_header(kKept), json({{"format", "fieldlines-project"}, {"version", 2}}));
  EXPECT_EQ(fl::require_json_file_format(fl::json_file_header(kKept), kKept, "f.json"), 2);
  EXPECT_EQ(fl::require_json_file_format(json({{"schema", "fieldlines-synth-truth"}, {"version", 1}}), kRead, "f.json"),
            1);
}

TEST(JsonFile, NamesTheFileAndWhatIsWrong) {
  const std::string not_kept = R"(f.json: not a fieldlines project file ("format" must be "fieldlines-project"))";
  EXPECT_EQ(error_of(json::array(), kKept), not_kept);
  EXPECT_EQ(error_of(json::object(), kKept), not_kept);
  EXPECT_EQ(error_of({{"format", 5}, {"version", 1}}, kKept), not_kept);  // a wrong type is no crash
  EXPECT_EQ(error_of({{"format", "fieldlines-thresholds"}, {"version", 1}}, kKept), not_kept);
  EXPECT_EQ(error_of({{"format", "fieldlines-project"}, {"version", 1}}, kRead),
            R"(f.json: not a fieldlines synthetic ground truth ("schema" must be "fieldlines-synth-truth"))");
  EXPECT_EQ(error_of({{"format", "fieldlines-project"}}, kKept), R"(f.json: missing integer "version")");
  EXPECT_EQ(error_of({{"format", "fieldlines-project"}, {"version", 1.5}}, kKept), R"(f.json: missing integer "version")");
  EXPECT_EQ(error_of({{"format", "fieldlines-project"}, {"version", 0}}, kKept), "f.json: invalid project version 0");
  EXPECT_EQ(error_of({{"format", "fieldlines-project"}, {"version", 3}}, kKept),
            "f.json: project version 3 was written by a newer fieldlines (this one reads up to 2); it will not be "
            "modified");
  EXPECT_EQ(error_of({{"schema", "fieldlines-synth-truth"}, {"version", 3}}, kRead),
            "f.json: ground-truth version 3 is newer than this fieldlines understands (2); update fieldlines");
}
