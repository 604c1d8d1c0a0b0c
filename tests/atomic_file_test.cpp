// Atomic saves and the clean-up of temporary files that killed saves leave behind.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <future>
#include <string>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"

namespace fl = fieldlines;
namespace fs = std::filesystem;

namespace {

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fl_atomic_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  int files() const {
    int n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++n;
    return n;
  }
  fs::path dir_;
};

}  // namespace

TEST_F(AtomicFile, WriteReplacesAndLeavesNoTemporaryFiles) {
  const fs::path p = dir_ / "f.txt";
  fl::write_file_atomically(p, "one");
  fl::write_file_atomically(p, "two");
  EXPECT_EQ(fl::read_file(p), "two");
  EXPECT_EQ(files(), 1);
  try {
    fl::write_file_atomically(dir_ / "no_such_dir" / "f.txt", "x");
    FAIL() << "expected an error";
  } catch (const fl::Error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_dir"), std::string::npos);
  }
}

// A pipe (or a device: /dev/null) is written in place; a file renamed over it would replace it.
TEST_F(AtomicFile, APipeIsWrittenInPlaceNotReplaced) {
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto reader = std::async(std::launch::async, [&] { return fieldlines::read_file(fifo); });
  fieldlines::write_file_atomically(fifo, "through the pipe");
  EXPECT_EQ(reader.get(), "through the pipe");
  EXPECT_TRUE(fs::is_fifo(fifo)) << "still the pipe";
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}), 1) << "no temporary left";
}

TEST_F(AtomicFile, StaleTemporariesOfThisFileOnlyAreRemoved) {
  const fs::path p = dir_ / "project.json";
  fl::write_file_atomically(p, "{}");
  const auto old = fs::file_time_type::clock::now() - std::chrono::hours(1);
  for (const char* name : {".project.json.tmp123", ".project.json.tmp9", ".project.json.tmp77"}) {
    fl::write_file_atomically(dir_ / name, "half a save");
    fs::last_write_time(dir_ / name, old);
  }
  fl::write_file_atomically(dir_ / ".project.json.tmp5", "a save in progress");  // young: kept
  // Not ours: another file's temporary, a look-alike with a non-numeric suffix, the file itself.
  for (const char* name : {".other.json.tmp1", ".project.json.tmpX", "project.json.tmp1"}) {
    fl::write_file_atomically(dir_ / name, "x");
    fs::last_write_time(dir_ / name, old);
  }
  EXPECT_EQ(fl::remove_stale_temporaries(p), 3);
  EXPECT_FALSE(fs::exists(dir_ / ".project.json.tmp123"));
  EXPECT_TRUE(fs::exists(dir_ / ".project.json.tmp5"));
  EXPECT_TRUE(fs::exists(dir_ / ".other.json.tmp1"));
  EXPECT_TRUE(fs::exists(dir_ / ".project.json.tmpX"));
  EXPECT_TRUE(fs::exists(dir_ / "project.json.tmp1"));
  EXPECT_EQ(fl::read_file(p), "{}");
  EXPECT_EQ(fl::remove_stale_temporaries(p, std::chrono::seconds(0)), 1);  // now the young one too
  EXPECT_EQ(fl::remove_stale_temporaries(dir_ / "missing" / "p.json"), 0);  // no folder: nothing, no throw
}
