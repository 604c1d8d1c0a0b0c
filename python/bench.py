#!/usr/bin/env python3
"""Per-frame time of LineDetector.detect through Python against `fieldlines bench`, in one run.

Usage:
  PYTHONPATH=build/release/python /usr/bin/python3 python/bench.py \\
      --cli build/release/app/cli/fieldlines ../shared/data/elsed-ssl/images

Three figures, all median ms per 640x480 frame on one OpenCV thread, same images, same run:
  fieldlines bench   its "fieldlines" row (detect + classify) in its block order, wall clock,
                     in a subprocess;
  python detect      det.detect(image) timed around the Python call: argument checks, GIL
                     release and the output array included;
  C++ in process     the same detector's detect() timed inside C++ (LineDetector._time_detect).
Rounds alternate the CLI and this process so that machine load hits both alike; within a round,
whole Python and C++ passes alternate so neither always runs on the cache the other left.
Images are decoded as the CLI decodes them (fieldlines.imread: load_image + to_bgr8). Last, the
binding's fixed cost per call is timed on a 2x2 image, which the detector returns from at once.
The CLI is asked for one round (--rounds 1; the rounds here alternate with Python) on the wall
clock (--clock wall), what time.perf_counter measures here, and its block order is read: there,
as in the loops here, our detector makes all its calls back to back, while its interleaved order
puts the peers (EDLines, FLD, LSD) between them. The CLI is still another process, timed at
other moments on its own copies of the images, so the C++ in-process figure is the one that
isolates the binding.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy

import fieldlines


def image_paths(inputs):
    exts = {".png", ".jpg", ".jpeg", ".bmp", ".tif", ".tiff", ".webp", ".ppm", ".pgm", ".pnm"}
    for item in map(Path, inputs):
        if item.is_dir():
            yield from sorted(p for p in item.iterdir() if p.suffix.lower() in exts and not p.name.startswith("."))
        else:
            yield item


def cli_median_ms(cli, inputs, repeat):
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "bench.json"
        subprocess.run([cli, "bench", "--quiet", "--rounds", "1", "--repeat", str(repeat), "--clock", "wall",
                        "--json", str(out), *inputs],
                       check=True, stdout=subprocess.DEVNULL)
        detectors = json.loads(out.read_text())["detectors"]
    return next(d["block"]["median_ms"] for d in detectors if d["name"] == "fieldlines")


def python_pass(detector, images, python_ms):
    for image in images:
        t0 = time.perf_counter_ns()
        detector.detect(image)
        python_ms.append((time.perf_counter_ns() - t0) / 1e6)


def cpp_pass(detector, images, cpp_ms):
    for image in images:
        cpp_ms.extend(detector._time_detect(image, 1))


def timed_passes(detector, images, repeat, python_ms, cpp_ms):
    """Whole passes, so each call finds the cache as the previous image left it; the order of
    the two alternates, so neither always follows the other."""
    for k in range(repeat):
        if k % 2 == 0:
            python_pass(detector, images, python_ms)
            cpp_pass(detector, images, cpp_ms)
        else:
            cpp_pass(detector, images, cpp_ms)
            python_pass(detector, images, python_ms)


def call_cost_us(detector, calls=20000):
    """The binding's own cost per call: a 2x2 image, which the detector returns from at once."""
    tiny = numpy.zeros((2, 2, 3), numpy.uint8)
    best = []
    for _ in range(5):
        t0 = time.perf_counter_ns()
        for _ in range(calls):
            detector.detect(tiny)
        python = time.perf_counter_ns() - t0
        cpp = 1e6 * sum(detector._time_detect(tiny, calls))
        best.append((python - cpp) / calls / 1000)
    return min(best)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("paths", nargs="+", help="images or folders (as for fieldlines bench)")
    parser.add_argument("--cli", default=os.environ.get("FIELDLINES_CLI", "build/release/app/cli/fieldlines"))
    parser.add_argument("--repeat", type=int, default=5, help="timed passes per round (default 5)")
    parser.add_argument("--rounds", type=int, default=3, help="CLI / Python alternations (default 3)")
    parser.add_argument("--json", help="write the figures here")
    args = parser.parse_args()

    images = [fieldlines.imread(p) for p in image_paths(args.paths)]
    if not images:
        sys.exit("bench.py: no image found")
    fieldlines.set_num_threads(1)  # as fieldlines bench does
    detector = fieldlines.LineDetector()
    timed_passes(detector, images, 1, [], [])  # warm-up, untimed, as the CLI's pass -1

    cli_ms, python_ms, cpp_ms, rounds = [], [], [], []
    for _ in range(args.rounds):
        cli = cli_median_ms(args.cli, args.paths, args.repeat)
        py_round, cpp_round = [], []
        timed_passes(detector, images, args.repeat, py_round, cpp_round)
        cli_ms.append(cli)
        python_ms += py_round
        cpp_ms += cpp_round
        rounds.append({"cli_ms": cli, "python_ms": statistics.median(py_round), "cpp_ms": statistics.median(cpp_round)})

    shapes = sorted({f"{i.shape[1]}x{i.shape[0]}" for i in images})
    result = {
        "images": len(images), "sizes": shapes, "repeat": args.repeat, "rounds": rounds,
        "fieldlines_bench_ms": statistics.median(cli_ms),
        "python_ms": statistics.median(python_ms),
        "cpp_in_process_ms": statistics.median(cpp_ms),
    }
    result["overhead_vs_bench"] = result["python_ms"] / result["fieldlines_bench_ms"] - 1
    result["overhead_vs_cpp_in_process"] = result["python_ms"] / result["cpp_in_process_ms"] - 1
    result["call_cost_us"] = call_cost_us(detector)

    print(f"{len(images)} images ({', '.join(shapes)}), {args.rounds} rounds x {args.repeat} passes, one thread")
    print(f"{'round':>5} {'fieldlines bench':>17} {'python detect':>14} {'C++ in process':>15}  (median ms)")
    for k, r in enumerate(rounds, 1):
        print(f"{k:>5} {r['cli_ms']:>17.3f} {r['python_ms']:>14.3f} {r['cpp_ms']:>15.3f}")
    print(f"{'all':>5} {result['fieldlines_bench_ms']:>17.3f} {result['python_ms']:>14.3f} "
          f"{result['cpp_in_process_ms']:>15.3f}")
    print(f"python / fieldlines bench: {100 * result['overhead_vs_bench']:+.1f} % "
          f"({'met' if result['overhead_vs_bench'] < 0.05 else 'NOT met'}: < 5 %)")
    print(f"python / C++ in process:   {100 * result['overhead_vs_cpp_in_process']:+.1f} % "
          f"(the binding's own cost: {result['call_cost_us']:.2f} us per call)")
    if args.json:
        Path(args.json).write_text(json.dumps(result, indent=2) + "\n")


if __name__ == "__main__":
    main()
