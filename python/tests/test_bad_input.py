"""Bad input raises ValueError / OSError / TypeError with the reason, never crashes."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import fieldlines


@pytest.fixture(scope="module")
def detector():
    return fieldlines.LineDetector()


IMAGE = np.zeros((48, 64, 3), np.uint8)


@pytest.mark.parametrize(
    "image, reason",
    [
        (IMAGE.astype(np.float32), "unsupported dtype float32"),
        (IMAGE.astype(np.float64), "unsupported dtype float64"),
        (IMAGE.astype(np.int16), "unsupported dtype int16"),
        (IMAGE.astype(np.int8), "unsupported dtype int8"),
        (IMAGE.astype(bool), "unsupported dtype bool"),
        (IMAGE.astype(">u2"), "non-native byte order"),
        (np.zeros((48, 64, 2), np.uint8), "unsupported channel count 2"),
        (np.zeros((48, 64, 5), np.uint8), "unsupported channel count 5"),
        (np.zeros(64, np.uint8), "expected HxW"),
        (np.zeros((2, 48, 64, 3), np.uint8), "expected HxW"),
        (np.zeros((0, 0, 3), np.uint8), "empty image"),
        (np.zeros((0, 64, 3), np.uint8), "empty image"),
        (np.zeros((48, 0), np.uint8), "empty image"),
        (IMAGE[:, ::2], "unsupported memory layout"),  # subsampled columns
        (IMAGE[::-1], "unsupported memory layout"),  # rows in reverse
        (IMAGE[:, :, ::-1], "unsupported memory layout"),  # RGB view of BGR
        (IMAGE.transpose(1, 0, 2), "unsupported memory layout"),
        (np.asfortranarray(IMAGE), "unsupported memory layout"),
        (np.broadcast_to(IMAGE[:1], IMAGE.shape), "unsupported memory layout"),
    ],
)
def test_bad_images_raise_value_error(detector, image, reason):
    with pytest.raises(ValueError, match=reason):
        detector.detect(image)


def test_layout_error_names_the_fix(detector):
    with pytest.raises(ValueError, match="numpy.ascontiguousarray"):
        detector.detect(IMAGE[..., ::-1])


def test_no_image_at_all_is_a_type_error(detector):
    with pytest.raises(TypeError):
        detector.detect(None)
    with pytest.raises(TypeError):
        detector.detect([[1.5, 2.5], [3.5, 4.5]])  # a list is not an image
    with pytest.raises(TypeError):
        detector.detect()


def test_detector_still_works_after_errors(detector, frame):
    for bad in (IMAGE.astype(np.float32), np.zeros((0, 0, 3), np.uint8), IMAGE[:, ::2]):
        with pytest.raises(ValueError):
            detector.detect(bad)
    assert len(detector.detect(frame)) > 0


def write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    return path


def default_dict():
    return fieldlines.LineDetector().thresholds


def test_missing_thresholds_file_is_file_not_found(tmp_path):
    for call in (fieldlines.load_thresholds_file, fieldlines.LineDetector.from_thresholds_file):
        with pytest.raises(FileNotFoundError, match="robot.json"):
            call(tmp_path / "robot.json")


def test_thresholds_file_that_is_a_folder_is_os_error(tmp_path):
    with pytest.raises(IsADirectoryError):
        fieldlines.load_thresholds_file(tmp_path)


UNREADABLE_CHECK = """
import sys, fieldlines
try:
    fieldlines.load_thresholds_file(sys.argv[1])
except PermissionError as e:
    print("PermissionError:", e)
    sys.exit(0)
