// A warm LineDetector::detect(image, out) makes no heap call: every buffer is the detector's
// (or the caller's vector) and is reused by capacity. This executable counts every allocation:
// it replaces malloc/calloc/realloc/posix_memalign/aligned_alloc/memalign/free (forwarding to
// glibc's __libc_* functions) and the global operator new/delete. Under AddressSanitizer, which
// owns malloc, it counts through ASan's allocator hooks instead, so the test runs there too.
#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <new>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "cli_test_support.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/synth/synth.hpp"
#include "shared_data.hpp"

namespace {

std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

inline void note_allocation() {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace

#if defined(__SANITIZE_ADDRESS__)
#define FIELDLINES_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FIELDLINES_ASAN 1
#endif
#endif

#ifdef FIELDLINES_ASAN
// From <sanitizer/allocator_interface.h>, declared here because GCC does not always install it;
// libasan exports it.
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*, std::size_t),
                                                         void (*free_hook)(const volatile void*));

namespace {
// ASan's interceptors must stay in charge of malloc and operator new; its hooks see every
// allocation they serve (malloc, calloc, realloc, memalign family, new).
void on_malloc(const volatile void*, std::size_t) { note_allocation(); }
void on_free(const volatile void*) {}
const int g_hooks_installed = __sanitizer_install_malloc_and_free_hooks(on_malloc, on_free);
}  // namespace
#else
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* ptr, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
void __libc_free(void* ptr);

void* malloc(std::size_t size) noexcept {
  note_allocation();
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  note_allocation();
  return __libc_calloc(count, size);
}
void* realloc(void* ptr, std::size_t size) noexcept {
  note_allocation();
  return __libc_realloc(ptr, size);
}
void* memalign(std::size_t alignment, std::size_t size) noexcept {
  note_allocation();
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  note_allocation();
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  note_allocation();
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* p = __libc_memalign(alignment, size);
  if (!p) return ENOMEM;
  *out = p;
  return 0;
}
void free(void* ptr) noexcept { __libc_free(ptr); }
}  // extern "C"

