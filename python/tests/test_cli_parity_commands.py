"""plan and correct as their commands: plan(overlay=True) is `plan --overlay`'s picture and
correct(cloud=) blanks what stands in the beam as `correct --cloud` does, pixel for pixel."""
import json

import numpy as np
import pytest

import projsurf
from test_projsurf import EXAMPLE_CALIB, run_cli, wall_and_floor, write_pcd


@pytest.fixture(scope="module")
def projector():
    return projsurf.read_calibration(EXAMPLE_CALIB)


def test_plan_overlay_is_the_clis_picture(projector, tmp_path):
    pcd, png = str(tmp_path / "c.pcd"), str(tmp_path / "plan.png")
    write_pcd(pcd, wall_and_floor(320, 240, f=262.5, wall=1.2, camera_height=1.0))
    cli = run_cli("plan", "--cloud", pcd, "--calib", EXAMPLE_CALIB, "--overlay", png, "--json", str(tmp_path / "p.json"))
    assert cli.returncode == 0, cli.stderr
    cloud = projsurf.read_cloud(pcd)
    plan = projsurf.plan(cloud, projector, overlay=True)
    assert plan["found"] is True
    ours, theirs = plan["overlay"], projsurf.read_image(png)
    assert ours.shape == theirs.shape
    # The same picture but for the detection's time in its caption ("method default; 3.2 ms"):
    # what differs lies on one line of text (a time with more digits, under load, moves the rest
    # of its line).
    differ = np.argwhere((ours != theirs).any(axis=2))
    if len(differ):
        assert differ[:, 0].max() - differ[:, 0].min() <= 20, (differ.min(axis=0), differ.max(axis=0))
    assert "overlay" not in projsurf.plan(cloud, projector)
    with pytest.raises(projsurf.InputError, match="^overlay: must be True or False$"):
        projsurf.plan(cloud, projector, overlay="yes")


def test_correct_blanks_what_stands_in_the_beam_as_the_cli(projector, tmp_path):
    wall = wall_and_floor()
    names = ("c.pcd", "person.pcd", "d.json", "p.png", "fb.png", "fb.json")
    pcd, person_pcd, det_json, picture_png, fb_png, fb_json = (str(tmp_path / n) for n in names)
    write_pcd(pcd, wall)
    assert run_cli("detect", "--cloud", pcd, "--calib", EXAMPLE_CALIB, "--json", det_json).returncode == 0
    detection = json.load(open(det_json))
    assert detection["found"]
    # Someone 1.2 m from the camera, in the middle of the view (the wall is 2.5 m away).
    person = wall.copy()
    block = person[180:330, 280:360]
    person[180:330, 280:360] = block * (1.2 / block[..., 2:3])
    write_pcd(person_pcd, person)
    assert run_cli("calibrate", "--write-picture", picture_png, "--resolution", "640,400").returncode == 0
    cli = run_cli("correct", "--calib", EXAMPLE_CALIB, "--detection", det_json, "--image", picture_png, "--out", fb_png,
                  "--cloud", person_pcd, "--json", fb_json)
    assert cli.returncode == 0, cli.stderr
    assert json.load(open(fb_json))["blanked_pixels"] > 1000
    picture = projsurf.read_image(picture_png)
    blanked = projsurf.correct(picture, projector, detection, cloud=projsurf.read_cloud(person_pcd))
    np.testing.assert_array_equal(blanked, projsurf.read_image(fb_png))
    plain = projsurf.correct(picture, projector, detection)
    lit = plain.max(axis=2) > 0
    assert (lit & (blanked.max(axis=2) == 0)).sum() > 1000  # the person's shadow is black
    # Nobody in front of the wall: nothing is blanked.
    np.testing.assert_array_equal(projsurf.correct(picture, projector, detection, cloud=projsurf.read_cloud(pcd)), plain)
