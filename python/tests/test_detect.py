"""LineDetector.detect: the C++ results segment for segment, every accepted input, threads."""
import json
import subprocess
import threading
import time

import numpy as np
import pytest

import fieldlines

FIELDS = ("x0", "y0", "x1", "y1", "saliency", "grad_x", "grad_y", "label")


def test_module_constants():
    assert fieldlines.LABELS == ("none", "boundary", "marking")
    assert fieldlines.LABELS[fieldlines.LABEL_NONE] == "none"
    assert fieldlines.LABELS[fieldlines.LABEL_BOUNDARY] == "boundary"
    assert fieldlines.LABELS[fieldlines.LABEL_MARKING] == "marking"
    assert fieldlines.SEGMENT_DTYPE.names == FIELDS
    assert fieldlines.SEGMENT_DTYPE["grad_x"].shape == (3,)
    assert fieldlines.SEGMENT_DTYPE["label"] == np.int8


def test_detect_returns_a_structured_array(frame):
    segs = fieldlines.LineDetector().detect(frame)
    assert segs.dtype == fieldlines.SEGMENT_DTYPE and segs.ndim == 1
    labels = {fieldlines.LABELS[code] for code in segs["label"]}
    assert labels == {"marking", "boundary"}, segs
    assert segs["grad_x"].shape == (len(segs), 3)
    # The marking's two edges: green -> white -> green, image-down gradients of opposite signs.
    marking = segs[segs["label"] == fieldlines.LABEL_MARKING]
    assert len(marking) == 2 and np.sign(marking["grad_y"][:, 1]).tolist() in ([1, -1], [-1, 1])


def test_matches_the_cli_segment_for_segment(ssl_images_dir, ssl_images, cli, tmp_path):
    """The 41 authors' images: every field of every segment equal to `fieldlines detect --json`."""
    out = tmp_path / "cli.json"
    subprocess.run([str(cli), "detect", "--quiet", "--json", str(out), str(ssl_images_dir)], check=True)
    cli_images = {entry["image"]: entry for entry in json.loads(out.read_text())["images"]}
    assert len(ssl_images) == 41 and set(cli_images) == {name for name, _ in ssl_images}
    detector = fieldlines.LineDetector()  # one detector for all: buffers reused as in the CLI
    total = 0
    for name, image in ssl_images:
        segs = detector.detect(image)
        expected = cli_images[name]["segments"]
        assert len(segs) == len(expected), name
        for i, (ours, theirs) in enumerate(zip(segs, expected)):
            where = f"{name} segment {i}"
            for field in ("x0", "y0", "x1", "y1", "saliency"):
                # The JSON holds each float's shortest form, which reads back to the same float32.
                assert ours[field] == np.float32(theirs[field]), (where, field)
            for field in ("grad_x", "grad_y"):
                assert ours[field].tolist() == np.float32(theirs[field]).tolist(), (where, field)
            assert fieldlines.LABELS[ours["label"]] == theirs["label"], where
        total += len(segs)
    assert total == 472  # docs/detector.md, "Fidelity": the reference's count


def test_reused_detector_equals_a_fresh_one(frame):
    detector = fieldlines.LineDetector()
    big = np.ascontiguousarray(np.tile(frame, (2, 2, 1)))
    detector.detect(big)
    assert detector.detect(frame).tobytes() == fieldlines.LineDetector().detect(frame).tobytes()


def test_crop_is_read_in_place_and_equals_a_copy(frame):
    crop = frame[30:400, 17:600]
    assert not crop.flags.c_contiguous
    detector = fieldlines.LineDetector()
    assert detector.detect(crop).tobytes() == detector.detect(np.ascontiguousarray(crop)).tobytes()


def test_read_only_input(frame):
    frame.setflags(write=False)
    assert len(fieldlines.LineDetector().detect(frame)) > 0


def test_grey_bgra_and_16_bit_as_in_cpp(frame):
    """docs/detector.md, "Input images": grey replicated, alpha dropped, 16-bit scaled by 1/256."""
    detector = fieldlines.LineDetector()
    bgr = detector.detect(frame)
    bgra = np.dstack([frame, np.full(frame.shape[:2], 255, np.uint8)])
    assert detector.detect(bgra).tobytes() == bgr.tobytes()
    assert detector.detect(frame.astype(np.uint16) * 256 + 100).tobytes() == bgr.tobytes()
    grey = np.ascontiguousarray(frame[:, :, 1])
    as_bgr = np.ascontiguousarray(np.repeat(grey[:, :, None], 3, axis=2))
    assert detector.detect(grey).tobytes() == detector.detect(as_bgr).tobytes()
    assert detector.detect(grey[:, :, None]).tobytes() == detector.detect(as_bgr).tobytes()
    assert fieldlines.LABEL_MARKING not in detector.detect(grey)["label"]


def test_tiny_images_give_no_segments():
    assert len(fieldlines.LineDetector().detect(np.zeros((2, 2, 3), np.uint8))) == 0


def test_same_detector_from_two_threads_is_serialised(frame):
    """Its buffers are shared, so calls take turns; results stay exact."""
    detector = fieldlines.LineDetector()
    expected = detector.detect(frame).tobytes()
    results, errors = [], []

    def work():
        try:
            for _ in range(30):
                results.append(detector.detect(frame).tobytes())
        except Exception as e:  # pragma: no cover - reported below
            errors.append(e)

    threads = [threading.Thread(target=work) for _ in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors and len(results) == 90 and set(results) == {expected}


def test_gil_is_released_during_detect(frame):
    """While one thread detects a large image, another keeps running Python.

    With the GIL held, the main loop below would stall for the whole call; released, its longest
    pause is a small fraction of it (generous bound: the machine may be loaded)."""
    big = np.ascontiguousarray(np.tile(frame, (8, 8, 1)))  # 5120x3840
    detector = fieldlines.LineDetector()
    start = time.perf_counter()
    detector.detect(big)
    duration = time.perf_counter() - start
    worker = threading.Thread(target=lambda: [detector.detect(big) for _ in range(3)])
    longest, last = 0.0, None
    worker.start()
    while worker.is_alive():
        now = time.perf_counter()
        if last is not None:
            longest = max(longest, now - last)
        last = now
    worker.join()
    assert longest < 0.5 * duration, (longest, duration)
