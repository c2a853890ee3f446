"""Hostile arguments to the Python module: every one a short projsurf.InputError (one line,
naming the argument), never a crash, a MemoryError or pybind11's TypeError listing every
signature. Run by ctest (python_tests) with the other module tests."""
import math

import numpy as np
import pytest

import projsurf
from test_projsurf import EXAMPLE_CALIB, wall_and_floor


@pytest.fixture(scope="module")
def projector():
    return projsurf.read_calibration(EXAMPLE_CALIB)


@pytest.fixture(scope="module")
def detection(projector):
    det = projsurf.detect(wall_and_floor(), projector)
    assert det["found"], det["reason"]
    return det


def one_line(error):
    text = str(error.value)
    assert "\n" not in text, text
    return text


def test_huge_broadcast_images_are_refused_before_any_copy(projector, detection, tmp_path):
    # 2^20 x 2^20 x 3 bytes (3 TiB) of one element: the contiguous copy used to fail into a null image.
    huge = np.broadcast_to(np.uint8(1), (2 ** 20, 2 ** 20, 3))
    with pytest.raises(projsurf.InputError) as info:
        projsurf.correct(huge, projector, detection)
    assert one_line(info).startswith("image: ")
    with pytest.raises(projsurf.InputError) as info:
        projsurf.write_image(str(tmp_path / "h.png"), huge)
    assert one_line(info).startswith("image: ")
    assert not (tmp_path / "h.png").exists()
    with pytest.raises(projsurf.InputError) as info:
        projsurf.depth_to_cloud(np.broadcast_to(np.uint16(1000), (2 ** 20, 2 ** 20)), fx=525, fy=525, cx=320, cy=240)
    assert one_line(info).startswith("depth: ")


def test_clouds_beyond_the_point_limit_are_refused(projector):
    with pytest.raises(projsurf.InputError) as info:
        projsurf.detect(np.broadcast_to(np.float32(1), (2 ** 40, 3)), projector)
    assert one_line(info).startswith("points: ")
    # One point over the limit of 2^24.
    with pytest.raises(projsurf.InputError) as info:
        projsurf.detect(np.broadcast_to(np.float32(1), (2 ** 24 + 1, 3)), projector)
    assert "16777216" in one_line(info)


@pytest.mark.parametrize("kwargs, start", [
    (dict(resolution="1280x800"), "resolution: expected two numbers"),
    (dict(resolution=(1280.5, 800)), "resolution: must be two whole numbers"),
    (dict(fov_deg=None), "fov_deg: expected two numbers"),
    (dict(origin="here"), "origin: expected three numbers"),
    (dict(direction=[0, 1]), "direction: expected three numbers"),
    # Values the calibration reader refuses in a file: the same rules here.
    (dict(fov_deg=(0.6, 0.4)), "Projector: projector.fov_deg [0.6, 0.4] looks like radians"),
    (dict(origin=[1e300, 0, 0]), "Projector: projector.axis.origin is more than 3 m"),
    (dict(origin=[math.nan, 0, 0]), "origin: is not finite"),
    (dict(resolution=(16384, 16384)), "resolution: exceeds the limit of 33554432 framebuffer pixels"),
])
def test_projector_arguments_are_checked_as_in_a_calibration_file(kwargs, start):
    with pytest.raises(projsurf.InputError) as info:
        projsurf.Projector(**kwargs)
    assert one_line(info).startswith(start)


