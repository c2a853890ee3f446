"""The Python keyword arguments that go through the shared translation layer (frontend/):
min_width / min_area as `detect --min-width/--min-area`, aspect and gravity as the CLI reads them."""
import os

import numpy as np
import pytest

import projsurf

SOURCE_DIR = os.environ.get("PROJSURF_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLE_CALIB = os.path.join(SOURCE_DIR, "examples", "calib", "example_calib.yaml")


def wall(width=320, height=240, f=262.5, distance=2.0):
    u, v = np.meshgrid(np.arange(width, dtype=np.float64), np.arange(height, dtype=np.float64))
    rays = np.stack([(u - (width - 1) / 2) / f, (v - (height - 1) / 2) / f, np.ones_like(u)], axis=-1)
    return (rays * distance).astype(np.float32)


@pytest.fixture(scope="module")
def projector():
    return projsurf.read_calibration(EXAMPLE_CALIB)


def test_min_width_and_min_area_turn_small_areas_into_not_found(projector):
    found = projsurf.detect(wall(), projector)
    assert found["found"]
    width = found["rectangle"]["width_m"]
    assert width > 0.20  # the defaults let a wall through
    narrow = projsurf.detect(wall(), projector, min_width=width + 0.5)
    assert not narrow["found"]
    assert "is narrower than min_width" in narrow["reason"]
    small = projsurf.Detector(projector, min_area=found["rectangle"]["area_m2"] * 2).detect(wall())
    assert not small["found"]
    assert "is smaller than min_area" in small["reason"]
    with pytest.raises(projsurf.InputError, match="^min_width: expected a number >= 0 or None, got '-1'$"):
        projsurf.detect(wall(), projector, min_width=-1)


def test_aspect_and_gravity_read_as_the_cli_reads_them(projector):
    with pytest.raises(projsurf.InputError, match=r"^aspect: expected a positive aspect ratio W:H, got '16x9' \(write 16:9\)$"):
        projsurf.detect(wall(), projector, aspect="16x9")
    a = projsurf.detect(wall(), projector, aspect=16 / 9)
    b = projsurf.detect(wall(), projector, aspect="16:9")
    np.testing.assert_array_equal(a["rectangle"]["corners"], b["rectangle"]["corners"])
    c = projsurf.detect(wall(), projector, gravity="0,1,0")  # as --gravity 0,1,0
    d = projsurf.detect(wall(), projector, gravity=[0, 1, 0])
    np.testing.assert_array_equal(c["rectangle"]["corners"], d["rectangle"]["corners"])
