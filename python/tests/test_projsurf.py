"""The Python module against the C++ library and the CLI: same detections, same framebuffers,
same one-line error messages. Run by ctest (python_tests), which puts the built module on
PYTHONPATH and names the CLI in PROJSURF_CLI."""
import json
import math
import os
import re
import subprocess
import sys

import numpy as np
import pytest

import projsurf

SOURCE_DIR = os.environ.get("PROJSURF_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLE_CALIB = os.path.join(SOURCE_DIR, "examples", "calib", "example_calib.yaml")
CLI = os.environ.get("PROJSURF_CLI", "projsurf")


def wall_and_floor(width=640, height=480, f=525.0, wall=2.5, camera_height=0.8, pitch_deg=0.0):
    """An organized (H, W, 3) float32 cloud: a depth camera `camera_height` m above the floor,
    `wall` m from a wall, pitched down by `pitch_deg` (camera frame: x right, y down, z forward)."""
    u, v = np.meshgrid(np.arange(width, dtype=np.float64), np.arange(height, dtype=np.float64))
    rays = np.stack([(u - (width - 1) / 2) / f, (v - (height - 1) / 2) / f, np.ones_like(u)], axis=-1)
    p = math.radians(pitch_deg)
    # World (level) directions of the camera's rays: the camera looks down by `pitch`.
    to_world = np.array([[1, 0, 0], [0, math.cos(p), math.sin(p)], [0, -math.sin(p), math.cos(p)]])
    world = rays @ to_world.T
    with np.errstate(divide="ignore", invalid="ignore"):
        t_wall = wall / world[..., 2]
        t_floor = np.where(world[..., 1] > 0, camera_height / world[..., 1], np.inf)
    t = np.minimum(t_wall, t_floor)
    return (rays * t[..., None]).astype(np.float32)


def run_cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True, timeout=120)


def write_pcd(path, cloud):
    h, w = cloud.shape[:2]
    with open(path, "w") as f:
        f.write(f"VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH {w}\nHEIGHT {h}\n"
                f"VIEWPOINT 0 0 0 1 0 0 0\nPOINTS {w * h}\nDATA ascii\n")
        np.savetxt(f, cloud.reshape(-1, 3), fmt="%.9g")


@pytest.fixture(scope="module")
def projector():
    return projsurf.read_calibration(EXAMPLE_CALIB)


def test_read_calibration_gives_the_example_projector(projector):
    assert (projector.width, projector.height) == (1280, 800)
    assert projector.fov_deg == pytest.approx((39.3, 24.0))
    np.testing.assert_allclose(projector.origin, [0.0, 0.12, 0.0])
    np.testing.assert_allclose(projector.direction, np.array([0.0, -0.05, 1.0]) / math.hypot(0.05, 1.0))
    # Keyword construction with the same values is the same projector.
    other = projsurf.Projector()
    assert (other.width, other.height) == (projector.width, projector.height)
    assert other.fov_deg == pytest.approx(projector.fov_deg, abs=1e-9)
    np.testing.assert_allclose(other.origin, projector.origin)
    np.testing.assert_allclose(other.direction, projector.direction)
    assert projector.to_pixel([0.0, 0.0, -1.0]) is None  # behind the lens
    u, v = projector.to_pixel(projector.origin + 2.0 * projector.direction)
    assert (u, v) == pytest.approx(((1280 - 1) / 2, (800 - 1) / 2))


def test_errors_are_input_errors_with_the_clis_line(tmp_path):
    missing = str(tmp_path / "missing.yaml")
    with pytest.raises(projsurf.InputError) as info:
        projsurf.read_calibration(missing)
    assert isinstance(info.value, ValueError)
    cloud = tmp_path / "c.pcd"
    write_pcd(cloud, wall_and_floor(64, 48, f=52.5))
    cli = run_cli("detect", "--cloud", str(cloud), "--calib", missing)
    assert cli.returncode == 2
    assert cli.stderr == f"projsurf: error: {info.value}\n"
    # A malformed calibration: the same line too.
    bad = tmp_path / "bad.yaml"
    bad.write_text("projector:\n  resolution: [1280]\n")
    with pytest.raises(projsurf.InputError) as info:
        projsurf.read_calibration(str(bad))
    cli = run_cli("detect", "--cloud", str(cloud), "--calib", str(bad))
    assert cli.stderr == f"projsurf: error: {info.value}\n"


