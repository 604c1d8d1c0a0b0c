"""LineDetector.features(): the field features of the last detect() with the stages on, named as
`fieldlines detect --json` names them (soccer_vision_2d_msgs)."""
import math

import numpy as np
import pytest

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


CAMERA = {"fx": 640.0, "fy": 640.0, "cx": 319.5, "cy": 239.5, "pitch_deg": 30.0, "roll_deg": 0.0, "height_m": 0.6}


def circle_arc_frame():
    """The far arc of a 0.75 m circle 0.8 m ahead of CAMERA (its image ellipse's centre lies below
    the frame): pixels whose ray meets the turf within the paint's width of the circle."""
    rows, cols = np.mgrid[0:480, 0:640].astype(float)
    pitch = math.radians(CAMERA["pitch_deg"])
    x, y = (cols - CAMERA["cx"]) / CAMERA["fx"], (rows - CAMERA["cy"]) / CAMERA["fy"]
    down = y * math.cos(pitch) + math.sin(pitch)  # the ray's fall per unit along the optical axis
    ahead = math.cos(pitch) - y * math.sin(pitch)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(down > 1e-6, CAMERA["height_m"] / down, np.inf)
    gx, gy = t * ahead, -t * x
    ring = np.abs(np.hypot(gx - 0.8, gy) - 0.75) <= 0.025
    frame = np.empty((480, 640, 3), np.uint8)
    frame[:] = (50, 140, 40)
    frame[ring] = 255
    noise = np.random.default_rng(3).normal(0, 4, frame.shape)
    return np.clip(frame + noise, 0, 255).astype(np.uint8)


def test_the_camera_fits_the_circle_on_the_turf():
    detector = with_features(True)
    assert detector.camera is None
    frame = circle_arc_frame()
    detector.camera = CAMERA
    assert detector.camera == CAMERA
    detector.detect(frame)
    ellipses = detector.features()["ellipses"]
    assert len(ellipses) == 1, ellipses
    assert ellipses[0]["cy"] > 480, "its centre lies below the frame"
    # On the ground: where it was painted, as `detect --camera --json` writes it.
    ground = detector.ground_features()
    assert len(ground["ellipses"]) == 1, ground
    centre = ground["ellipses"][0]["center"]["position"]
    assert abs(centre["x"] - 0.8) < 0.05 and abs(centre["y"]) < 0.05, centre
    assert abs(ground["ellipses"][0]["diameter"] - 1.5) < 0.05
    assert all(s["start"]["x"] > 0 for s in ground["segments"])
    # The camera survives a change of thresholds, and None removes it.
    thresholds = detector.thresholds
    thresholds["detector"]["piece_length"] = 12
    detector.thresholds = thresholds
    assert detector.camera == CAMERA
    detector.camera = None
    assert detector.camera is None
    assert detector.ground_features() is None


def test_a_bad_camera_is_refused_and_the_old_one_kept():
    detector = with_features(True)
    detector.camera = CAMERA
    for bad in ({**CAMERA, "height_m": -1}, {k: v for k, v in CAMERA.items() if k != "fx"},
                {**CAMERA, "pitch_deg": float("nan")}, {**CAMERA, "roll_deg": "level"}, [1, 2]):
        try:
            detector.camera = bad
        except ValueError as e:
            assert "camera" in str(e)
        else:
            raise AssertionError(f"accepted {bad}")
    assert detector.camera == CAMERA


def test_steady_features_hold_the_circle_over_a_missed_frame():
    detector = with_features(True)
    detector.camera = CAMERA
    steady = fieldlines.SteadyFeatures(hold_ms=80)
    frame = circle_arc_frame()
    turf = np.empty_like(frame)
    turf[:] = frame[-1, 0]
    detector.detect(frame)
    assert len(steady.update(detector, 0.0)["ellipses"]) == 1
    detector.detect(turf)
    assert detector.ground_features()["ellipses"] == []
    # Missed 33 ms later, held; the robot stepped 0.1 m ahead, so the circle is 0.1 m nearer.
    held = steady.update(detector, 33.0, motion=(0.1, 0.0, 0.0))["ellipses"]
    assert len(held) == 1
    assert abs(held[0]["center"]["position"]["x"] - 0.7) < 0.05, held
    assert steady.update(detector, 200.0)["ellipses"] == [], "older than the hold"
    with pytest.raises(ValueError):
        fieldlines.SteadyFeatures(smoothing=0)
    with pytest.raises(ValueError):
        steady.update(with_features(True), 300.0)  # no camera
