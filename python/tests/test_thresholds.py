"""Thresholds dicts: file round trip, detectors built from them, classify, calibrate."""
import json
import subprocess

import numpy as np

import fieldlines
from conftest import SOURCE_DIR

DEFAULTS = SOURCE_DIR / "assets" / "default_thresholds.json"


def test_thresholds_file_round_trip(tmp_path):
    """load -> dict -> save gives the same bytes the C++ writer wrote, and loads back equal."""
    loaded = fieldlines.load_thresholds_file(DEFAULTS)
    assert loaded["format"] == "fieldlines-thresholds" and loaded["version"] == 1
    out = tmp_path / "robot.json"
    fieldlines.save_thresholds_file(out, loaded)
    assert out.read_bytes() == DEFAULTS.read_bytes()
    assert fieldlines.load_thresholds_file(str(out)) == loaded  # str or path-like


def test_defaults_are_the_authors(frame):
    built_in, shipped = fieldlines.LineDetector().thresholds, fieldlines.load_thresholds_file(DEFAULTS)
    assert built_in.pop("provenance") == {} and shipped.pop("provenance")["source"]
    assert built_in == shipped
    from_file = fieldlines.LineDetector.from_thresholds_file(DEFAULTS)
    assert from_file.detect(frame).tobytes() == fieldlines.LineDetector().detect(frame).tobytes()


def test_edited_dict_reaches_the_detector(tmp_path, frame):
    t = fieldlines.load_thresholds_file(DEFAULTS)
    t["classes"]["marking"]["min_length"] = np.float32(10000)  # NumPy values are accepted
    t["provenance"] = {"note": "no markings"}
    out = tmp_path / "robot.json"
    fieldlines.save_thresholds_file(out, t)
    detector = fieldlines.LineDetector.from_thresholds_file(out)
    assert detector.thresholds["provenance"] == {"note": "no markings"}
    assert detector.thresholds["classes"]["marking"]["min_length"] == 10000
    assert fieldlines.LABEL_MARKING not in detector.detect(frame)["label"]
    assert fieldlines.LABEL_MARKING in fieldlines.LineDetector().detect(frame)["label"]


def test_thresholds_setter(frame):
    detector = fieldlines.LineDetector()
    before = detector.detect(frame)
    t = detector.thresholds
    t["classes"]["boundary"]["min_length"] = 10000
    detector.thresholds = t  # same detector parameters: only the labels change
    after = detector.detect(frame)
    assert fieldlines.LABEL_BOUNDARY in before["label"] and fieldlines.LABEL_BOUNDARY not in after["label"]
    assert after[["x0", "y0", "x1", "y1"]].tolist() == before[["x0", "y0", "x1", "y1"]].tolist()
    t["detector"]["min_line_length"] = 1000  # new detector parameters: a new engine
    detector.thresholds = t
    assert len(detector.detect(frame)) == 0


def test_classify_equals_the_detectors_labels(frame):
    segs = fieldlines.LineDetector().detect(frame)
    assert fieldlines.classify(segs).tolist() == segs["label"].tolist()
    assert fieldlines.classify(segs[::-1]).tolist() == segs["label"][::-1].tolist()
    strict = fieldlines.load_thresholds_file(DEFAULTS)
    strict["classes"]["marking"]["min_length"] = 10000
    labels = fieldlines.classify(segs, strict)
    assert labels.dtype == np.int8 and fieldlines.LABEL_MARKING not in labels
    assert fieldlines.classify(segs[:0]).tolist() == []


def test_calibrate_equals_the_cli(ssl_images_dir, ssl_images, cli, tmp_path):
    """fieldlines.calibrate(images) gives the classes and detector of `fieldlines calibrate DIR`."""
    out = tmp_path / "cli.json"
    subprocess.run([str(cli), "calibrate", "--quiet", str(ssl_images_dir), "-o", str(out)], check=True)
    theirs = json.loads(out.read_text())
    ours = fieldlines.calibrate([image for _, image in ssl_images])
    for key in ("format", "version", "detector", "classes", "gradient_mode", "reference_pi", "light", "field_boundary"):
        assert ours[key] == theirs[key], key
    assert ours["light"]["adapt"] is True  # every SSL frame shows the carpet
    assert ours["provenance"]["method"] == "label-free"
    # The segments above each frame's field boundary are left out of the fit, as the CLI does.
    counts = theirs["provenance"]["counts"]
    assert ours["provenance"]["counts"] == {"images": 41, "segments": counts["segments"], "frames_with_field_colour": 41}
    assert 100 < counts["segments"]
    # The venue's detector: ELSED's finer anchor grid, with the stripes stage on.
    assert ours["detector"]["scan_interval"] == 2 and ours["detector"]["stripes"] is True
    assert ours["provenance"]["detector"] == theirs["provenance"]["detector"]
    # The widest stripe from the frames' own stripes, recorded where it came from.
    assert ours["detector"]["stripe_max_width"] == ours["provenance"]["detector"]["stripe_max_width"] <= 0.15
    # The result is an ordinary thresholds dict: a detector takes it, and it saves.
    fieldlines.LineDetector(ours).detect(ssl_images[0][1])
    fieldlines.save_thresholds_file(tmp_path / "robot.json", ours)
    # keep_detector: the given detector parameters (here the built-in ones), as --keep-detector.
    kept = fieldlines.calibrate([image for _, image in ssl_images], keep_detector=True)
    assert kept["detector"] == fieldlines.load_thresholds_file(DEFAULTS)["detector"]
    assert kept["provenance"]["detector"] == {"calibrated": False}
    assert 100 < kept["provenance"]["counts"]["segments"] < 472  # of the method's 472, those below the boundary