@pytest.mark.parametrize("points, message", [
    (np.zeros((5, 2)), "points: expected an (N, 3) or (H, W, 3) array, got shape (5, 2)"),
    (np.zeros((0, 3)), "points: the cloud has no points"),
    (np.array([["a", "b", "c"]]), "points: expected numbers"),
    ("not a cloud", "points: expected an (N, 3) or (H, W, 3) array, got a str 'not a cloud' (projsurf.read_cloud"),
    (np.zeros((2, 3, 4)), "points: expected an (N, 3) or (H, W, 3) array, got shape (2, 3, 4)"),
])
def test_bad_points_raise_input_error(projector, points, message):
    with pytest.raises(projsurf.InputError, match=None) as info:
        projsurf.detect(points, projector)
    assert str(info.value).startswith(message)


def test_all_nan_cloud_is_not_found_like_the_cli(projector, tmp_path):
    # docs/limits.md: a cloud whose points are all NaN is a valid frame (found: false and a
    # reason), in Python (detect, Tracker.update) as in the CLI; it raised InputError here.
    nan = np.full((48, 64, 3), np.nan, dtype=np.float32)
    det = projsurf.detect(nan, projector)
    assert det["found"] is False and det["reason"]
    assert projsurf.Tracker(projector).update(nan)["found"] is False
    cloud = tmp_path / "nan.pcd"
    write_pcd(cloud, nan)
    cli = run_cli("detect", "--cloud", str(cloud), "--calib", EXAMPLE_CALIB)
    assert cli.returncode == 0
    assert json.loads(cli.stdout)["found"] is False


def test_bad_options_raise_input_error(projector):
    cloud = wall_and_floor()
    with pytest.raises(projsurf.InputError, match="^aspect: expected a positive aspect ratio"):
        projsurf.detect(cloud, projector, aspect="16x9")
    with pytest.raises(projsurf.InputError, match="^gravity: the vector is zero$"):
        projsurf.detect(cloud, projector, gravity=[0, 0, 0])
    with pytest.raises(projsurf.InputError, match="^method: expected 'default' or 'paper'"):
        projsurf.detect(cloud, projector, method="fast")


def test_detect_on_an_organized_cloud(projector):
    det = projsurf.detect(wall_and_floor(), projector, aspect="16:9", gravity="auto")
    assert det["found"] and det["reason"] is None
    rect = det["rectangle"]
    assert rect["corners"].shape == (4, 3) and rect["corners"].dtype == np.float64
    assert rect["width_m"] / rect["height_m"] == pytest.approx(16 / 9, rel=1e-6)
    assert rect["area_m2"] > 0.5  # a plain wall 2.5 m away: most of the projector's 1.8 x 1.1 m footprint
    np.testing.assert_allclose(rect["corners"][:, 2], 2.5, atol=0.01)  # on the wall
    # The floor says level (estimateGravityFromFloor gives it to about 1 deg on this cloud).
    np.testing.assert_allclose(det["gravity"], [0, 1, 0], atol=0.03)
    a, b, c, d = det["plane"]["coefficients"]
    assert abs(c) == pytest.approx(1.0, abs=1e-3) and abs(d) == pytest.approx(2.5, abs=0.01)
    assert det["surface_check"]["accepted"] is True
    assert det["timing_ms"]["total"] > 0


def test_gravity_auto_follows_a_pitched_camera(projector):
    det = projsurf.detect(wall_and_floor(pitch_deg=20.0), projector, gravity="auto")
    p = math.radians(20.0)
    # Looking down by 20 deg: gravity turns towards the camera's z.
    np.testing.assert_allclose(det["gravity"], [0, math.cos(p), math.sin(p)], atol=0.03)
    # Upright on the wall: the rectangle's left edge is along gravity.
    c = det["rectangle"]["corners"]
    left = (c[3] - c[0]) / np.linalg.norm(c[3] - c[0])
    assert abs(left @ det["gravity"]) == pytest.approx(1.0, abs=1e-3)


