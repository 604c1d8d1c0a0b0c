// `fieldlines bench`: our detector against OpenCV's line detectors, same process, same images.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "app/cli/args.hpp"
#include "app/cli/commands.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "fieldlines/data/image_io.hpp"
#include "app/cli/image_inputs.hpp"
#include "app/cli/output_file.hpp"
#include "app/cli/progress.hpp"
#include "app/cli/subcommand.hpp"
#include "bench/peers/order_rounds.hpp"
#include "bench/peers/peer_detectors.hpp"

namespace fieldlines::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHelp = R"(usage: fieldlines bench [options] PATH...

Times, in this process, on the same colour images and on one thread (cv::setNumThreads(1);
our rows may take more with --detector-threads):
  fieldlines  our LineDetector: ELSED + colour gradients + classification
  fieldlines+light, fieldlines+stripes, fieldlines+coarse, fieldlines+thin, fieldlines+scales,
  fieldlines+junctions, fieldlines+features, fieldlines+ground
              the same with the per-frame light adaptation, with the stripes stage (every
              marking checked and measured across its width), with the coarse pass (the lower
              0.7 drawn again at a third of the size: coarse_scale 3, its upper 0.2 keeping the
              lines it resolves), with the thin-line pass
              (the upper 0.6 drawn again on lines' ridges: thin_reach 2), with both passes, with
              the stripes, field boundary
              and L/T/X junctions (the features of the detector's own drawing), or with every
              field feature (those and the centre circle, which draws the frame a second time),
              or with those and a camera (a 60-degree view 30 degrees down, 0.6 m up): every
              feature also on the ground (the circle fitted there, junctions checked square)
  edlines     OpenCV ximgproc EdgeDrawing in EDLines mode (detectEdges + detectLines)
  fld         OpenCV ximgproc FastLineDetector
  lsd         OpenCV LineSegmentDetector
  gradients   our gradient stage alone: one fused pass (grey, Gaussian, Sobel x/y, magnitude,
              direction), what the fieldlines row starts with
  floor       cvtColor + 5x5 Gaussian + Sobel x and y: what any gradient-based detector pays
Each call starts from the BGR image (grey conversion is timed). A detector's time depends on
what ran before it, so every row is timed in two orders, in --rounds rounds:
  block        each detector makes all its calls of the round back to back (one untimed call
               first), detectors in a random order
  interleaved  image by image, every detector once per image, in a random order per image
Each round runs the two orders in a random order (--seed). After one untimed warm-up pass
(which also counts the segments), prints per row the mean ms per call in each order,
segments per image, and ours/this in each order: per round, our time over this row's, each
summed over the round's calls (the median call would be one frame's, and hide what a stage
costs on the busier frames); the median over rounds. "worse" is the larger of the two orders
(the less flattering to us), with its min-max over rounds. The targets ours <= 0.4 x edlines
and ours <= 1.5 x floor (--floor-target) are checked against the worse ratio; gradients/floor
junctions/fieldlines and features/fieldlines (what the field features cost, target <= 1.2),
ground/features (what the ground stage adds, target <= 1.1), coarse/fieldlines, thin/fieldlines
and scales/fieldlines (what the coarse pass, the thin-line pass and both cost; target <= 1.25
each) are reported the same way.
PATH is an image or a folder; images that fail to load are reported and skipped (exit 1).

options:
  --rounds R    rounds (default 5, in [1, 10000]); the ratios' spread is taken over them
  --repeat N    passes over all images in each order in each round (default 1, in [1, 10000]):
                every detector is timed 2 x R x N times per image
  --seed S      seed of the random orders (default 1, in [0, 2147483647])
  --clock C     what a call's time is: thread-cpu (default with one detector thread) is the
                calling thread's CPU time, which other processes' turns do not inflate (wall
                time would flatter the short calls on a loaded machine: a 10 ms peer call is
                preempted far more often than a 1 ms one); wall (the default, and the only
                choice, with --detector-threads above 1, whose bands run on other threads)
  --floor-target X  the ours/floor ratio to check (default 1.5, the SSL target; the Humanoid
                frames, larger and busier, have 2)
  --scale WxH   resize every loaded image to W x H pixels (cv::resize, INTER_LINEAR; stretched
                if the aspect ratio differs) before timing, e.g. 1280x720 or 1920x1080;
                W and H in [8, 8192]
  --thresholds FILE  every fieldlines row starts from the file's detector parameters and
                thresholds (what a robot with that file runs: a calibrated one's denser anchor
                grid, its stripes) instead of the built-in ones; the fieldlines row with the
                coarse and the thin-line pass off, so that their rows add what they cost
  --detector-threads N  DetectorParams::threads for the fieldlines and gradients rows (default
                1, in [1, 64]): the gradient pass runs in N row bands at once; the peers and the
                floor stay on one thread
  --json OUT    write the results as JSON (below)
  --quiet       no progress on stderr
  -h, --help    this help

JSON: {"images":N, "scale":{"width","height"} (with --scale only), "thresholds":FILE (with
  --thresholds only), "detector_threads":N,
  "rounds":R, "passes_per_round":N, "seed":S, "clock":"thread-cpu"|"wall",
  "detectors":[{"name", "mean_ms", "median_ms", "p90_ms" (over every timed call, both orders),
    "segments_per_image", "block":{"mean_ms","median_ms","p90_ms"}, "interleaved":{likewise},
    "ours_over_this":RATIO}],
  "targets":{"edlines":TARGET, "floor":TARGET}, "gradients_over_floor":RATIO,
  "junctions_over_plain":RATIO, "features_over_plain":RATIO, "ground_over_features":RATIO,
  "coarse_over_plain":RATIO, "thin_over_plain":RATIO, "scales_over_plain":RATIO}
  RATIO  = {"block", "interleaved", "worse", "worse_order" ("block" or "interleaved"), "min", "max"}
           (min and max: the worse order's ratio over rounds)
  TARGET = {"ratio" (the worse ours/this), "limit", "met", "order", "min", "max"}

examples:
  fieldlines bench ../shared/data/elsed-ssl/images
  fieldlines bench --rounds 9 --json bench.json frame.png
  fieldlines bench --thresholds venue.json ../shared/data/humanoid-samples
  fieldlines bench --quiet --rounds 7 --scale 1920x1080 --detector-threads 2 ../shared/data/elsed-ssl/images
)";

struct TargetCheck {
  std::string label;  // "fieldlines/edlines"
  peers::RatioSummary ratio;
  double limit;
  bool met() const { return ratio.worse <= limit; }
};

nlohmann::ordered_json calls_json(const std::vector<double>& ms) {
  return {{"mean_ms", peers::mean(ms)}, {"median_ms", peers::quantile(ms, 0.5)}, {"p90_ms", peers::quantile(ms, 0.9)}};
}

nlohmann::ordered_json ratio_json(const peers::RatioSummary& r) {
  return {{"block", r.by_order[0]}, {"interleaved", r.by_order[1]},
          {"worse", r.worse},       {"worse_order", peers::order_name(r.worse_order)},
          {"min", r.min},           {"max", r.max}};
}

nlohmann::ordered_json target_json(const TargetCheck& t) {
  return {{"ratio", t.ratio.worse}, {"limit", t.limit}, {"met", t.met()},
          {"order", peers::order_name(t.ratio.worse_order)}, {"min", t.ratio.min}, {"max", t.ratio.max}};
}

// "0.31 [0.29-0.33, block]": the worse order's ratio, its spread over rounds and the order.
std::string worse_text(const peers::RatioSummary& r) {
  return cv::format("%.2f [%.2f-%.2f, %s]", r.worse, r.min, r.max, peers::order_name(r.worse_order));
}

// "WxH", both sides in [8, 8192] (FLD and LSD need a few pixels; 8192 keeps a frame's maps
// far below any int overflow).
cv::Size parse_scale(const std::string& text) {
  const auto bad = [&] {
    return Error("--scale: expected WxH with W and H whole numbers in [8, 8192] (e.g. 1280x720), got '" + text + "'");
  };
  const std::size_t x = text.find('x');
  if (x == std::string::npos) throw bad();
  try {
    return {parse_int(std::string_view(text).substr(0, x), "--scale", 8, 8192),
            parse_int(std::string_view(text).substr(x + 1), "--scale", 8, 8192)};
  } catch (const Error&) {
    throw bad();
  }
}

}  // namespace

