// `fieldlines convert` end to end through the built CLI: project <-> reference CSV without
// losing a labelled segment, unlabelled segments counted and skipped, inputs never overwritten,
// bad input named with exit 2.
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_test_support.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/reference_csv.hpp"

namespace fs = std::filesystem;

namespace fieldlines::test {
namespace {

// Every float field identical (for finite floats: equal with the same sign bit) and the label.
::testing::AssertionResult same_segment(const Segment& a, const Segment& b) {
  const float va[] = {a.x0, a.y0, a.x1, a.y1, a.saliency, a.grad_x[0], a.grad_x[1], a.grad_x[2],
                      a.grad_y[0], a.grad_y[1], a.grad_y[2]};
  const float vb[] = {b.x0, b.y0, b.x1, b.y1, b.saliency, b.grad_x[0], b.grad_x[1], b.grad_x[2],
                      b.grad_y[0], b.grad_y[1], b.grad_y[2]};
  for (std::size_t i = 0; i < 11; ++i)
    if (va[i] != vb[i] || std::signbit(va[i]) != std::signbit(vb[i]))
      return ::testing::AssertionFailure() << "field " << i << ": " << va[i] << " != " << vb[i];
  if (a.label != b.label)
    return ::testing::AssertionFailure() << "label " << to_string(a.label) << " != " << to_string(b.label);
  return ::testing::AssertionSuccess();
}

// A project of `images` images with random awkward floats; every 4th segment is unlabelled and
// the last image holds only unlabelled segments.
Project random_project(int images, int per_image, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-300, 700);
  Project p;
  p.detector.gradient_threshold = 31;
  p.thresholds.marking.thresholds.min_length = 42;
  int k = 0;
  for (int i = 0; i < images; ++i) {
    ImageEntry e;
    e.path = i == 1 ? "frames/with, comma \"q\".png" : "frames/" + std::to_string(i) + ".png";
    e.detect_ms = 1.25 * i;
    for (int j = 0; j < per_image; ++j, ++k) {
      Segment s{u(rng), u(rng), u(rng), u(rng), std::abs(u(rng)), {u(rng), u(rng) / 3, u(rng) / 7},
                {u(rng) / 11, u(rng), -0.f}, Label::Unlabelled};
      const Label labels[] = {Label::Marking, Label::Boundary, Label::None, Label::Unlabelled};
      s.label = i == images - 1 ? Label::Unlabelled : labels[k % 4];
      e.segments.push_back(s);
    }
    p.images.push_back(std::move(e));
  }
  return p;
}

class ConvertCli : public TempDirTest {};

TEST_F(ConvertCli, ProjectToCsvToProjectKeepsEveryLabelledSegmentExactly) {
  const Project p = random_project(6, 9, 7);
  const fs::path proj = dir_ / "p.json", csv = dir_ / "labels.csv", back = dir_ / "back" / "p2.json";
  p.save(proj);
  fs::create_directories(back.parent_path());

  CliRun r = run_cli({"convert", proj.string(), "-o", csv.string()}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // 5 labelled images of 9 segments, every 4th unlabelled; the 6th image: 9 unlabelled.
  const std::size_t labelled = p.labelled_count(), unlabelled = 6 * 9 - labelled;
  EXPECT_NE(r.err.find("convert: " + std::to_string(labelled) + " labelled segments from 5 images -> " + csv.string() +
                       "; " + std::to_string(unlabelled) + " unlabelled segments not exported"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(read_reference_csv(csv).size(), labelled);

  r = run_cli({"convert", csv.string(), "--output", back.string()}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("convert: " + std::to_string(labelled) + " labelled and 0 unlabelled segments from 5 images -> "),
            std::string::npos)
      << r.err;
  const Project q = Project::load(back);
  ASSERT_EQ(q.images.size(), 5u);
  std::size_t compared = 0;
  for (std::size_t i = 0; i < q.images.size(); ++i) {
    EXPECT_EQ(q.images[i].path, p.images[i].path);
    std::vector<Segment> want;
    for (const Segment& s : p.images[i].segments)
      if (s.label != Label::Unlabelled) want.push_back(s);
    ASSERT_EQ(q.images[i].segments.size(), want.size()) << i;
    for (std::size_t j = 0; j < want.size(); ++j, ++compared)
      EXPECT_TRUE(same_segment(q.images[i].segments[j], want[j])) << "image " << i << " segment " << j;
  }
  EXPECT_EQ(compared, labelled);
}

TEST_F(ConvertCli, CsvToProjectToCsvIsByteIdentical) {
  const Project p = random_project(5, 12, 3);
  const std::vector<ReferenceRow> rows = reference_rows_from_project(p);
  const fs::path csv = dir_ / "a.csv", proj = dir_ / "a.json", again = dir_ / "again.csv";
  write_reference_csv(csv, rows);
  CliRun r = run_cli({"convert", csv.string(), "-o", proj.string()}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(Project::load(proj).labelled_count(), rows.size());
  r = run_cli({"convert", proj.string(), "-o", again.string()}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(again), read_text(csv));
}

TEST_F(ConvertCli, RealAnnotationFileRoundTripsRowForRow) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl/annotations/D4_humanoid_kid.csv", d4);
  const std::vector<ReferenceRow> rows = read_reference_csv(d4);
  const fs::path proj = dir_ / "d4.json", csv = dir_ / "d4.csv";
  CliRun r = run_cli({"convert", d4.string(), "-o", proj.string()}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_cli({"convert", proj.string(), "-o", csv.string()}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("convert: " + std::to_string(rows.size()) + " labelled segments from "), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("unlabelled"), std::string::npos) << r.err;
  // Rows of one image are contiguous in the authors' files, so the order is kept too.
  const std::vector<ReferenceRow> back = read_reference_csv(csv);
  ASSERT_EQ(back.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(back[i].image, rows[i].image) << i;
    ASSERT_TRUE(same_segment(back[i].segment, rows[i].segment)) << "row " << i + 2;
  }
}

TEST_F(ConvertCli, UnlabelledRowsAreCountedAndSkippedInCsvButKeptInAProject) {
  std::vector<ReferenceRow> rows;
  for (int i = 0; i < 7; ++i) {
    ReferenceRow r;
    r.image = i < 4 ? "a.png" : "b.png";
    r.segment = Segment{float(i), 1, float(i) + 10, 2, 20, {1, 2, 3}, {4, 5, 6}, Label::Unlabelled};
    if (i == 1) r.segment.label = Label::Marking;
    if (i == 2) r.segment.label = Label::None;
    rows.push_back(r);
  }
  const fs::path in = dir_ / "some_unlabelled.csv";
  write_reference_csv(in, rows);  // unlabelled rows are written with all three columns False
  ASSERT_EQ(read_reference_csv(in).size(), 7u);

  CliRun r = run_cli({"convert", in.string(), "-o", (dir_ / "out.csv").string()}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("2 labelled segments from 1 image"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("; 5 unlabelled segments not exported"), std::string::npos) << r.err;
  const std::vector<ReferenceRow> out = read_reference_csv(dir_ / "out.csv");
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].segment.label, Label::Marking);
  EXPECT_EQ(out[1].segment.label, Label::None);

  r = run_cli({"convert", in.string(), "-o", (dir_ / "out.json").string(), "--quiet"}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const Project p = Project::load(dir_ / "out.json");
  ASSERT_EQ(p.images.size(), 2u);
  EXPECT_EQ(p.images[0].segments.size() + p.images[1].segments.size(), 7u);
  EXPECT_EQ(p.labelled_count(), 2u);
}

TEST_F(ConvertCli, RefusesToWriteOverItsInputOrAFileOfAnotherKind) {
  const Project p = random_project(3, 4, 1);
  const fs::path proj = dir_ / "p.json", csv = dir_ / "p.csv";
  p.save(proj);
  write_reference_csv(csv, reference_rows_from_project(p));
  const std::string proj_bytes = read_text(proj), csv_bytes = read_text(csv);

  // The same file, also under another spelling.
  for (const fs::path& out : {csv, dir_ / "." / "p.csv"}) {
    const CliRun r = run_cli({"convert", csv.string(), "-o", out.string()}, dir_);
    EXPECT_EQ(r.exit_code, 2) << out;
    EXPECT_NE(r.err.find("fieldlines convert: error: -o " + out.string() + ": is also an input file"), std::string::npos)
        << r.err;
  }
  CliRun r = run_cli({"convert", proj.string(), "-o", proj.string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is also an input file"), std::string::npos) << r.err;

  // An existing OUT of the wrong kind (here: a thresholds-like JSON, a text file) is kept.
  const fs::path notes = write_bytes("notes.csv", "my notes, not labels\n");
  const fs::path thr = write_bytes("robot.json", "{\"format\": \"fieldlines-thresholds\"}\n");
  r = run_cli({"convert", proj.string(), "-o", notes.string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("refusing to overwrite -o " + notes.string() + ", it is not a reference CSV"), std::string::npos)
      << r.err;
  r = run_cli({"convert", csv.string(), "-o", thr.string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("refusing to overwrite -o " + thr.string() + ", it is not a project file"), std::string::npos)
      << r.err;
  EXPECT_EQ(read_text(notes), "my notes, not labels\n");
  EXPECT_EQ(read_text(thr), "{\"format\": \"fieldlines-thresholds\"}\n");
  EXPECT_EQ(read_text(proj), proj_bytes);
  EXPECT_EQ(read_text(csv), csv_bytes);

  // An existing file of the right kind is replaced.
  r = run_cli({"convert", proj.string(), "-o", (dir_ / "copy.csv").string()}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_cli({"convert", csv.string(), "-o", (dir_ / "copy.csv").string()}, dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST_F(ConvertCli, MalformedInputExitsWith2AndNamesTheFile) {
  const Project p = random_project(2, 3, 5);
  const fs::path good = dir_ / "good.csv";
  write_reference_csv(good, reference_rows_from_project(p));
  const std::size_t lines = reference_rows_from_project(p).size() + 1;
  const fs::path bad_csv =
      write_bytes("bad.csv", read_text(good) + "x.png,1,2,3,4,5,6,7,8,9,10,NaN,True,False,False\n");
  const fs::path out = dir_ / "out.json";
  CliRun r = run_cli({"convert", bad_csv.string(), "-o", out.string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("fieldlines convert: error: " + bad_csv.string() + ":" + std::to_string(lines + 1) +
                       ": column 'segment_length': value must be finite"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out));

  const fs::path bad_json = write_bytes("bad.json", "{\"format\": \"fieldlines-project\", \"version\": 1,");
  r = run_cli({"convert", bad_json.string(), "-o", (dir_ / "out.csv").string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("fieldlines convert: error: " + bad_json.string() + ": damaged project file"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.csv"));

  r = run_cli({"convert", (dir_ / "none.csv").string(), "-o", (dir_ / "out.csv").string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("none.csv' is not a file"), std::string::npos) << r.err;
}

TEST_F(ConvertCli, UsageErrorsAreCheckedBeforeReading) {
  const fs::path csv = dir_ / "a.csv";
  write_reference_csv(csv, reference_rows_from_project(random_project(2, 2, 9)));
  fs::create_directories(dir_ / "folder.json");
  const struct {
    std::vector<std::string> args;
    std::string message;
  } cases[] = {
      {{"convert", csv.string()}, "missing -o OUT"},
      {{"convert", "-o", (dir_ / "o.csv").string()}, "no DATA given"},
      {{"convert", csv.string(), csv.string(), "-o", (dir_ / "o.csv").string()}, "expected one DATA file, got 2"},
      {{"convert", csv.string(), "-o", (dir_ / "o.txt").string()}, "expected a name ending in .csv"},
      {{"convert", csv.string(), "-o", (dir_ / "nowhere" / "o.csv").string()}, "does not exist"},
      {{"convert", csv.string(), "-o", (dir_ / "folder.json").string()}, "is a folder"},
      {{"convert", csv.string(), "--frobnicate", "-o", (dir_ / "o.csv").string()}, "--frobnicate"},
  };
  for (const auto& c : cases) {
    const CliRun r = run_cli(c.args, dir_);
    EXPECT_EQ(r.exit_code, 2) << c.message;
    EXPECT_NE(r.err.find("fieldlines convert: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
  // The output folder is checked before a malformed DATA is read.
  const fs::path bad = write_bytes("bad.csv", "nonsense\n");
  const CliRun r = run_cli({"convert", bad.string(), "-o", (dir_ / "nowhere" / "o.csv").string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("folder"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "o.csv"));
}

}  // namespace
}  // namespace fieldlines::test