def test_layouts_and_dtypes_give_the_same_detection(projector):
    organized = wall_and_floor()
    flat32 = organized.reshape(-1, 3)
    flat32 = flat32[np.isfinite(flat32).all(axis=1)]
    reference = projsurf.detect(flat32, projector)
    assert reference["found"]

    class Cloud:  # what an Open3D PointCloud offers: a .points numpy can read
        def __init__(self, points):
            self.points = points

    for same in (flat32.astype(np.float64), np.asfortranarray(flat32), np.repeat(flat32, 2, axis=0)[::2],
                 Cloud(flat32.astype(np.float64)), flat32.astype(np.float64).tolist()):
        det = projsurf.detect(same, projector)
        np.testing.assert_array_equal(det["rectangle"]["corners"], reference["rectangle"]["corners"])
        assert det["plane"]["inliers"] == reference["plane"]["inliers"]


def test_detector_keeps_detecting_a_stream(projector):
    detector = projsurf.Detector(projector, aspect=16 / 9, gravity=[0, 1, 0])
    cloud = wall_and_floor()
    first = detector.detect(cloud)
    again = detector.detect(cloud)
    np.testing.assert_array_equal(first["rectangle"]["corners"], again["rectangle"]["corners"])
    assert projsurf.detect(cloud, projector, aspect=16 / 9)["rectangle"]["area_m2"] == first["rectangle"]["area_m2"]


def test_same_detection_and_framebuffer_as_the_cli(projector, tmp_path):
    cloud = wall_and_floor()
    pcd, det_json, picture_png, fb_png = (str(tmp_path / n) for n in ("c.pcd", "d.json", "p.png", "fb.png"))
    write_pcd(pcd, cloud)
    cli = run_cli("detect", "--cloud", pcd, "--calib", EXAMPLE_CALIB, "--aspect", "16:9", "--json", det_json)
    assert cli.returncode == 0, cli.stderr
    from_cli = json.load(open(det_json))
    ours = projsurf.detect(projsurf.read_cloud(pcd), projector, aspect="16:9")
    assert ours["found"] == from_cli["found"] is True
    np.testing.assert_allclose(ours["rectangle"]["corners"], from_cli["rectangle"]["corners"], atol=2e-6)

    # The calibration picture, 640x360, as the picture to show.
    assert run_cli("calibrate", "--write-picture", picture_png, "--resolution", "640,360").returncode == 0
    cli = run_cli("correct", "--calib", EXAMPLE_CALIB, "--detection", det_json, "--image", picture_png, "--out", fb_png)
    assert cli.returncode == 0, cli.stderr
    picture = projsurf.read_image(picture_png)
    assert picture.shape == (360, 640, 3) and picture.dtype == np.uint8
    framebuffer = projsurf.correct(picture, projector, from_cli)  # the JSON's (rounded) corners, as the CLI
    assert framebuffer.shape == (800, 1280, 3) and framebuffer.dtype == np.uint8
    np.testing.assert_array_equal(framebuffer, projsurf.read_image(fb_png))
    assert framebuffer.max() == 255 and (framebuffer[0, 0] == 0).all()


def test_correct_takes_any_row_layout_and_grey(projector):
    det = projsurf.detect(wall_and_floor(), projector, aspect="16:9")
    rgb = np.zeros((360, 640, 3), np.uint8)
    rgb[:, :320] = (255, 0, 0)
    packed = projsurf.correct(rgb, projector, det)
    strided = projsurf.correct(np.ascontiguousarray(rgb[:, :, ::-1])[:, :, ::-1], projector, det)
    np.testing.assert_array_equal(packed, strided)
    assert packed[..., 0].max() == 255 and packed[..., 2].max() == 0  # channels kept in their order
    grey = projsurf.correct(rgb[..., 0].copy(), projector, det)
    assert grey.shape == (800, 1280)
    np.testing.assert_array_equal(grey, packed[..., 0])
    k = projsurf.keystone(projector, det, (640, 360))
    h = k["homography"]
    corners = np.array([[-0.5, -0.5, 1], [639.5, -0.5, 1], [639.5, 359.5, 1], [-0.5, 359.5, 1]]) @ h.T
    np.testing.assert_allclose(corners[:, :2] / corners[:, 2:], k["picture_px"], atol=1e-6)