sys.exit(1)
"""


def test_unreadable_thresholds_file_is_permission_error(tmp_path):
    path = write(tmp_path, "robot.json", json.dumps(default_dict()))
    path.chmod(0)
    if os.geteuid() != 0:
        with pytest.raises(PermissionError, match="robot.json"):
            fieldlines.load_thresholds_file(path)
        return
    # Root reads every file through CAP_DAC_OVERRIDE: the check runs in a child that is still
    # root (so it reaches the module wherever the build is) but without the capabilities that
    # bypass file modes (setpriv is util-linux's, on every Debian).
    run = subprocess.run(["setpriv", "--bounding-set=-dac_override,-dac_read_search", sys.executable, "-c",
                          UNREADABLE_CHECK, str(path)], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "robot.json" in run.stdout


@pytest.mark.parametrize(
    "text, reason",
    [
        ("", "robot.json"),
        ("{not json", "robot.json"),
        ("[]", "robot.json"),
        ('{"format": "something-else", "version": 1}', "robot.json"),
        ('{"format": "fieldlines-thresholds", "version": 99}', "robot.json"),
        ('{"format": "fieldlines-thresholds", "version": 1}', "detector"),
    ],
)
def test_malformed_thresholds_file_is_value_error(tmp_path, text, reason):
    path = write(tmp_path, "robot.json", text)
    for call in (fieldlines.load_thresholds_file, fieldlines.LineDetector.from_thresholds_file):
        with pytest.raises(ValueError, match=reason):
            call(path)


def test_out_of_range_values_are_named(tmp_path):
    bad = default_dict()
    bad["detector"]["gaussian_kernel"] = 4
    with pytest.raises(ValueError, match="gaussian_kernel"):
        fieldlines.load_thresholds_file(write(tmp_path, "robot.json", json.dumps(bad)))
    with pytest.raises(ValueError, match="gaussian_kernel"):
        fieldlines.LineDetector(bad)
    bad = default_dict()
    bad["classes"]["marking"]["max_angle_deg"] = 400
    with pytest.raises(ValueError, match="max_angle"):
        fieldlines.save_thresholds_file(tmp_path / "out.json", bad)
    assert not (tmp_path / "out.json").exists()


@pytest.mark.parametrize("value", [float("nan"), float("inf"), object()])
def test_dicts_that_are_not_json_are_value_errors(tmp_path, value):
    bad = default_dict()
    bad["classes"]["marking"]["min_length"] = value
    with pytest.raises(ValueError, match="not JSON data"):
        fieldlines.LineDetector(bad)
    with pytest.raises(ValueError, match="not JSON data"):
        fieldlines.save_thresholds_file(tmp_path / "out.json", bad)


def test_thresholds_that_are_not_a_dict(detector):
    with pytest.raises(ValueError, match="expected a dict"):
        fieldlines.LineDetector("robot.json")  # a path belongs to from_thresholds_file
    with pytest.raises(ValueError, match="expected a dict"):
        detector.thresholds = 3


def test_unwritable_thresholds_file_is_os_error(tmp_path):
    with pytest.raises(OSError):
        fieldlines.save_thresholds_file(tmp_path / "no" / "such" / "folder" / "robot.json", default_dict())


def test_classify_refuses_other_arrays():
    with pytest.raises(ValueError, match="SEGMENT_DTYPE"):
        fieldlines.classify(np.zeros((3, 14), np.float32))
    with pytest.raises(ValueError, match="SEGMENT_DTYPE"):
        fieldlines.classify([1, 2, 3])
    with pytest.raises(ValueError, match="1-D"):
        fieldlines.classify(np.zeros((2, 2), fieldlines.SEGMENT_DTYPE))


def test_calibrate_bad_input(frame):
    with pytest.raises(TypeError, match="one array"):
        fieldlines.calibrate(frame)
    with pytest.raises(TypeError, match="images\\[1\\]"):
        fieldlines.calibrate([frame, "frame.png"])
    with pytest.raises(ValueError, match="images\\[1\\]: unsupported dtype float32"):
        fieldlines.calibrate([frame, frame.astype(np.float32)])
    with pytest.raises(TypeError):
        fieldlines.calibrate(42)


def test_calibration_refusal_is_a_value_error_with_the_reason(frame):
    with pytest.raises(ValueError, match="calibration refused: .*segments"):
        fieldlines.calibrate([frame] * 3)
    with pytest.raises(ValueError, match="calibration refused"):
        fieldlines.calibrate([])


def test_imread_errors(tmp_path):
    with pytest.raises(FileNotFoundError):
        fieldlines.imread(tmp_path / "missing.png")
    with pytest.raises(ValueError, match="bad.png"):
        fieldlines.imread(write(tmp_path, "bad.png", "not an image"))
