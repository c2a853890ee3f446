"""The Python keyword arguments that go through the shared translation layer (frontend/):
min_width / min_area as `detect --min-width/--min-area`, aspect and gravity as the CLI reads them."""
import json
import os
import subprocess
import warnings

import numpy as np
import pytest

import projsurf
from test_projsurf import wall_and_floor as wall_and_floor_cloud

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


def test_aspect_as_a_pair_is_the_ratio(projector):
    a = projsurf.detect(wall(), projector, aspect=(16, 9))
    b = projsurf.detect(wall(), projector, aspect="16:9")
    np.testing.assert_array_equal(a["rectangle"]["corners"], b["rectangle"]["corners"])
    assert a["rectangle"]["width_m"] / a["rectangle"]["height_m"] == pytest.approx(16 / 9, rel=1e-6)
    with pytest.raises(projsurf.InputError, match=r"^aspect: expected a positive aspect ratio W:H, got '16:0'"):
        projsurf.detect(wall(), projector, aspect=(16, 0))
    with pytest.raises(projsurf.InputError, match=r"^aspect: expected two numbers, got a tuple of 3 items$"):
        projsurf.detect(wall(), projector, aspect=(16, 9, 1))


# The repository's real frame (data/): colour registered to the depth.
FRAME = os.path.join(SOURCE_DIR, "data", "tum_o3d_fr3_office_partition")
CLI = os.environ.get("PROJSURF_CLI", "projsurf")


def run_cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True, timeout=120)


def frame():
    points = projsurf.read_depth_cloud(os.path.join(FRAME, "depth.png"), os.path.join(FRAME, "camera.yaml"))
    return points, projsurf.read_image(os.path.join(FRAME, "rgb.png"))


def test_suitability_as_the_cli_reads_it(projector):
    points, rgb = frame()
    for mode in ("off", "avoid", "prefer"):
        det = projsurf.detect(points, projector, colour=rgb, suitability=mode, gravity="auto")
        cli = json.loads(run_cli("detect", "--depth", os.path.join(FRAME, "depth.png"), "--camera",
                                 os.path.join(FRAME, "camera.yaml"), "--rgb", os.path.join(FRAME, "rgb.png"),
                                 "--calib", EXAMPLE_CALIB, "--gravity", "auto", "--suitability", mode).stdout)
        # "off": colour not used, no suitability key in either (the JSON's rule).
        assert ("suitability" in det) == ("suitability" in cli) == (mode != "off")
        if mode != "off":
            assert det["suitability"]["mode"] == cli["suitability"]["mode"] == mode
        np.testing.assert_allclose(det["rectangle"]["corners"], cli["rectangle"]["corners"], atol=1e-6)
    with pytest.raises(projsurf.InputError, match="^suitability: "):
        projsurf.detect(points, projector, suitability="sometimes")
    # Without colour the mode cannot act: the CLI's warning, as a UserWarning.
    with pytest.warns(UserWarning, match="suitability needs registered colour"):
        projsurf.detect(points, projector, suitability="prefer")


def test_colour_is_checked_by_the_clis_policy(projector, tmp_path):
    points, rgb = frame()
    # Colour of another frame's view (the image upside down): not registered, not used, warned by both.
    flipped = np.ascontiguousarray(rgb[::-1, ::-1])
    with pytest.warns(UserWarning, match=r"^colour: colour is not registered to the depth \(.*\); not used$"):
        det = projsurf.detect(points, projector, colour=flipped)
    assert "suitability" not in det
    flipped_png = str(tmp_path / "flipped.png")
    projsurf.write_image(flipped_png, flipped)
    cli = run_cli("detect", "--depth", os.path.join(FRAME, "depth.png"), "--camera", os.path.join(FRAME, "camera.yaml"),
                  "--rgb", flipped_png, "--calib", EXAMPLE_CALIB)
    assert cli.returncode == 0
    assert f"projsurf: warning: {flipped_png}: colour is not registered to the depth (" in cli.stderr
    # Unorganized points cannot be registered to: a warning, as the CLI's for an unorganized cloud.
    with pytest.warns(UserWarning, match="colour needs an organized cloud or a depth image"):
        det = projsurf.detect(points.reshape(-1, 3), projector, colour=rgb)
    assert "suitability" not in det
    # Grey or 16-bit colour is refused as `detect --rgb` refuses it.
    with pytest.raises(projsurf.InputError, match=r"^colour: expected 8-bit 3-channel colour \(B, G, R\), got 8-bit with 1 channel$"):
        projsurf.detect(points, projector, colour=rgb[..., 0].copy())
    with pytest.raises(projsurf.InputError, match=r"^colour: expected 8-bit 3-channel colour \(B, G, R\), got 16-bit with 1 channel \(a depth PNG\?\)$"):
        projsurf.detect(points, projector, colour=np.zeros(points.shape[:2], np.uint16))
    with pytest.raises(projsurf.InputError, match=r"^colour: colour image is 320x240, the cloud is 640x480$"):
        projsurf.detect(points, projector, colour=np.ascontiguousarray(rgb[::2, ::2]))


