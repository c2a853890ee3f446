"""A wrong type anywhere is a projsurf.InputError with one short line naming the argument: never
pybind11's TypeError with its signature dump, never the argument printed whole."""
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import projsurf
from test_projsurf import EXAMPLE_CALIB, wall_and_floor

MAX_LINE = 200  # characters: a message is one readable line whatever the argument's size


@pytest.fixture(scope="module")
def projector():
    return projsurf.read_calibration(EXAMPLE_CALIB)


def one_line(call, starts):
    with pytest.raises(projsurf.InputError) as info:
        call()
    message = str(info.value)
    assert message.startswith(starts), message
    assert "\n" not in message and len(message) <= MAX_LINE, message
    return message


def test_a_big_list_is_named_not_printed(projector):
    # A 480x640 image as a list of lists (the 1.9 MB message): a short line with the hint.
    image = np.zeros((480, 640), dtype=np.uint8).tolist()
    det = projsurf.detect(wall_and_floor(), projector)
    message = one_line(lambda: projsurf.correct(image, projector, det), "image: expected a numpy array, got a list")
    assert "480 items" in message and "numpy.asarray" in message
    one_line(lambda: projsurf.depth_to_cloud(image, fx=1, fy=1, cx=0, cy=0), "depth: expected a numpy array")
    one_line(lambda: projsurf.detect(wall_and_floor(), projector, colour=image), "colour: expected a numpy array")


def test_a_path_where_a_projector_is_expected_says_how_to_read_one():
    cloud = wall_and_floor(64, 48, f=52.5)
    for path in (EXAMPLE_CALIB, pathlib.Path(EXAMPLE_CALIB)):
        message = one_line(lambda: projsurf.detect(cloud, path), "projector: expected a projsurf.Projector, got ")
        assert "read_calibration" in message
    one_line(lambda: projsurf.Detector([1280, 800]), "projector: expected a projsurf.Projector, got a list of 2 items")
    one_line(lambda: projsurf.plan(cloud, None), "projector: expected a projsurf.Projector, got None")
    one_line(lambda: projsurf.keystone(3, {}, (640, 360)), "projector: expected a projsurf.Projector, got an int 3")


def test_paths_may_be_pathlib_paths_and_nothing_else(projector, tmp_path):
    assert projsurf.read_calibration(pathlib.Path(EXAMPLE_CALIB)).width == projector.width
    projsurf.write_calibration(tmp_path / "c.yaml", projector)
    assert projsurf.read_calibration(str(tmp_path / "c.yaml")).height == projector.height
    one_line(lambda: projsurf.read_calibration(42), "path: expected a file path (str or pathlib.Path), got an int 42")
    one_line(lambda: projsurf.read_cloud(None), "path: expected a file path")
    one_line(lambda: projsurf.write_image(b"x.png", np.zeros((2, 2), np.uint8)), "path: expected a file path")


@pytest.mark.parametrize("call, starts", [
    (lambda p: projsurf.Projector(resolution="1280x800"), "resolution: expected two numbers, got a str '1280x800'"),
    (lambda p: projsurf.Projector(resolution=(1280, "800")), "resolution: expected two numbers, got a tuple of 2 items whose item 1 is a str '800'"),
    (lambda p: projsurf.Projector(fov_deg=40), "fov_deg: expected two numbers, got an int 40"),
    (lambda p: projsurf.Projector(origin=[0, 0.1]), "origin: expected three numbers x, y, z, got a list of 2 items"),
    (lambda p: projsurf.Projector(direction="forward"), "direction: expected three numbers"),
    (lambda p: p.to_pixel("here"), "point: expected three numbers"),
    (lambda p: projsurf.detect(wall_and_floor(), p, method=1), "method: expected a str, got an int 1"),
    (lambda p: projsurf.detect(wall_and_floor(), p, hull=3), "hull: expected a str, got an int 3"),
    (lambda p: projsurf.detect(wall_and_floor(), p, seed=-1), "seed: must be a whole number from 0 to 4294967295, got '-1'"),
    (lambda p: projsurf.detect(wall_and_floor(), p, seed=1.5), "seed: must be a whole number from 0 to 4294967295, got '1.5'"),
    (lambda p: projsurf.detect(wall_and_floor(), p, min_width="wide"), "min_width: expected a number >= 0 or None, got a str 'wide'"),
    (lambda p: projsurf.detect(wall_and_floor(), p, gravity={"down": 1}), "gravity: expected three numbers gx, gy, gz, 'gx,gy,gz' or 'auto', got a dict of 1 item"),
    (lambda p: projsurf.detect(wall_and_floor(), p, gravity=np.zeros((100, 100))), "gravity: expected three numbers gx, gy, gz, 'gx,gy,gz' or 'auto', got an array of shape (100, 100) and dtype float64"),
    (lambda p: projsurf.detect(wall_and_floor(), p, aspect=object()), "aspect: expected None, a number, 'W:H' or a pair (W, H), got an object"),
    (lambda p: projsurf.detect(wall_and_floor(), p, suitability=True), "suitability: expected a str, got True"),
    (lambda p: projsurf.plan(wall_and_floor(), p, width="1 m"), "width: expected a number, got a str '1 m'"),
    (lambda p: projsurf.keystone(p, {}, "640x360"), "picture_size: expected two numbers, got a str '640x360'"),
    (lambda p: projsurf.depth_to_cloud(np.zeros((4, 4), np.uint16), fx="525", fy=1, cx=0, cy=0), "fx: expected a number, got a str '525'"),
])
def test_wrong_types_name_the_argument(projector, call, starts):
    one_line(lambda: call(projector), starts)


def test_numpy_scalars_and_lists_of_numbers_are_numbers(projector):
    cloud = wall_and_floor()
    a = projsurf.detect(cloud, projector, aspect=np.float64(16 / 9), seed=np.int64(42), min_width=np.float32(0.1))
    b = projsurf.detect(cloud, projector, aspect=16 / 9, seed=42, min_width=0.1)
    np.testing.assert_array_equal(a["rectangle"]["corners"], b["rectangle"]["corners"])
    p = projsurf.Projector(resolution=np.array([1280, 800]), origin=np.array([0.0, 0.12, 0.0]))
    assert (p.width, p.height) == (1280, 800)


def test_without_numpy_the_import_error_names_the_interpreter():
    # -S: no site-packages, so no numpy (Debian's is in dist-packages); the module must say so.
    module_dir = os.path.dirname(projsurf.__file__)
    probe = subprocess.run([sys.executable, "-S", "-c", "import numpy"], capture_output=True)
    if probe.returncode == 0:
        pytest.skip("numpy is importable without site-packages here")
    r = subprocess.run([sys.executable, "-S", "-c", f"import sys; sys.path.insert(0, {module_dir!r}); import projsurf"],
                       capture_output=True, text=True)
    assert r.returncode != 0
    last = r.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: projsurf needs numpy, which " + sys.executable), last
    assert "python3-numpy" in last