// Every operator new ends in the counting malloc / posix_memalign above.
namespace {
void* counted_new(std::size_t size) {
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void* counted_new(std::size_t size, std::align_val_t alignment) {
  void* p = nullptr;
  const std::size_t a = std::max(static_cast<std::size_t>(alignment), sizeof(void*));
  if (posix_memalign(&p, a, size ? size : 1) != 0) throw std::bad_alloc();
  return p;
}
}  // namespace

void* operator new(std::size_t size) { return counted_new(size); }
void* operator new[](std::size_t size) { return counted_new(size); }
void* operator new(std::size_t size, std::align_val_t a) { return counted_new(size, a); }
void* operator new[](std::size_t size, std::align_val_t a) { return counted_new(size, a); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return std::malloc(size ? size : 1); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return std::malloc(size ? size : 1); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
#endif

namespace fieldlines {
namespace {

namespace fs = std::filesystem;

// Heap calls made by one detect(image, out).
long allocations_in_detect(LineDetector& detector, const cv::Mat& image, std::vector<Segment>& out) {
  g_allocations = 0;
  g_counting = true;
  detector.detect(image, out);
  g_counting = false;
  return g_allocations.load();
}

// Two warm-up passes, then every frame once more, counted; with the per-frame counts so a
// failure names the frame.
void expect_warm_detect_allocates_nothing(const std::vector<cv::Mat>& frames, const std::vector<std::string>& names,
                                         const DetectorParams& params = {}, const Thresholds& thresholds = {}) {
  LineDetector detector(params, thresholds);
  std::vector<Segment> out;
  // A cold detector does allocate, inside libfieldlines_detect: the counter sees the library.
  EXPECT_GT(allocations_in_detect(detector, frames.front(), out), 0);
  std::size_t segments = 0;
  for (int pass = 0; pass < 2; ++pass)
    for (const cv::Mat& f : frames) detector.detect(f, out), segments += out.size();
  EXPECT_GT(segments, 0u) << "the frames must exercise drawing and validation";
  for (std::size_t i = 0; i < frames.size(); ++i)
    EXPECT_EQ(allocations_in_detect(detector, frames[i], out), 0) << names[i] << " (" << frames[i].cols << "x"
                                                                  << frames[i].rows << ")";
}

// Keeps the compiler from eliding an allocation whose result is never used.
void escape(void* p) { asm volatile("" : : "g"(p) : "memory"); }

template <class F>
long allocations_in(F&& f) {
  g_allocations = 0;
  g_counting = true;
  f();
  g_counting = false;
  return g_allocations.load();
}

TEST(DetectAllocations, CounterSeesEveryKindOfAllocation) {
  // The test would pass vacuously if the counter missed allocations.
  EXPECT_GT(allocations_in([] {
              auto* v = new std::vector<int>(100);
              escape(v->data());
              delete v;
            }),
            0)
      << "operator new";
  EXPECT_GT(allocations_in([] {
              void* p = std::malloc(10);
              escape(p);
              p = std::realloc(p, 1000);
              escape(p);
              std::free(p);
            }),
            0)
      << "malloc/realloc";
  EXPECT_GT(allocations_in([] {
              void* p = std::calloc(4, 8);
              escape(p);
              std::free(p);
            }),
            0)
      << "calloc";
  EXPECT_GT(allocations_in([] {
              void* p = nullptr;
              if (posix_memalign(&p, 64, 128) == 0) escape(p);
              std::free(p);
            }),
            0)
      << "posix_memalign";
}

// `count` synthetic fields, each shifted `step` px further, with names that say which.
struct SyntheticFrames {
  std::vector<cv::Mat> frames;
  std::vector<std::string> names;
};
SyntheticFrames synthetic_frames(int count, int step) {
  SyntheticFrames out;
  for (int shift = 0; shift < count; ++shift) {
    out.frames.push_back(test::synthetic_field(640, 480, shift * step));
    out.names.push_back("synthetic shift " + std::to_string(shift * step));
  }
  return out;
}

TEST(DetectAllocations, NoneOnSyntheticFramesOfOneSize) {
  const auto [frames, names] = synthetic_frames(6, 7);
  expect_warm_detect_allocates_nothing(frames, names);
}

// The robot's per-frame light adaptation (light.hpp) measures the field colour on fixed-size
// histograms: still nothing.
TEST(DetectAllocations, NoneWithLightAdaptation) {
  const auto [frames, names] = synthetic_frames(4, 5);
  ASSERT_TRUE(estimate_field_colour(frames.front())) << "the frames must show a field";
  Thresholds t;
  t.light = {true, {40, 120, 40}};
  expect_warm_detect_allocates_nothing(frames, names, {}, t);
}

// A gradient threshold per frame (dark_field above every frame's field): the gradient passes
// take the frame's threshold without being configured again.
TEST(DetectAllocations, NoneWithDarkField) {
  const auto [frames, names] = synthetic_frames(4, 5);
  DetectorParams p;
  p.dark_field = 765;
  Thresholds t;
  t.light = {true, {40, 120, 40}};
  expect_warm_detect_allocates_nothing(frames, names, p, t);
}

// Every field feature stage on: the stripes, their intersections, the centre circle.
DetectorParams all_features() {
  DetectorParams p;
  p.stripes = true;
  p.intersections = true;
  p.centre_circle = true;
  return p;
}

// The stripes stage (stripes.hpp) measures its profiles in the detector's workspace and writes
// the markings into the detector's features: still nothing.
TEST(DetectAllocations, NoneWithStripes) {
  const auto [frames, names] = synthetic_frames(4, 5);
  DetectorParams stripes;
  stripes.stripes = true;
  LineDetector probe(stripes);
  probe.detect(frames.front());
  ASSERT_FALSE(probe.features().markings.empty()) << "the frames must exercise the stripes";
  expect_warm_detect_allocates_nothing(frames, names, stripes);
  stripes.stripe_require_twin = true;
  Thresholds t;
  t.light = {true, {40, 120, 40}};
  t.field_boundary_gate = true;
  expect_warm_detect_allocates_nothing(frames, names, stripes, t);
  expect_warm_detect_allocates_nothing(frames, names, all_features(), t);
}

// The coarse pass (DetectorParams::coarse_scale) downsamples into its own reused band and engine:
// still nothing, alone and with every feature stage after it (and its twins' band).
TEST(DetectAllocations, NoneWithTheCoarsePass) {
  const auto [frames, names] = synthetic_frames(4, 5);
  DetectorParams coarse;
  coarse.coarse_scale = 2;
  coarse.coarse_from = 0.4;
  expect_warm_detect_allocates_nothing(frames, names, coarse);
  DetectorParams every = all_features();
  every.coarse_scale = 3;
  every.coarse_twins_from = 0.2;  // the band above coarse_from keeping the lines it resolves
  expect_warm_detect_allocates_nothing(frames, names, every);
}

// The thin-line pass (DetectorParams::thin_reach) keeps its ridge maps and the list of what it
// wrote, and reads the gradient pass's kept smoothed grey: still nothing, alone, with every
// feature stage, and when frame sizes alternate; nor with the boundary's gate, which starts its
// rows at each frame's field top.
TEST(DetectAllocations, NoneWithTheThinPass) {
  const auto [frames, names] = synthetic_frames(4, 5);
  DetectorParams thin;
  thin.thin_reach = 3;
  expect_warm_detect_allocates_nothing(frames, names, thin);
  Thresholds gated;
  gated.field_boundary_gate = true;
  expect_warm_detect_allocates_nothing(frames, names, thin, gated);
  DetectorParams every = all_features();
  every.thin_reach = 2;
  every.thin_to = 1.0;
  every.coarse_scale = 3;
  expect_warm_detect_allocates_nothing(frames, names, every);
}

// With the camera known the centre circle is also fitted on the turf (ground_circle.hpp) and
// every feature is projected onto it (ground_features.hpp); the camera is set per frame, as a
// walking robot's pose changes: still nothing.
TEST(DetectAllocations, NoneWithTheCameraSetPerFrame) {
  synth::SynthParams params;
  params.field.scene = synth::Scene::Kid;
  std::vector<synth::SynthSample> samples;
  for (const int index : {1, 5, 15, 22}) samples.push_back(synth::generate(params, 4242, index));
  LineDetector detector(all_features());
  std::vector<Segment> out;
  std::size_t ellipses = 0, on_ground = 0;
  for (int pass = 0; pass < 2; ++pass)
    for (const synth::SynthSample& s : samples) {
      detector.set_camera(synth::to_ground_camera(s.truth.intrinsics, s.truth.pose));
      detector.detect(s.bgr, out);
      ellipses += detector.features().ellipses.size();
      const GroundFeatures& g = detector.ground_features();
      on_ground += g.segments.size() + g.intersections.size() + g.ellipses.size() + g.field_boundary.size();
    }
  EXPECT_GT(ellipses, 0u) << "the frames must exercise the fit on the turf";
  EXPECT_GT(on_ground, 0u) << "the frames must exercise the ground features";
  for (const synth::SynthSample& s : samples) {
    const GroundCamera camera = synth::to_ground_camera(s.truth.intrinsics, s.truth.pose);
    EXPECT_EQ(allocations_in([&] {
                detector.set_camera(camera);
                detector.detect(s.bgr, out);
              }),
              0)
        << "kid 4242 frame " << s.truth.index;
  }
}

// With threads > 1 the workers start on the first detect and are woken per frame without a heap
// call; the counter sees every thread's allocations.
TEST(DetectAllocations, NoneWithTwoThreadsOnFramesOfOneSize) {
  std::vector<cv::Mat> frames;
  std::vector<std::string> names;
  for (const cv::Size s : {cv::Size(640, 480), cv::Size(1280, 720), cv::Size(1920, 1080)}) {
    for (int shift = 0; shift < 3; ++shift) {
      frames.push_back(test::synthetic_field(s.width, s.height, shift * 7));
      names.push_back(cv::format("synthetic %dx%d shift %d", s.width, s.height, shift * 7));
    }
  }
  DetectorParams two;
  two.threads = 2;
  expect_warm_detect_allocates_nothing(frames, names, two);
}

void expect_none_when_sizes_alternate(const DetectorParams& params) {
  LineDetector detector(params);
  std::vector<Segment> out;
  const cv::Mat large = test::synthetic_field(1280, 720), small = test::synthetic_field(320, 240, 5),
                middle = test::synthetic_field(800, 600, 3), tall = test::synthetic_field(480, 640, 9);
  for (const cv::Mat* f : {&large, &small, &middle, &tall}) detector.detect(*f, out);
  detector.detect(large, out);  // drawing buffers grow to whichever frame needs most
  for (int round = 0; round < 3; ++round)
    for (const cv::Mat* f : {&small, &large, &tall, &middle, &small}) {
      EXPECT_EQ(allocations_in_detect(detector, *f, out), 0)
          << f->cols << "x" << f->rows << " round " << round << ", threads " << params.threads;
      EXPECT_FALSE(out.empty());
    }
}

TEST(DetectAllocations, NoneWhenSizesAlternateAfterTheLargest) {
  expect_none_when_sizes_alternate({});
  DetectorParams two;  // 320x240 splits into two bands, so does every other size
  two.threads = 2;
  expect_none_when_sizes_alternate(two);
  DetectorParams stripes;  // profiles as long as the tallest frame allows
  stripes.stripes = true;
  expect_none_when_sizes_alternate(stripes);
  expect_none_when_sizes_alternate(all_features());
  DetectorParams thin;  // its band and maps follow the frame's size
  thin.thin_reach = 3;
  expect_none_when_sizes_alternate(thin);
}

std::vector<fs::path> images_in(const fs::path& dir) {
  std::vector<fs::path> paths;
  for (const auto& e : fs::directory_iterator(dir)) paths.push_back(e.path());
  std::sort(paths.begin(), paths.end());
  return paths;
}

void expect_none_on_folder(const fs::path& dir, std::size_t expected_frames, const DetectorParams& params = {},
                           const Thresholds& thresholds = {}) {
  SCOPED_TRACE(params.intersections ? "all features on" : (params.stripes ? "stripes on" : "stripes off"));
  std::vector<cv::Mat> frames;
  std::vector<std::string> names;
  for (const fs::path& p : images_in(dir)) {
    cv::Mat bgr = cv::imread(p.string(), cv::IMREAD_COLOR);
    if (bgr.empty()) continue;
    frames.push_back(bgr);
    names.push_back(p.filename().string());
  }
  ASSERT_EQ(frames.size(), expected_frames) << dir;
  expect_warm_detect_allocates_nothing(frames, names, params, thresholds);
}

TEST(DetectAllocations, NoneOnTheAuthorsSslFrames) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl/images", dir);
  expect_none_on_folder(dir, 41);
  DetectorParams two;
  two.threads = 2;
  expect_none_on_folder(dir, 41, two);
  DetectorParams stripes;
  stripes.stripes = true;
  expect_none_on_folder(dir, 41, stripes);
  LineDetector probe(all_features());
  std::size_t found = 0;
  for (const fs::path& p : images_in(dir)) {
    probe.detect(cv::imread(p.string(), cv::IMREAD_COLOR));
    found += probe.features().intersections.size();
  }
  ASSERT_GT(found, 0u) << "the frames must exercise the intersections";
  expect_none_on_folder(dir, 41, all_features());
  DetectorParams thin = all_features();
  thin.thin_reach = 3;
  expect_none_on_folder(dir, 41, thin);
}

TEST(DetectAllocations, NoneOnHumanoidFramesOfTwoSizes) {
  FIELDLINES_REQUIRE_SHARED("data/humanoid-samples", dir);
  expect_none_on_folder(dir, 9);  // 640x360 and 800x600, interleaved by name
  DetectorParams stripes;
  stripes.stripes = true;
  expect_none_on_folder(dir, 9, stripes);
  expect_none_on_folder(dir, 9, all_features());
  DetectorParams thin;
  thin.thin_reach = 2;
  Thresholds gated;  // the thin pass's rows from each frame's field top, which moves frame to frame
  gated.field_boundary_gate = true;
  expect_none_on_folder(dir, 9, thin, gated);
}

}  // namespace
}  // namespace fieldlines
