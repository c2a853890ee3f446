"""projsurf.plan(): where the robot should stand, as `projsurf plan` says it."""
import json
import os
import subprocess

import numpy as np
import pytest

import projsurf
from test_projsurf import EXAMPLE_CALIB, run_cli, wall_and_floor, write_pcd


@pytest.fixture(scope="module")
def projector():
    return projsurf.read_calibration(EXAMPLE_CALIB)


def test_plan_steps_back_from_a_near_wall(projector):
    cloud = wall_and_floor(wall=1.2, camera_height=1.0)
    plan = projsurf.plan(cloud, projector)
    assert plan["found"] is True and plan["reason"] is None
    assert plan["move"]["forward_m"] < 0 and "back" in plan["move"]["words"]
    assert plan["predicted"]["area_m2"] > 1.5 * plan["today"]["area_m2"]
    rotation = np.array(plan["camera_pose"]["rotation"])
    np.testing.assert_allclose(rotation @ rotation.T, np.eye(3), atol=1e-9)
    assert np.linalg.norm(plan["camera_pose"]["translation"]) <= 2.0 + 1e-9
    # Today's answer is detect()'s.
    today = projsurf.detect(cloud, projector)
    np.testing.assert_allclose(plan["today"]["corners"], today["rectangle"]["corners"], atol=1e-12)


def test_plan_for_a_width_and_the_same_as_the_cli(projector, tmp_path):
    cloud = wall_and_floor(wall=1.2, camera_height=1.0)
    plan = projsurf.plan(cloud, projector, width=1.2, max_move=1.5)
    assert plan["found"] is True and plan["predicted"]["width_m"] >= 1.2
    pcd, out = str(tmp_path / "c.pcd"), str(tmp_path / "plan.json")
    write_pcd(pcd, cloud)
    cli = run_cli("plan", "--cloud", pcd, "--calib", EXAMPLE_CALIB, "--width", "1.2", "--max-move", "1.5",
                  "--json", out)
    assert cli.returncode == 0, cli.stderr
    from_cli = json.load(open(out))
    assert from_cli["move"]["words"] == plan["move"]["words"]
    np.testing.assert_allclose(from_cli["predicted"]["corners"], plan["predicted"]["corners"], atol=1e-5)


def test_plan_refuses_bad_options(projector):
    cloud = wall_and_floor()
    with pytest.raises(projsurf.InputError, match="width: must be between 0 and 50 m"):
        projsurf.plan(cloud, projector, width=-1)
    with pytest.raises(projsurf.InputError, match="max_move"):
        projsurf.plan(cloud, projector, max_move=float("nan"))


def test_plan_takes_colour_as_detect_does(projector):
    # `plan --rgb`'s counterpart: the colour goes through detect()'s policy (a wrong size is
    # refused by the same words) and today's answer stays detect()'s with the same colour.
    cloud = wall_and_floor(wall=1.2, camera_height=1.0)
    grey_wall = np.full(cloud.shape[:2] + (3,), 180, np.uint8)
    with pytest.raises(projsurf.InputError, match=r"^colour: colour image is 320x240, the cloud is 640x480$"):
        projsurf.plan(cloud, projector, colour=np.ascontiguousarray(grey_wall[::2, ::2]))
    # A plain wall has no depth edges to check the registration on: used as given, said by both.
    with pytest.warns(UserWarning, match="^colour: cannot check that the colour is registered"):
        plan = projsurf.plan(cloud, projector, colour=grey_wall, overlay=True)
    with pytest.warns(UserWarning, match="^colour: cannot check that the colour is registered"):
        today = projsurf.detect(cloud, projector, colour=grey_wall)
    assert plan["found"] is True
    np.testing.assert_allclose(plan["today"]["corners"], today["rectangle"]["corners"], atol=1e-12)
    assert plan["overlay"].shape[2] == 3