def test_correct_refuses_what_cannot_be_shown(projector):
    not_found = projsurf.detect(np.array([[0.0, 0.0, 2.0]] * 10), projector)
    assert not not_found["found"] and not_found["reason"]
    with pytest.raises(projsurf.InputError, match="^detection: the detection found no surface"):
        projsurf.correct(np.zeros((10, 10, 3), np.uint8), projector, not_found)
    with pytest.raises(projsurf.InputError, match="^detection: 'rectangle.corners' are not the corners of a rectangle"):
        projsurf.correct(np.zeros((10, 10, 3), np.uint8), projector, np.array([[0, 0, 2], [1, 0, 2], [1, 2, 2], [0, 1, 2.0]]))
    with pytest.raises(projsurf.InputError, match="^image: expected an image of dtype uint8, uint16 or float32"):
        projsurf.correct(np.zeros((10, 10, 3), np.int64), projector, np.array([[0, 0, 2], [1, 0, 2], [1, 1, 2], [0, 1, 2.0]]))


def test_read_cloud_shares_the_clouds_memory(tmp_path):
    pcd = str(tmp_path / "c.pcd")
    cloud = wall_and_floor(64, 48, f=52.5)
    write_pcd(pcd, cloud)
    read = projsurf.read_cloud(pcd)
    assert read.shape == (48, 64, 3) and read.dtype == np.float32
    assert not read.flags.owndata  # a view of the C++ cloud, not a copy
    np.testing.assert_allclose(read, cloud, rtol=1e-6)


