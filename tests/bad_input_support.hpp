#pragma once
// Shared inputs for the bad-input matrix tests (docs/bad_input.md): small valid files that each
// test then damages in one way, and runners for the built CLI (optionally under a file-size
// limit that simulates a full disk).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "cli_test_support.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "fieldlines/detect/thresholds_file.hpp"

namespace fieldlines::test {

inline constexpr const char* kCsvHeader =
    "img_path,x0,y0,x1,y1,grad_Bx,grad_Gx,grad_Rx,grad_By,grad_Gy,grad_Ry,segment_length,"
    "is_field_boundary,is_field_marking,is_not_a_field_feature\n";

// `n` labelled rows over 10 images: markings (white-ish gradient), boundaries (green) and clutter.
inline std::vector<ReferenceRow> labelled_rows(int n, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<ReferenceRow> rows;
  for (int i = 0; i < n; ++i) {
    ReferenceRow r;
    r.image = "img" + std::to_string(i % 10) + ".png";
    Segment& s = r.segment;
    s.x0 = 10, s.y0 = 10 + static_cast<float>(i % 50), s.x1 = 100, s.y1 = 5;
    s.saliency = 30 + 200 * u(rng);
    const float m = 20 + 100 * u(rng);
    switch (i % 3) {
      case 0: s.grad_y = {m, 0.8f * m, m}, s.label = Label::Marking; break;
      case 1: s.grad_y = {5, m, 5}, s.label = Label::Boundary; break;
      default: s.grad_y = {m * (u(rng) - .5f), m * (u(rng) - .5f), m}, s.label = Label::None; break;
    }
    rows.push_back(r);
  }
  return rows;
}

class BadInputTest : public TempDirTest {
 protected:
  std::filesystem::path path(const std::string& name) const { return dir_ / name; }

  std::filesystem::path bytes(const std::string& name, const std::string& contents) const {
    const auto p = path(name);
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << contents;
    return p;
  }
  std::filesystem::path image(const std::string& name, const cv::Mat& img) const {
    const auto p = path(name);
    std::filesystem::create_directories(p.parent_path());
    EXPECT_TRUE(cv::imwrite(p.string(), img)) << p;
    return p;
  }
  std::filesystem::path field_image(const std::string& name) const { return image(name, synthetic_field(320, 240)); }
  // The first `keep` bytes of a valid image of the same format.
  std::filesystem::path truncated_image(const std::string& name, double keep) const {
    const std::string full = read_text(field_image(name));
    return bytes(name, full.substr(0, static_cast<std::size_t>(static_cast<double>(full.size()) * keep)));
  }
  std::filesystem::path csv(const std::string& name, int n = 60) const {
    const auto p = path(name);
    write_reference_csv(p, labelled_rows(n));
    return p;
  }
  std::filesystem::path thresholds(const std::string& name) const {
    const auto p = path(name);
    const ThresholdsFile defaults;
    save_thresholds_file(p, defaults);
    return p;
  }
  std::filesystem::path project(const std::string& name, int n = 60) const {
    const auto p = path(name);
    project_from_reference_rows(labelled_rows(n)).save(p);
    return p;
  }
  // A 2-image synthetic set made by `fieldlines synth` (made once per test process, copied).
  std::filesystem::path synth_set(const std::string& name) const {
    static const std::filesystem::path master = [] {
      const auto d = std::filesystem::temp_directory_path() / ("fieldlines_bad_input_set_" + std::to_string(::getpid()));
      std::filesystem::create_directories(d);
      const CliRun r = run_cli({"synth", "--scene", "ssl", "--n", "2", "--seed", "3", "--quiet", "-o", (d / "set").string()}, d);
      EXPECT_EQ(r.exit_code, 0) << r.err;
      std::atexit([] {
        std::error_code ec;
        std::filesystem::remove_all(std::filesystem::temp_directory_path() /
                                        ("fieldlines_bad_input_set_" + std::to_string(::getpid())), ec);
      });
      return d / "set";
    }();
    const auto p = path(name);
    std::filesystem::copy(master, p, std::filesystem::copy_options::recursive);
    return p;
  }
  // The synthetic set's images, sorted.
  static std::vector<std::filesystem::path> set_images(const std::filesystem::path& set) {
    std::vector<std::filesystem::path> out;
    for (const auto& e : std::filesystem::directory_iterator(set))
      if (e.path().extension() == ".png") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
  }

  CliRun run(const std::vector<std::string>& args) const { return run_cli(args, dir_); }

  // Runs the CLI with RLIMIT_FSIZE = `kib` KiB (0: no regular file may grow) and SIGXFSZ
  // ignored: a write past the limit then fails with EFBIG, as a write to a full disk fails with
  // ENOSPC. stderr comes back through a pipe and stdout goes to /dev/null, neither of which the
  // limit applies to.
  CliRun run_with_file_limit(const std::vector<std::string>& args, int kib) const {
    std::string cmd = "bash -c " + shell_quote("ulimit -f " + std::to_string(kib) + "; trap '' XFSZ; exec \"$0\" \"$@\"");
    cmd += ' ';
    cmd += shell_quote(cli_path().string());
    for (const auto& a : args) {
      cmd += ' ';
      cmd += shell_quote(a);
    }
    cmd += " 2>&1 >/dev/null </dev/null";
    CliRun r;
    FILE* pipe = ::popen(cmd.c_str(), "r");
    if (pipe == nullptr) return r;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.err.append(buf, n);
    const int status = ::pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
  }
};

// The exit code is `code` (so no signal) and stderr holds every one of `parts`.
#define EXPECT_CLI_FAILS(run_result, code, ...)                                    \
  do {                                                                             \
    const ::fieldlines::test::CliRun& r_ = (run_result);                           \
    EXPECT_EQ(r_.exit_code, code) << r_.err;                                       \
    for (const std::string& part_ : std::vector<std::string>{__VA_ARGS__})         \
      EXPECT_NE(r_.err.find(part_), std::string::npos) << "missing '" << part_ << "' in:\n" << r_.err; \
  } while (0)

}  // namespace fieldlines::test
