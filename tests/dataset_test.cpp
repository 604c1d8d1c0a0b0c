// Project files (atomic, versioned, never overwriting what they cannot read), label
// re-attachment after re-detection, and the undo/redo command stack.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/data/data_file.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/label_commands.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "shared_data.hpp"

namespace fl = fieldlines;
namespace fs = std::filesystem;

namespace {

fl::Segment seg(float x0, float y0, float x1, float y1, fl::Label label = fl::Label::Unlabelled) {
  fl::Segment s{x0, y0, x1, y1, std::hypot(x1 - x0, y1 - y0), {1.5f, -2.f, 3.f}, {-4.f, 5.25f, 6.f}, label};
  return s;
}

fl::Project sample() {
  fl::Project p;
  p.detector.gradient_threshold = 25;
  p.thresholds.marking.thresholds.min_length = 77;
  p.images.push_back({"frames/a.png", {seg(0, 0, 100, 0, fl::Label::Marking), seg(0, 50, 0, 150)}, 4.5});
  p.images.push_back({"frames/b.png", {seg(10, 10, 200, 20, fl::Label::None)}, 2});
  return p;
}

class ProjectFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fl_project_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

std::string error_of(auto&& f) {
  try {
    f();
  } catch (const fl::Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_F(ProjectFiles, SaveLoadRoundTrip) {
  const fl::Project p = sample();
  const fs::path file = dir_ / "labels.json";
  p.save(file);
  const fl::Project q = fl::Project::load(file);
  EXPECT_EQ(q.detector, p.detector);
  EXPECT_EQ(q.thresholds, p.thresholds);
  ASSERT_EQ(q.images.size(), 2u);
  EXPECT_EQ(q.images[0].path, "frames/a.png");
  EXPECT_DOUBLE_EQ(q.images[0].detect_ms, 4.5);
  ASSERT_EQ(q.images[0].segments.size(), 2u);
  EXPECT_EQ(q.images[0].segments[0].label, fl::Label::Marking);
  EXPECT_EQ(q.images[0].segments[1].label, fl::Label::Unlabelled);
  EXPECT_EQ(q.images[0].segments[0].grad_y, p.images[0].segments[0].grad_y);
  EXPECT_EQ(q.labelled_count(), 2u);
  EXPECT_EQ(q.labelled().size(), 2u);
  EXPECT_EQ(fl::Project::resolve(file, "frames/a.png"), dir_ / "frames/a.png");
}

TEST_F(ProjectFiles, DamagedOrNewerFilesGiveClearErrorsAndAreNeverOverwritten) {
  const fs::path file = dir_ / "labels.json";
  sample().save(file);
  std::string text = fl::read_file(file);
  // Truncated (e.g. a crash in another tool): load fails, save refuses.
  std::ofstream(file, std::ios::trunc) << text.substr(0, text.size() / 2);
  const std::string damaged = fl::read_file(file);
  EXPECT_NE(error_of([&] { fl::Project::load(file); }).find("damaged"), std::string::npos);
  EXPECT_NE(error_of([&] { sample().save(file); }).find("refusing to overwrite"), std::string::npos);
  EXPECT_EQ(fl::read_file(file), damaged);
  // Newer version.
  const std::size_t at = text.find("\"version\": 1");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 12, "\"version\": 9");
  std::ofstream(file, std::ios::trunc) << text;
  EXPECT_NE(error_of([&] { fl::Project::load(file); }).find("newer"), std::string::npos);
  EXPECT_NE(error_of([&] { sample().save(file); }).find("refusing"), std::string::npos);
  EXPECT_EQ(fl::read_file(file), text);
  // A bad label names the segment.
  text.replace(at, 12, "\"version\": 1");
  text.replace(text.find("\"marking\"\n"), 9, "\"maybe\"  ");  // a segment label, not the class key
  std::ofstream(file, std::ios::trunc) << text;
  EXPECT_NE(error_of([&] { fl::Project::load(file); }).find("images[0].segments[0]"), std::string::npos);
}

TEST(Reattach, KeepsLabelsOfMatchingSegmentsAndCountsTheLost) {
  const std::vector<fl::Segment> old = {seg(0, 0, 100, 0, fl::Label::Marking),
                                        seg(0, 50, 0, 150, fl::Label::Boundary),
                                        seg(300, 300, 400, 400, fl::Label::None), seg(500, 0, 600, 0)};
  std::vector<fl::Segment> fresh = {
      seg(2, 1, 98, 1.5f),         // same line, slightly moved: keeps marking
      seg(0.5f, 60, 1, 100),       // a piece of the vertical one: boundary
      seg(0.5f, 100, 1, 150),      // the other piece: boundary
      seg(300, 300, 400, 330),     // same start, very different angle: not a match
      seg(500, 0, 600, 0)};        // matches only an unlabelled one
  const fl::ReattachStats st = fl::reattach_labels(old, fresh);
  EXPECT_EQ(fresh[0].label, fl::Label::Marking);
  EXPECT_EQ(fresh[1].label, fl::Label::Boundary);
  EXPECT_EQ(fresh[2].label, fl::Label::Boundary);
  EXPECT_EQ(fresh[3].label, fl::Label::Unlabelled);
  EXPECT_EQ(fresh[4].label, fl::Label::Unlabelled);
  EXPECT_EQ(st.labelled_before, 3u);
  EXPECT_EQ(st.kept, 2u);
  EXPECT_EQ(st.lost, 1u);
  EXPECT_EQ(st.labelled_after, 3u);
  // A parallel line 10 px away is another line.
  std::vector<fl::Segment> shifted = {seg(0, 10, 100, 10)};
  EXPECT_EQ(fl::reattach_labels(old, shifted).lost, 3u);
  EXPECT_EQ(shifted[0].label, fl::Label::Unlabelled);

  fl::Project p = sample();
  const fl::ReattachStats pst = p.replace_segments(0, {seg(1, 0, 90, 0)});
  EXPECT_EQ(pst.kept, 1u);
  EXPECT_EQ(p.images[0].segments.size(), 1u);
  EXPECT_EQ(p.images[0].segments[0].label, fl::Label::Marking);
  EXPECT_THROW(p.replace_segments(5, {}), fl::Error);
}

TEST(LabelHistory, UndoRedoSingleAndBatchEdits) {
  fl::Project p = sample();
  fl::LabelHistory h;
  EXPECT_FALSE(h.undo(p));
  const std::vector<fl::SegmentRef> one = {{0, 1}};
  EXPECT_TRUE(h.apply(p, one, fl::Label::Boundary, "one"));
  EXPECT_EQ(p.images[0].segments[1].label, fl::Label::Boundary);
  const std::vector<fl::SegmentRef> batch = {{0, 0}, {0, 1}, {1, 0}};
  EXPECT_TRUE(h.apply(p, batch, fl::Label::None, "batch"));
  EXPECT_EQ(h.next_undo()->edits.size(), 2u);  // {1,0} was already none
  EXPECT_FALSE(h.apply(p, batch, fl::Label::None));  // changes nothing: no step
  EXPECT_TRUE(h.undo(p));
  EXPECT_EQ(p.images[0].segments[0].label, fl::Label::Marking);
  EXPECT_EQ(p.images[0].segments[1].label, fl::Label::Boundary);
  EXPECT_EQ(h.next_redo()->description, "batch");
  EXPECT_TRUE(h.undo(p));
  EXPECT_EQ(p.images[0].segments[1].label, fl::Label::Unlabelled);
  EXPECT_FALSE(h.can_undo());
  EXPECT_TRUE(h.redo(p));
  EXPECT_TRUE(h.redo(p));
  EXPECT_EQ(p.images[0].segments[0].label, fl::Label::None);
  EXPECT_FALSE(h.redo(p));
  // A new edit after undo drops the redo branch.
  h.undo(p);
  const std::vector<fl::SegmentRef> other = {{1, 0}};
  h.apply(p, other, fl::Label::Marking);
  EXPECT_FALSE(h.can_redo());
  // Out of range: error, nothing changed.
  const fl::Project before = p;
  const std::vector<fl::SegmentRef> bad = {{0, 0}, {0, 7}};
  EXPECT_THROW(h.apply(p, bad, fl::Label::Marking), fl::Error);
  EXPECT_EQ(p.images[0].segments[0].label, before.images[0].segments[0].label);
}

TEST(ProjectShared, ReferenceCsvBecomesAProjectAndBackLosslessly) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl/annotations/D4_humanoid_kid.csv", d4);
  const auto rows = fl::read_reference_csv(d4);
  const fl::Project p = fl::project_from_reference_rows(rows);
  EXPECT_EQ(p.labelled_count(), rows.size());
  const fs::path file = fs::temp_directory_path() / "fl_project_d4.json";
  fs::remove(file);
  p.save(file);
  const fl::Project q = fl::Project::load(file);
  fs::remove(file);
  const fl::LabelledSet a = fl::labelled_set_from_rows(rows), b = q.labelled();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.images.size(), b.images.size());
  std::size_t same = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    same += a.segments[i].grad_x == b.segments[i].grad_x && a.segments[i].label == b.segments[i].label &&
            a.images[a.image_of[i]] == b.images[b.image_of[i]];
  // Rows of one image are contiguous in these files, so order is preserved too.
  EXPECT_EQ(same, a.size());
}