def test_the_example_script_runs(tmp_path):
    script = os.path.join(SOURCE_DIR, "examples", "python", "detect_and_correct.py")
    out = str(tmp_path / "fb.png")
    run = subprocess.run([sys.executable, script, EXAMPLE_CALIB, out], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert "rectangle" in run.stdout and "framebuffer 1280x800" in run.stdout
    fb = projsurf.read_image(out)
    assert fb.shape == (800, 1280, 3) and fb.max() == 255
    run = subprocess.run([sys.executable, script, str(tmp_path / "none.yaml"), out], capture_output=True, text=True,
                         timeout=120)
    assert run.returncode == 2
    assert run.stderr.startswith("detect_and_correct: error: " + str(tmp_path / "none.yaml") + ": ")
    assert run.stderr.count("\n") == 1
    # --help: whole sentences, the usage lines and the notes after the options (issue 40: it ended mid-sentence).
    run = subprocess.run([sys.executable, script, "--help"], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    description = run.stdout.split("\n\n")[1]
    assert description.startswith("projsurf from Python:") and description.rstrip().endswith("framebuffer."), run.stdout
    assert "--depth depth.png --camera camera.yaml" in run.stdout and "PYTHONPATH=build/python" in run.stdout


def test_an_open3d_cloud_is_taken_as_it_is(projector):
    o3d = pytest.importorskip("open3d")  # Debian's python3-open3d; projsurf does not need it
    flat = wall_and_floor().reshape(-1, 3)
    flat = flat[np.isfinite(flat).all(axis=1)]
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(flat.astype(np.float64)))
    det = projsurf.detect(cloud, projector)
    reference = projsurf.detect(flat, projector)
    assert det["found"]
    np.testing.assert_array_equal(det["rectangle"]["corners"], reference["rectangle"]["corners"])


def test_depth_to_cloud_matches_the_depth_png_reader(tmp_path):
    depth = np.full((48, 64), 2500, np.uint16)
    depth[0, 0] = 0  # no reading
    cloud = projsurf.depth_to_cloud(depth, fx=52.5, fy=52.5, cx=31.5, cy=23.5)
    assert cloud.shape == (48, 64, 3) and cloud.dtype == np.float32
    assert np.isnan(cloud[0, 0]).all()
    np.testing.assert_allclose(cloud[1:, :, 2], 2.5)
    np.testing.assert_allclose(cloud[23, 63], [(63 - 31.5) * 2.5 / 52.5, (23 - 23.5) * 2.5 / 52.5, 2.5], rtol=1e-6)
    png, camera = str(tmp_path / "d.png"), tmp_path / "camera.yaml"
    projsurf.write_image(png, depth)
    camera.write_text("camera:\n  width: 64\n  height: 48\n  fx: 52.5\n  fy: 52.5\n  cx: 31.5\n  cy: 23.5\n"
                      "  depth_scale: 1000.0\n")
    np.testing.assert_array_equal(projsurf.read_depth_cloud(png, str(camera)), cloud)
    # Every other dtype or shape: the one message, naming what was given (issue 40).
    for wrong, given in ((depth.astype(np.float32), "(48, 64) float32"), (depth.astype(np.float64), "(48, 64) float64"),
                         (depth.astype(np.uint8), "(48, 64) uint8"), (np.zeros((48, 64, 3), np.uint16), "(48, 64, 3) uint16")):
        with pytest.raises(projsurf.InputError, match="^depth: expected an \\(H, W\\) uint16 depth image "
                                                      "\\(depth_scale units per metre, 0 = no reading\\), got a "
                                                      + re.escape(given) + " array$"):
            projsurf.depth_to_cloud(wrong, fx=52.5, fy=52.5, cx=31.5, cy=23.5)


def test_depth_to_cloud_refuses_a_transposed_depth():
    # A VGA depth handed over as (640, 480) with a VGA camera's principal point (issue 40).
    depth = np.full((640, 480), 2000, np.uint16)
    with pytest.raises(projsurf.InputError, match="^depth: is \\(640, 480\\): 480 wide, 640 high, but cx and cy lie "
                                                  "at the centre of a 640 x 480 image: transposed\\?"):
        projsurf.depth_to_cloud(depth, fx=525, fy=525, cx=319.5, cy=239.5)
    assert projsurf.depth_to_cloud(depth.T, fx=525, fy=525, cx=319.5, cy=239.5).shape == (480, 640, 3)
    # A principal point off the centre but not at the transposed one is a camera's own.
    assert projsurf.depth_to_cloud(depth, fx=525, fy=525, cx=300, cy=300).shape == (640, 480, 3)


def _colour_frame():
    """A frontal wall 2.5 m away with a box in front, a dark square on the wall beside it,
    and the matching (registered) colour."""
    h, w, f = 480, 640, 525.0
    v, u = np.mgrid[0:h, 0:w].astype(np.float32)
    z = np.full((h, w), 2.5, np.float32)
    z[300:460, 40:260] = 1.6  # a box
    pts = np.dstack([(u - 319.5) * z / f, (v - 239.5) * z / f, z]).astype(np.float32)
    colour = np.full((h, w, 3), 200, np.uint8)
    colour[300:460, 40:260] = (40, 80, 120)
    colour[60:260, 300:560] = 15  # dark panel on the wall
    return pts, colour


def test_colour_is_used_only_when_registered():
    pts, colour = _colour_frame()
    proj = projsurf.Projector()
    plain = projsurf.detect(pts, proj)
    assert "suitability" not in plain
    with_colour = projsurf.detect(pts, proj, colour=colour)
    assert with_colour["suitability"]["mode"] == "avoid"
    assert with_colour["suitability"]["unsuitable_share"] <= 0.02
    shifted = np.ascontiguousarray(np.roll(colour, 15, axis=1))
    with pytest.warns(UserWarning, match="not registered"):
        moved = projsurf.detect(pts, proj, colour=shifted)
    assert "suitability" not in moved
    with pytest.raises(projsurf.InputError):
        projsurf.detect(pts, proj, colour=colour[:100])