def test_the_registration_check_takes_its_keys_from_the_settings_file(projector, tmp_path):
    points, rgb = frame()
    flipped = np.ascontiguousarray(rgb[::-1, ::-1])  # another view: refused with the defaults (above)
    flipped_png = str(tmp_path / "flipped.png")
    projsurf.write_image(flipped_png, flipped)
    # Offset 0 need not beat any shift: the same colour is taken, by Python and by the CLI.
    lax = tmp_path / "lax.yaml"
    lax.write_text("suitability:\n  registration:\n    min_zero_over_median: 0\n    min_zero_over_best: 0\n")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        det = projsurf.detect(points, projector, colour=flipped, config=str(lax), gravity="auto")
    assert det["suitability"]["mode"] == "avoid"
    cli = run_cli("detect", "--depth", os.path.join(FRAME, "depth.png"), "--camera", os.path.join(FRAME, "camera.yaml"),
                  "--rgb", flipped_png, "--calib", EXAMPLE_CALIB, "--config", str(lax), "--gravity", "auto")
    assert cli.returncode == 0 and "registered" not in cli.stderr, cli.stderr
    assert json.loads(cli.stdout)["suitability"]["mode"] == "avoid"
    # More depth edges needed than the frame has: the check cannot tell, the colour goes as given.
    strict = tmp_path / "strict.yaml"
    strict.write_text("suitability.registration.min_edge_pixels: 16777216\n")
    with pytest.warns(UserWarning, match=r"^colour: cannot check that the colour is registered to the depth \("):
        det = projsurf.detect(points, projector, colour=flipped, config=str(strict), gravity="auto")
    assert "suitability" in det
    cli = run_cli("detect", "--depth", os.path.join(FRAME, "depth.png"), "--camera", os.path.join(FRAME, "camera.yaml"),
                  "--rgb", flipped_png, "--calib", EXAMPLE_CALIB, "--config", str(strict), "--gravity", "auto")
    assert f"projsurf: warning: {flipped_png}: cannot check that the colour is registered" in cli.stderr


def test_the_clis_input_warnings_are_user_warnings(projector, tmp_path):
    # An "up" vector (a raw accelerometer reading) given as gravity: the floor contradicts it.
    cloud = wall_and_floor_cloud()
    with pytest.warns(UserWarning, match="^gravity 0,-1,0 puts the floor above the camera"):
        projsurf.detect(cloud, projector, gravity=[0, -1, 0])
    # No gravity given and a camera pitched 20 deg: the CLI's "give --gravity auto", in Python's words.
    pitched = wall_and_floor_cloud(pitch_deg=20.0)
    with pytest.warns(UserWarning, match=r"^the floor says the camera is tilted 20 deg from level; give gravity='auto'"):
        projsurf.detect(pitched, projector)
    # A stream checks its first cloud only (the camera's mount does not change; the floor
    # search is a detection's worth of work).
    stream = projsurf.Detector(projector)
    with pytest.warns(UserWarning, match="tilted 20 deg"):
        stream.detect(pitched)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        stream.detect(pitched)
        projsurf.detect(pitched, projector, gravity="auto")  # asked for: no warning
        projsurf.detect(cloud, projector)  # a level camera: none either
    # A typo under the calibration's projector: (its distortion would be lost).
    typo = tmp_path / "calib_typo.yaml"
    typo.write_text(open(EXAMPLE_CALIB).read() + "  distorsion: [0.1, 0, 0, 0, 0]\n")
    with pytest.warns(UserWarning, match=r"calib_typo.yaml: unknown key 'projector.distorsion' is ignored"):
        projsurf.read_calibration(str(typo))
    # A cloud in millimetres.
    with pytest.warns(UserWarning, match="millimetres"):
        projsurf.detect(cloud * 1000.0, projector)


