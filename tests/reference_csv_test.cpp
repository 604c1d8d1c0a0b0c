// Reference annotation CSV: conversion to our conventions, lossless round trip, clear errors.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "shared_data.hpp"

namespace fl = fieldlines;
namespace fs = std::filesystem;

namespace {

const char* kHeader =
    "img_path,x0,y0,x1,y1,grad_Bx,grad_Gx,grad_Rx,grad_By,grad_Gy,grad_Ry,segment_length,"
    "is_field_boundary,is_field_marking,is_not_a_field_feature\n";

class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fl_csv_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                        "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }
  fs::path dir_;
};

std::string error_of(const fs::path& p) {
  try {
    fl::read_reference_csv(p);
  } catch (const fl::Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_F(TempDir, ConvertsChannelOrderAndYSign) {
  const fs::path p = write("a.csv", std::string(kHeader) +
                                        "img.png,1,2,3,4,10,20,30,-40,-50,-60,77,False,True,False\n");
  const auto rows = fl::read_reference_csv(p);
  ASSERT_EQ(rows.size(), 1u);
  const fl::Segment& s = rows[0].segment;
  EXPECT_EQ(rows[0].image, "img.png");
  EXPECT_FLOAT_EQ(s.x0, 1);
  EXPECT_FLOAT_EQ(s.y1, 4);
  // B,G,R -> R,G,B and row-above-minus-below -> image-down.
  EXPECT_FLOAT_EQ(s.grad_x[0], 30);
  EXPECT_FLOAT_EQ(s.grad_x[2], 10);
  EXPECT_FLOAT_EQ(s.grad_y[0], 60);
  EXPECT_FLOAT_EQ(s.grad_y[1], 50);
  EXPECT_FLOAT_EQ(s.grad_y[2], 40);
  EXPECT_FLOAT_EQ(s.saliency, 77);
  EXPECT_EQ(s.label, fl::Label::Marking);
}

TEST_F(TempDir, RowsWithoutLabelColumnsAreUnlabelled) {
  const fs::path p = write("u.csv",
                           "img_path,x0,y0,x1,y1,grad_Bx,grad_Gx,grad_Rx,grad_By,grad_Gy,grad_Ry,segment_length\n"
                           "a.png,0,0,5,5,1,2,3,4,5,6,7\n");
  const auto rows = fl::read_reference_csv(p);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].segment.label, fl::Label::Unlabelled);
}

TEST_F(TempDir, MalformedRowsNameFileAndLine) {
  const std::string good = "a.png,0,0,5,5,1,2,3,4,5,6,7,False,False,True\n";
  EXPECT_NE(error_of(write("m.csv", std::string(kHeader) + good + "a.png,0,0,5,5,1,2,3\n")).find("m.csv:3"),
            std::string::npos);
  const std::string nan = error_of(write("n.csv", std::string(kHeader) + "a.png,0,0,5,5,1,nan,3,4,5,6,7,False,False,True\n"));
  EXPECT_NE(nan.find("n.csv:2"), std::string::npos);
  EXPECT_NE(nan.find("grad_Gx"), std::string::npos);
  EXPECT_NE(error_of(write("i.csv", std::string(kHeader) + "a.png,0,0,5,5,1,inf,3,4,5,6,7,False,False,True\n")), "");
  EXPECT_NE(error_of(write("x.csv", std::string(kHeader) + "a.png,0,0,5,5,1,2x,3,4,5,6,7,False,False,True\n")), "");
  const std::string b = error_of(write("b.csv", std::string(kHeader) + "a.png,0,0,5,5,1,2,3,4,5,6,7,Maybe,False,True\n"));
  EXPECT_NE(b.find("is_field_boundary"), std::string::npos);
  const std::string several = error_of(write("s.csv", std::string(kHeader) + "a.png,0,0,5,5,1,2,3,4,5,6,7,True,True,False\n"));
  EXPECT_NE(several.find("several"), std::string::npos);
  EXPECT_NE(error_of(write("h.csv", "img_path,x0\n")).find("h.csv:1"), std::string::npos);
  EXPECT_NE(error_of(dir_ / "missing.csv").find("missing.csv"), std::string::npos);
}

TEST_F(TempDir, ExportThenImportLosesNothing) {
  std::vector<fl::ReferenceRow> rows;
  const fl::Label labels[] = {fl::Label::Marking, fl::Label::Boundary, fl::Label::None, fl::Label::Unlabelled};
  for (int i = 0; i < 40; ++i) {
    fl::ReferenceRow r;
    r.image = i % 3 == 0 ? "dir, with comma/\"q\".png" : "img" + std::to_string(i % 5) + ".png";
    r.segment = {0.1f * i, 1.f / 3 + i, 639.9f - i, 1e-7f * i, 12.345678f + i, {1.f / 7, -2.5f, 3e-3f},
                 {-0.f, 255.f / 9, -1e5f / (i + 1)}, labels[i % 4]};
    rows.push_back(r);
  }
  const fs::path p = dir_ / "round.csv";
  fl::write_reference_csv(p, rows);
  const auto back = fl::read_reference_csv(p);
  ASSERT_EQ(back.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(back[i].image, rows[i].image);
    const fl::Segment &a = rows[i].segment, &b = back[i].segment;
    EXPECT_EQ(a.x0, b.x0);
    EXPECT_EQ(a.y0, b.y0);
    EXPECT_EQ(a.x1, b.x1);
    EXPECT_EQ(a.y1, b.y1);
    EXPECT_EQ(a.saliency, b.saliency);
    EXPECT_EQ(a.grad_x, b.grad_x);
    EXPECT_EQ(a.grad_y, b.grad_y);
    EXPECT_EQ(a.label, b.label);
  }
}

TEST(ReferenceCsvShared, ReadsAndRoundTripsTheAuthorsFiles) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl/annotations/D1_ssl_natural_light.csv", d1);
  const auto rows = fl::read_reference_csv(d1);
  ASSERT_EQ(rows.size(), 1747u);
  // First row: 13,293,0,331, gx B,G,R = 80.09677,73.16936,89.70967, gy -31.01612,-27.911293,-35.19355.
  EXPECT_FLOAT_EQ(rows[0].segment.grad_x[0], 89.70967f);
  EXPECT_FLOAT_EQ(rows[0].segment.grad_y[0], 35.19355f);
  EXPECT_EQ(rows[0].segment.label, fl::Label::Marking);
  for (const auto& r : rows) ASSERT_NE(r.segment.label, fl::Label::Unlabelled);
  const fs::path out = fs::temp_directory_path() / "fl_csv_d1_roundtrip.csv";
  fl::write_reference_csv(out, rows);
  const auto back = fl::read_reference_csv(out);
  fs::remove(out);
  ASSERT_EQ(back.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(back[i].segment.grad_y, rows[i].segment.grad_y);
    ASSERT_EQ(back[i].segment.label, rows[i].segment.label);
    ASSERT_EQ(back[i].image, rows[i].image);
  }
}

