"""projsurf.Tracker: continuous mode from Python, as the node's ~continuous keeps the picture put."""
import numpy as np
import pytest

import projsurf

from test_projsurf import EXAMPLE_CALIB, wall_and_floor


@pytest.fixture(scope="module")
def projector():
    return projsurf.read_calibration(EXAMPLE_CALIB)


def noisy(cloud, rng, sigma=0.005):
    return (cloud + rng.normal(0.0, sigma, cloud.shape)).astype(np.float32)


def spread(corners):
    """Largest distance of any frame's corners from the first frame's, m."""
    first = corners[0]
    return max(float(np.max(np.linalg.norm(c - first, axis=1))) for c in corners)


def test_a_still_robot_keeps_the_picture_while_the_noisy_detection_moves(projector):
    rng = np.random.default_rng(11)
    tracker = projsurf.Tracker(projector, aspect="16:9")
    frames = [tracker.update(noisy(wall_and_floor(), rng)) for _ in range(6)]
    assert [f["event"] for f in frames] == ["acquired"] + ["kept"] * 5
    assert all(f["found"] for f in frames)
    raw = [f["rectangle"]["corners"] for f in frames]
    shown = [f["shown"]["corners"] for f in frames]
    assert shown[0].shape == (4, 3) and shown[0].dtype == np.float64
    # Steady: the shown rectangle moves less than the raw detection, and by millimetres at most.
    assert spread(shown) < 0.005
    assert spread(shown) < spread(raw)
    # Smaller than the detection (steady scale), on the same wall.
    assert frames[0]["shown"]["width_m"] < frames[0]["rectangle"]["width_m"]
    np.testing.assert_allclose(shown[0][:, 2], raw[0][:, 2], atol=0.02)


def test_a_moving_camera_sees_the_picture_stay_put_on_the_wall(projector):
    tracker = projsurf.Tracker(projector, aspect="16:9")
    cloud = wall_and_floor()  # a wall wider than the view: the same cloud after a move along it
    first = tracker.update(cloud)
    pose = np.eye(4)
    pose[0, 3] = 0.05  # the camera drove 5 cm to its right
    moved = tracker.update(cloud, camera_pose=pose)
    assert moved["event"] == "kept"
    np.testing.assert_allclose(moved["rectangle"]["corners"], first["rectangle"]["corners"])
    # The raw detection did not move in the camera frame; the picture moved 5 cm left in it.
    np.testing.assert_allclose(moved["shown"]["corners"] - first["shown"]["corners"],
                               np.tile([-0.05, 0.0, 0.0], (4, 1)), atol=1e-6)


def test_nothing_found_shows_nothing_and_reset_forgets(projector):
    tracker = projsurf.Tracker(projector)
    floor_only = wall_and_floor(wall=1e6)
    floor_only[floor_only[..., 2] > 6.0] = np.nan  # no wall within what the camera reads
    nothing = tracker.update(floor_only)
    assert nothing["found"] is False and nothing["shown"] is None and nothing["event"] == "none"
    assert tracker.update(wall_and_floor())["event"] == "acquired"
    tracker.reset()
    assert tracker.update(wall_and_floor())["event"] == "acquired"
    assert tracker.projector.width == projector.width


@pytest.mark.parametrize("pose, message", [
    (np.eye(3), "camera_pose: expected a 4x4 array"),
    ("identity", "camera_pose: expected a 4x4 array"),
    (np.full((4, 4), np.nan), "camera_pose: holds a value that is not finite"),
    (np.diag([2.0, 1.0, 1.0, 1.0]), "camera_pose: its top-left 3x3 is not a rotation"),
    (np.vstack([np.eye(4)[:3], [0, 0, 1, 1]]), "camera_pose: its last row must be 0 0 0 1"),
])
def test_a_bad_camera_pose_is_an_input_error(projector, pose, message):
    tracker = projsurf.Tracker(projector)
    with pytest.raises(projsurf.InputError, match=message):
        tracker.update(wall_and_floor(), camera_pose=pose)


def test_settings_belong_to_the_constructor_and_are_checked_there(projector):
    with pytest.raises(projsurf.InputError, match="method"):
        projsurf.Tracker(projector, method="best")
    with pytest.raises(projsurf.InputError, match="aspect: unknown keyword argument"):
        projsurf.Tracker(projector).update(wall_and_floor(), aspect="16:9")
    with pytest.raises(projsurf.InputError, match="projector: expected a projsurf.Projector"):
        projsurf.Tracker("calib.yaml")