def test_the_clis_pipeline_settings_under_the_same_names(projector):
    points, _ = frame()
    depth, camera = os.path.join(FRAME, "depth.png"), os.path.join(FRAME, "camera.yaml")
    settings = {"cell": 0.02, "max_planes": 2, "max_tilt": 0.15, "max_outlier_fraction": 0.05}
    det = projsurf.detect(points, projector, gravity="auto", **settings)
    cli = json.loads(run_cli("detect", "--depth", depth, "--camera", camera, "--calib", EXAMPLE_CALIB, "--gravity",
                             "auto", "--cell", "0.02", "--max-planes", "2", "--max-tilt", "0.15",
                             "--max-outlier-fraction", "0.05").stdout)
    default = projsurf.detect(points, projector, gravity="auto")
    assert det["found"] == cli["found"]
    np.testing.assert_allclose(det["rectangle"]["corners"], cli["rectangle"]["corners"], atol=1e-6)
    # The 2 cm raster really is used: the rectangle differs from the 1 cm default's.
    assert not np.allclose(det["rectangle"]["corners"], default["rectangle"]["corners"], atol=1e-4)
    paper = dict(voxel_leaf=0.04, ransac_distance=0.04, max_outliers=8000)
    a = projsurf.detect(points, projector, method="paper", **paper)
    b = json.loads(run_cli("detect", "--depth", depth, "--camera", camera, "--calib", EXAMPLE_CALIB, "--method",
                           "paper", "--voxel-leaf", "0.04", "--ransac-distance", "0.04", "--max-outliers",
                           "8000").stdout)
    assert a["found"] == b["found"] and a["surface_check"] == b["surface_check"]
    # A setting the method ignores: the CLI's warning, as a UserWarning.
    with pytest.warns(UserWarning, match="^cell is ignored by the paper method$"):
        projsurf.Detector(projector, method="paper", cell=0.02)
    with pytest.warns(UserWarning, match="^hull is ignored by the default method$"):
        projsurf.detect(points, projector, hull="convex")
    cli = run_cli("detect", "--depth", depth, "--camera", camera, "--calib", EXAMPLE_CALIB, "--hull", "convex")
    assert "projsurf: warning: --hull is ignored by the default method" in cli.stderr
    # Out of range, of the wrong type, or a name that is none of them: one line naming it.
    with pytest.raises(projsurf.InputError, match=r"^cell: must be a number from 0.002 to 0.5, got '0.9'$"):
        projsurf.detect(points, projector, cell=0.9)
    with pytest.raises(projsurf.InputError, match=r"^max_planes: must be a whole number from 1 to 20, got '2.5'$"):
        projsurf.detect(points, projector, max_planes=2.5)
    with pytest.raises(projsurf.InputError, match=r"^aspcet: unknown keyword argument \(known: points, projector, aspect,"):
        projsurf.detect(points, projector, aspcet="16:9")
    with pytest.raises(projsurf.InputError, match=r"^max_planes: unknown keyword argument \(Detector.detect takes points"):
        projsurf.Detector(projector).detect(points, max_planes=3)


def test_explain_as_the_cli_gives_it(projector):
    points, rgb = frame()
    calib = os.path.join(FRAME, "calib.yaml")
    det = projsurf.detect(points, projsurf.read_calibration(calib), colour=rgb, gravity="auto", aspect=(16, 9),
                          explain=True)
    cli = json.loads(run_cli("detect", "--depth", os.path.join(FRAME, "depth.png"), "--camera",
                             os.path.join(FRAME, "camera.yaml"), "--rgb", os.path.join(FRAME, "rgb.png"), "--calib",
                             calib, "--gravity", "auto", "--aspect", "16:9", "--explain").stdout)
    assert det["found"] and cli["found"]
    # The same list, by the same serialiser: every plane, its verdict and its reason in words.
    assert det["candidates"] == cli["candidates"]
    assert [c["verdict"] for c in det["candidates"]].count("chosen") == 1
    assert "candidates" not in projsurf.detect(points, projector, gravity="auto")
    # Too small, in Python's spelling of the option, with digits that show the difference.
    small = projsurf.detect(points, projector, colour=rgb, gravity="auto", aspect="16:9", min_width=0.2,
                            explain=True)
    assert not small["found"]
    reasons = [c["reason"] for c in small["candidates"] if c["verdict"] == "too_small"]
    assert reasons and reasons[0].endswith("is narrower than min_width 0.200 m"), small["candidates"]
    with pytest.raises(projsurf.InputError, match=r"^explain: must be True or False$"):
        projsurf.detect(points, projector, explain="yes")


def test_overlay_as_the_cli_draws_it(projector, tmp_path):
    points, rgb = frame()
    png = str(tmp_path / "overlay.png")
    run_cli("detect", "--depth", os.path.join(FRAME, "depth.png"), "--camera", os.path.join(FRAME, "camera.yaml"),
            "--rgb", os.path.join(FRAME, "rgb.png"), "--calib", EXAMPLE_CALIB, "--explain", "--overlay", png)
    cli = projsurf.read_image(png)
    det = projsurf.detect(points, projector, colour=rgb, explain=True, overlay=True)
    assert det["overlay"].dtype == np.uint8 and det["overlay"].shape == cli.shape
    plain = projsurf.Detector(projector).detect(points, colour=rgb, overlay=True)["overlay"]
    assert plain.shape[1] == cli.shape[1] and plain.shape[0] < cli.shape[0]  # no reasons below the picture
    assert "overlay" not in projsurf.detect(points, projector)
