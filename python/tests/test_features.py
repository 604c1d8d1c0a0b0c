"""LineDetector.features(): the field features of the last detect() with the stages on, named as
`fieldlines detect --json` names them (soccer_vision_2d_msgs)."""
import math

import numpy as np

import fieldlines


def painted_t(width=640, height=480):
    """Turf with a painted T (bar along y = 150..160, stem down from its middle), camera-like noise."""
    frame = np.empty((height, width, 3), np.uint8)
    frame[:] = (50, 140, 40)
    rows = np.arange(height)[:, None]
    cols = np.arange(width)[None, :]
    bar = np.abs(rows - (150 + 20 * (cols - 60) / 530)) <= 4
    stem = (np.abs(cols - (320 + 0.05 * (rows - 160))) <= 4) & (rows >= 150) & (rows <= 440)
    frame[(bar & (cols >= 60) & (cols <= 590)) | stem] = 255
    noise = np.random.default_rng(7).normal(0, 4, frame.shape)
    return np.clip(frame + noise, 0, 255).astype(np.uint8)


def with_features(on):
    thresholds = fieldlines.LineDetector().thresholds
    for stage in ("stripes", "intersections", "centre_circle"):
        thresholds["detector"][stage] = on
    return fieldlines.LineDetector(thresholds)


def test_features_are_empty_with_the_stages_off():
    detector = with_features(False)
    detector.detect(painted_t())
    assert detector.features() == {"markings": [], "intersections": [], "ellipses": [], "field_boundary": []}


def test_a_t_junction_and_the_markings():
    detector = with_features(True)
    detector.detect(painted_t())
    f = detector.features()
    assert set(f) == {"markings", "intersections", "ellipses", "field_boundary"}
    assert f["markings"] and set(f["markings"][0]) == {"x0", "y0", "x1", "y1", "width"}
    assert len(f["intersections"]) == 1, f["intersections"]
    j = f["intersections"][0]
    assert list(j) == ["x", "y", "type", "num_rays", "heading_rays", "confidence"]
    assert j["type"] == "T" and j["num_rays"] == 3
    assert abs(j["x"] - 320) < 8 and abs(j["y"] - 160) < 8
    rays = j["heading_rays"]
    assert rays == sorted(rays) and all(0 <= r < 2 * math.pi for r in rays)
    # Left, down (pi/2 is image down) and right.
    for want in (math.pi, math.pi / 2, 0):
        assert min(abs(math.remainder(r - want, 2 * math.pi)) for r in rays) < 0.1, rays
    assert 0 < j["confidence"] <= 1
    assert f["ellipses"] == []
    assert f["field_boundary"], "the boundary comes with the feature stages"