TEST_F(ProjectFiles, ReferenceRowsFromProjectAreTheLabelledSegmentsAndReadBackExactly) {
  fl::Project p = sample();  // a.png: marking + unlabelled; b.png: none
  // Awkward floats (not exactly representable in decimal, tiny, huge, negative zero) and an image
  // path the CSV has to quote; an image holding only unlabelled segments is not exported.
  p.images.push_back({"frames/c, \"odd\".png",
                      {fl::Segment{1.f / 3, 2e-7f, 3.4e38f, -0.f, 0.1f, {-0.f, 1e-40f, 7.f / 9}, {0.3f, -1.f / 7, 0}, fl::Label::Boundary},
                       seg(5, 5, 6, 6)},
                      1});
  p.images.push_back({"frames/empty.png", {seg(1, 1, 9, 9), seg(2, 2, 8, 8)}, 1});
  const std::vector<fl::ReferenceRow> rows = fl::reference_rows_from_project(p);
  ASSERT_EQ(rows.size(), 3u);
  ASSERT_EQ(rows.size(), p.labelled_count());
  EXPECT_EQ(rows[0].image, "frames/a.png");
  EXPECT_EQ(rows[0].segment.label, fl::Label::Marking);
  EXPECT_EQ(rows[1].image, "frames/b.png");
  EXPECT_EQ(rows[1].segment.label, fl::Label::None);
  EXPECT_EQ(rows[2].image, "frames/c, \"odd\".png");
  EXPECT_EQ(rows[2].segment.label, fl::Label::Boundary);
  for (const fl::ReferenceRow& r : rows) EXPECT_NE(r.segment.label, fl::Label::Unlabelled);

  // Through the CSV file and back into a project: every field bit for bit (sign of zero too).
  // For finite floats, equal with the same sign bit means the same bits.
  const auto same = [&](const fl::Segment& a, const fl::Segment& b) {
    const float va[] = {a.x0, a.y0, a.x1, a.y1, a.saliency, a.grad_x[0], a.grad_x[1], a.grad_x[2],
                        a.grad_y[0], a.grad_y[1], a.grad_y[2]};
    const float vb[] = {b.x0, b.y0, b.x1, b.y1, b.saliency, b.grad_x[0], b.grad_x[1], b.grad_x[2],
                        b.grad_y[0], b.grad_y[1], b.grad_y[2]};
    for (std::size_t i = 0; i < 11; ++i)
      if (va[i] != vb[i] || std::signbit(va[i]) != std::signbit(vb[i])) return false;
    return a.label == b.label;
  };
  const fs::path csv = dir_ / "labels.csv";
  fl::write_reference_csv(csv, rows);
  const std::vector<fl::ReferenceRow> read = fl::read_reference_csv(csv);
  ASSERT_EQ(read.size(), rows.size());
  const fl::Project q = fl::project_from_reference_rows(read);
  ASSERT_EQ(q.images.size(), 3u);
  const std::vector<fl::ReferenceRow> again = fl::reference_rows_from_project(q);
  ASSERT_EQ(again.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(again[i].image, rows[i].image) << i;
    EXPECT_TRUE(same(again[i].segment, rows[i].segment)) << i;
  }
  // The second export writes the same bytes.
  fl::write_reference_csv(dir_ / "again.csv", again);
  EXPECT_EQ(fl::read_file(dir_ / "again.csv"), fl::read_file(csv));
  EXPECT_TRUE(fl::reference_rows_from_project(fl::Project{}).empty());
}