int cmd_bench(const Args& args) {
  const auto parsed = parse_or_print_help(args,
                                          {"--json", "--rounds", "--repeat", "--seed", "--clock", "--floor-target",
                                           "--scale", "--detector-threads", "--thresholds"},
                                          {"--quiet"}, kHelp);
  if (!parsed) return 0;
  const ParsedArgs& a = *parsed;
  if (a.positionals().empty()) throw Error("no PATH given: name at least one image or folder (see --help)");
  peers::RoundsParams rounds;
  rounds.rounds = a.int_or("--rounds", 5, 1, 10000);
  rounds.passes = a.int_or("--repeat", 1, 1, 10000);
  rounds.seed = static_cast<std::uint64_t>(a.int_or("--seed", 1, 0, 2147483647));
  const double floor_target = a.double_or("--floor-target", 1.5, 0.1, 100);
  const std::optional<cv::Size> scale =
      a.has("--scale") ? std::optional<cv::Size>(parse_scale(*a.value("--scale"))) : std::nullopt;
  DetectorParams params;
  Thresholds thresholds;
  const std::optional<std::string> thresholds_path = a.value("--thresholds");
  if (thresholds_path) {
    const ThresholdsFile file = load_thresholds_file(*thresholds_path);
    params = file.detector, thresholds = file.thresholds;
    params.coarse_scale = 1, params.thin_reach = 0;  // one scale: the pass rows add them
  }
  params.threads = a.int_or("--detector-threads", 1, 1, 64);
  const std::string clock = a.value_or("--clock", params.threads == 1 ? "thread-cpu" : "wall");
  if (clock != "thread-cpu" && clock != "wall")
    throw Error("--clock: expected thread-cpu or wall, got '" + clock + "'");
  if (clock == "thread-cpu" && params.threads > 1)
    throw Error("--clock thread-cpu misses the work of --detector-threads' other threads: use --clock wall");
  rounds.clock = clock == "wall" ? peers::Clock::Wall : peers::Clock::ThreadCpu;
  const std::optional<fs::path> json_out = output_path(a, "--json", a.positionals());

  ImageInputs inputs = expand_image_inputs(a.positionals());
  std::vector<FailedImage> failed = std::move(inputs.failed);
  std::vector<cv::Mat> images;
  for (const auto& path : inputs.images) {
    try {
      // Every detector gets the same 8-bit BGR frame, as a robot's camera delivers it.
      cv::Mat bgr = to_bgr8(load_image(path)).clone();
      if (scale) cv::resize(bgr, bgr, *scale, 0, 0, cv::INTER_LINEAR);
      images.push_back(std::move(bgr));
    } catch (const std::exception& e) {
      failed.push_back({path, e.what()});
    }
  }
  for (const auto& f : failed) std::fprintf(stderr, "fieldlines bench: %s\n", f.error.c_str());
  if (images.empty()) throw Error("no image could be loaded, nothing to time");

  // Single thread for everyone: OpenCV would otherwise parallelise some peers and not others.
  const int previous_threads = cv::getNumThreads();
  cv::setNumThreads(1);
  const auto detectors = peers::make_timed_detectors(params, thresholds);
  std::vector<peers::DetectorTimes> times;
  {
    ProgressParams pp;
    if (a.flag("--quiet")) pp.mode = ProgressParams::Mode::Off;
    Progress progress("bench", peers::calls_expected(detectors.size(), images.size(), rounds), stderr, pp);
    times = peers::time_in_both_orders(detectors, images, rounds, [&progress] { progress.advance(); });
  }
  cv::setNumThreads(previous_threads);

  const auto row = [&](const std::string& name) -> const peers::DetectorTimes& {
    return *std::find_if(times.begin(), times.end(), [&](const auto& t) { return t.name == name; });
  };
  const peers::DetectorTimes& ours = times.front();
  const std::string size_note = scale ? cv::format(" scaled to %dx%d", scale->width, scale->height) : "";
  const std::string thread_note =
      params.threads == 1 ? "single thread"
                          : cv::format("single thread (fieldlines and gradients: %d detector threads)", params.threads);
  std::printf("%zu image%s%s x %d round%s x %d pass%s in each order (block, interleaved; seed %llu), %s\n",
              images.size(), images.size() == 1 ? "" : "s", size_note.c_str(), rounds.rounds,
              rounds.rounds == 1 ? "" : "s", rounds.passes, rounds.passes == 1 ? "" : "es",
              static_cast<unsigned long long>(rounds.seed), thread_note.c_str());
  if (thresholds_path) std::printf("fieldlines rows: the detector parameters and thresholds of %s\n", thresholds_path->c_str());
  std::printf("ms: mean call, %s time; ours/this: median over rounds of the round's ratio of summed times; worse: the larger, "
              "[min-max over rounds, order]\n\n",
              peers::clock_name(rounds.clock));
  std::printf("%-20s %9s %11s %13s   %s\n", "", "", "", "", "------------ ours/this ------------");
  std::printf("%-20s %9s %11s %13s   %6s %8s  %s\n", "detector", "block ms", "interl. ms", "segments/img", "block",
              "interl.", "worse [min-max, order]");
  nlohmann::ordered_json detectors_json = nlohmann::ordered_json::array();
  for (const auto& t : times) {
    const double per_image = t.segments / static_cast<double>(images.size());
    const peers::RatioSummary r = peers::ratio_in_both_orders(ours, t);
    const std::vector<double> block = t.pooled(peers::Order::Block), inter = t.pooled(peers::Order::Interleaved);
    std::vector<double> all = block;
    all.insert(all.end(), inter.begin(), inter.end());
    std::printf("%-20s %9.3f %11.3f %13.1f   %6.2f %8.2f  %s\n", t.name.c_str(), peers::mean(block), peers::mean(inter), per_image, r.by_order[0], r.by_order[1], worse_text(r).c_str());
    nlohmann::ordered_json row_json{{"name", t.name}};
    row_json.update(calls_json(all));  // "mean_ms", "median_ms", "p90_ms" over both orders
    row_json["segments_per_image"] = per_image;
    row_json["block"] = calls_json(block);
    row_json["interleaved"] = calls_json(inter);
    row_json["ours_over_this"] = ratio_json(r);
    detectors_json.push_back(std::move(row_json));
  }
  const TargetCheck vs_edlines{"fieldlines/edlines", peers::ratio_in_both_orders(ours, row("edlines")), 0.4};
  const TargetCheck vs_floor{"fieldlines/floor", peers::ratio_in_both_orders(ours, row("floor")), floor_target};
  std::printf("\ntargets, checked on the worse order:\n");
  for (const TargetCheck* t : {&vs_edlines, &vs_floor})
    std::printf("  %s = %s (<= %.2f: %s)\n", t->label.c_str(), worse_text(t->ratio).c_str(), t->limit,
                t->met() ? "met" : "NOT met");
  // A ratio reported beside the targets: "name = worse (block b, interleaved i: what)".
  const auto report = [](const char* name, const peers::RatioSummary& r, const char* what) {
    std::printf("%s = %s (block %.2f, interleaved %.2f: %s)\n", name, worse_text(r).c_str(), r.by_order[0],
                r.by_order[1], what);
  };
  const peers::RatioSummary gradients = peers::ratio_in_both_orders(row("gradients"), row("floor"));
  report("gradients/floor", gradients, "our fused gradient pass against OpenCV's blur + Sobel");
  const peers::RatioSummary junctions = peers::ratio_in_both_orders(row("fieldlines+junctions"), ours);
  report("junctions/fieldlines", junctions, "stripes, field boundary and junctions against none; target <= 1.2");
  const peers::RatioSummary features = peers::ratio_in_both_orders(row("fieldlines+features"), ours);
  report("features/fieldlines", features, "every field feature on against none; target <= 1.2");
  const peers::RatioSummary ground = peers::ratio_in_both_orders(row("fieldlines+ground"), row("fieldlines+features"));
  report("ground/features", ground, "every feature with a camera, on the ground too, against without; target <= 1.1");
  const peers::RatioSummary coarse = peers::ratio_in_both_orders(row("fieldlines+coarse"), ours);
  report("coarse/fieldlines", coarse, "the coarse pass (coarse_scale 3) against one scale; target <= 1.25");
  const peers::RatioSummary thin = peers::ratio_in_both_orders(row("fieldlines+thin"), ours);
  report("thin/fieldlines", thin, "the thin-line pass (thin_reach 2) against one scale; target <= 1.25");
  const peers::RatioSummary scales = peers::ratio_in_both_orders(row("fieldlines+scales"), ours);
  report("scales/fieldlines", scales, "both passes against one scale; target <= 1.25");

  if (json_out) {
    nlohmann::ordered_json j{{"images", images.size()}};
    if (scale) j["scale"] = {{"width", scale->width}, {"height", scale->height}};
    if (thresholds_path) j["thresholds"] = *thresholds_path;
    j["detector_threads"] = params.threads;
    j["rounds"] = rounds.rounds;
    j["passes_per_round"] = rounds.passes;
    j["seed"] = rounds.seed;
    j["clock"] = peers::clock_name(rounds.clock);
    j["detectors"] = detectors_json;
    j["targets"] = {{"edlines", target_json(vs_edlines)}, {"floor", target_json(vs_floor)}};
    j["gradients_over_floor"] = ratio_json(gradients);
    j["junctions_over_plain"] = ratio_json(junctions);
    j["features_over_plain"] = ratio_json(features);
    j["ground_over_features"] = ratio_json(ground);
    j["coarse_over_plain"] = ratio_json(coarse);
    j["thin_over_plain"] = ratio_json(thin);
    j["scales_over_plain"] = ratio_json(scales);
    write_output_file(*json_out, j.dump(2) + "\n");
    std::printf("results written to %s\n", json_out->string().c_str());
  }
  return failed.empty() ? 0 : 1;
}

}  // namespace fieldlines::cli
