"""Shared fixtures. ctest sets the environment (python/CMakeLists.txt):
FIELDLINES_CLI the `fieldlines` binary, FIELDLINES_SHARED_DIR the authors' data, FIELDLINES_SOURCE_DIR,
FIELDLINES_BUILD_DIR and FIELDLINES_PYTHON_INSTALL_DIR. What is missing skips with a message, or fails
under CI (CI=true), the rule of tests/shared_data.hpp."""
import os
from pathlib import Path

import numpy as np
import pytest

import fieldlines

SOURCE_DIR = Path(os.environ.get("FIELDLINES_SOURCE_DIR", Path(__file__).resolve().parents[2]))


def require(what, path):
    """`path` if it exists; otherwise fail under CI, skip elsewhere."""
    if path is not None and Path(path).exists():
        return Path(path)
    message = f"{what} not found at {path}"
    if os.environ.get("CI") == "true":
        pytest.fail(f"{message} (required under CI)")
    pytest.skip(f"{message}; set it to run this test")


@pytest.fixture(scope="session")
def ssl_images_dir():
    shared = Path(os.environ.get("FIELDLINES_SHARED_DIR", SOURCE_DIR.parent / "shared"))
    return require("shared data (FIELDLINES_SHARED_DIR)", shared / "data" / "elsed-ssl" / "images")


@pytest.fixture(scope="session")
def ssl_images(ssl_images_dir):
    """(file name, BGR image) for the 41 authors' SSL images, decoded as the CLI decodes them."""
    paths = sorted(p for p in ssl_images_dir.iterdir() if p.suffix.lower() == ".png")
    return [(p.name, fieldlines.imread(p)) for p in paths]


@pytest.fixture(scope="session")
def cli():
    return require("the fieldlines CLI (FIELDLINES_CLI)", os.environ.get("FIELDLINES_CLI"))


@pytest.fixture
def frame():
    """A 640x480 BGR field: green carpet, a slightly tilted white line, a black wall at the top."""
    image = np.zeros((480, 640, 3), np.uint8)
    image[:] = (40, 140, 40)
    rows = np.arange(480)[:, None]
    cols = np.arange(640)[None, :]
    image[np.abs(rows - (240 + 0.05 * cols)) < 4] = (235, 235, 235)
    # Tilted so that the edges cross the detector's anchor grid (docs/detector.md, "Fidelity").
    image[rows < 40 + 0.07 * cols] = (10, 10, 10)
    return image