// A DATA file is a project or a reference CSV, told apart by name or header, and loads as the
// same Project either way: a CSV (even one interleaving images) as the project convert makes.
TEST_F(ProjectFiles, DataFilesLoadAsProjectsWhateverTheirFormat) {
  const fl::Project p = sample();
  const std::vector<fl::ReferenceRow> rows = fl::reference_rows_from_project(p);
  const std::vector<fl::ReferenceRow> interleaved = {rows[0], rows[1],
                                                     {"frames/a.png", seg(1, 2, 30, 4, fl::Label::Boundary)}};
  fl::write_reference_csv(dir_ / "rows.CSV", interleaved);
  fs::copy_file(dir_ / "rows.CSV", dir_ / "rows.txt");  // no .csv name: told by its header
  p.save(dir_ / "p.json");
  EXPECT_TRUE(fl::is_reference_csv_data(dir_ / "rows.CSV"));
  EXPECT_TRUE(fl::is_reference_csv_data(dir_ / "rows.txt"));
  EXPECT_FALSE(fl::is_reference_csv_data(dir_ / "p.json"));

  const fl::Project from_csv = fl::load_data_as_project(dir_ / "rows.txt");
  const fl::Project converted = fl::project_from_reference_rows(fl::read_reference_csv(dir_ / "rows.CSV"));
  ASSERT_EQ(from_csv.images.size(), 2u);
  EXPECT_EQ(from_csv.images[0].segments.size(), 2u);  // grouped by image
  const fl::LabelledSet a = from_csv.labelled(), b = converted.labelled();
  ASSERT_EQ(a.size(), 3u);
  ASSERT_EQ(b.size(), 3u);
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_TRUE(a.segments[i].x0 == b.segments[i].x0 && a.segments[i].label == b.segments[i].label) << i;
  EXPECT_EQ(a.image_of, (std::vector<std::uint32_t>{0, 0, 1}));
  EXPECT_EQ(a.segments[1].label, fl::Label::Boundary);
  EXPECT_EQ(from_csv.thresholds, fl::Thresholds{});

  const fl::Project from_json = fl::load_data_as_project(dir_ / "p.json");
  EXPECT_EQ(from_json.labelled_count(), p.labelled_count());
  EXPECT_EQ(from_json.thresholds, p.thresholds);
  EXPECT_EQ(error_of([&] { fl::load_data_as_project(dir_); }), "'" + dir_.string() + "' is not a file");
}