def test_wrong_types_are_short_input_errors(projector, detection):
    cloud = wall_and_floor(64, 48, f=52.5)
    picture = np.zeros((10, 10, 3), np.uint8)
    cases = [
        (lambda: projsurf.detect(cloud, "projector"), "projector: expected a projsurf.Projector"),
        (lambda: projsurf.detect(cloud, projector, seed=-1), "seed: must be a whole number"),
        (lambda: projsurf.detect(cloud, projector, method=3), "method: expected a str"),
        (lambda: projsurf.Detector("projector"), "projector: expected a projsurf.Projector"),
        (lambda: projsurf.keystone(projector, detection, "640x480"), "picture_size: expected two numbers"),
        (lambda: projsurf.keystone(projector, detection, (640, 480), tolerance_px="2"), "tolerance_px: expected a number"),
        (lambda: projsurf.correct("picture", projector, detection), "image: expected a numpy array"),
        (lambda: projsurf.correct(picture, 1280, detection), "projector: expected a projsurf.Projector"),
        (lambda: projsurf.plan(cloud, projector, width="wide"), "width: expected a number"),
        (lambda: projsurf.depth_to_cloud(np.zeros((4, 4), np.uint16), fx="525", fy=525, cx=2, cy=2), "fx: expected a number"),
        (lambda: projsurf.read_image(3), "path: expected a file path"),
        (lambda: projsurf.write_image(None, picture), "path: expected a file path"),
    ]
    for call, start in cases:
        with pytest.raises(projsurf.InputError) as info:
            call()
        assert one_line(info).startswith(start), (start, str(info.value))


def test_tolerance_that_is_not_a_number_is_refused(projector, detection):
    for bad in (math.nan, -1.0, math.inf):
        with pytest.raises(projsurf.InputError) as info:
            projsurf.correct(np.zeros((48, 64, 3), np.uint8), projector, detection, tolerance_px=bad)
        assert "tolerance_px" in one_line(info)


def test_a_path_with_a_nul_is_refused_not_cut_short(tmp_path, monkeypatch):
    # The C library ends a name at its NUL: 'a\0b.png' used to write a file called 'a'.
    monkeypatch.chdir(tmp_path)
    with pytest.raises(projsurf.InputError) as info:
        projsurf.write_image("a\0b.png", np.zeros((4, 4), np.uint8))
    assert one_line(info).startswith("path: ")
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(projsurf.InputError):
        projsurf.read_calibration("calib\0.yaml")


def test_messages_quoting_bytes_that_are_not_utf8_stay_one_readable_line(projector, tmp_path):
    # A settings file's word is quoted in the message: Python could not decode the raw bytes.
    bad = tmp_path / "bad.yaml"
    bad.write_bytes(b"method: \xff\xfe\n")
    with pytest.raises(projsurf.InputError) as info:
        projsurf.detect(wall_and_floor(64, 48, f=52.5), projector, config=str(bad))
    assert "\\xFF\\xFE" in one_line(info)


def test_arguments_matching_no_signature_are_one_line(projector):
    # pybind11's TypeError listed every signature on many lines (issue 39).
    cloud = wall_and_floor(64, 48, f=52.5)
    with pytest.raises(projsurf.InputError) as info:
        projsurf.plan(cloud, projector, bogus=1)
    assert one_line(info).startswith("plan: unknown keyword argument 'bogus' (known: points, projector")
    with pytest.raises(projsurf.InputError) as info:
        projsurf.print_config("x.yaml")
    assert one_line(info).startswith("print_config: takes 0 positional argument(s), got 1")
    with pytest.raises(projsurf.InputError) as info:
        projsurf.Tracker(projector, 1, 2)
    assert one_line(info).startswith("Tracker: takes 1 positional argument(s), got 3")
    # What matches still runs, and the functions keep their names and help.
    assert projsurf.plan.__name__ == "plan" and "Raises" in projsurf.plan.__doc__
    assert projsurf.print_config().startswith("# projsurf detector settings")


def test_a_camera_pose_beyond_any_map_is_refused(projector):
    pose = np.eye(4)
    pose[0, 3] = 1e300
    tracker = projsurf.Tracker(projector)
    with pytest.raises(projsurf.InputError) as info:
        tracker.update(wall_and_floor(64, 48, f=52.5), camera_pose=pose)
    assert one_line(info).startswith("camera_pose: puts the camera more than 100000 m")


def test_a_latin1_key_in_a_calibration_warns_in_readable_utf8(tmp_path):
    calib = tmp_path / "c.yaml"
    calib.write_bytes(open(EXAMPLE_CALIB, "rb").read() + b"  distorsi\xf3n: [0, 0, 0, 0, 0]\n")
    with pytest.warns(UserWarning) as warned:
        projsurf.read_calibration(str(calib))  # raised UnicodeDecodeError
    assert any("distorsi\\xF3n" in str(w.message) for w in warned)
