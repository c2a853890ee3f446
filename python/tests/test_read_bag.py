"""read_bag(): the clouds of a ROS 1 bag as `projsurf detect --bag` reads them (the bag written
by `projsurf bag` from the frame that ships in data/)."""
import json
import os
import shutil
import subprocess

import numpy as np
import pytest

import projsurf
from test_frontend_options import EXAMPLE_CALIB, SOURCE_DIR

CLI = os.environ.get("PROJSURF_CLI", "projsurf")
FRAME = os.path.join(SOURCE_DIR, "data", "tum_o3d_fr3_office_partition")


def cli(*args):
    run = subprocess.run([CLI, *args], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    return run


@pytest.fixture(scope="module")
def bag(tmp_path_factory):
    """Two depth images of the frame (16UC1 mm) and their camera_infos."""
    tmp = tmp_path_factory.mktemp("bag")
    frames = tmp / "frames"
    frames.mkdir()
    for name in ("0001.png", "0002.png"):
        shutil.copy(os.path.join(FRAME, "depth.png"), frames / name)
    path = tmp / "frames.bag"
    cli("bag", "--depth-dir", str(frames), "--camera", os.path.join(FRAME, "camera.yaml"), "--out", str(path))
    return path


def test_read_bag_gives_each_depth_image_as_a_cloud(bag):
    frames = projsurf.read_bag(bag)
    assert [f["index"] for f in frames] == [0, 1]
    assert all(f["topic"] == "/camera/depth/image_rect" for f in frames)
    assert frames[0]["stamp"] == pytest.approx(1.0)
    assert frames[1]["stamp"] == pytest.approx(1.0 + 1 / 30, abs=1e-6)
    assert frames[0]["points"].shape == (480, 640, 3)
    np.testing.assert_array_equal(frames[0]["points"], frames[1]["points"])
    depth = projsurf.read_depth_cloud(os.path.join(FRAME, "depth.png"), os.path.join(FRAME, "camera.yaml"))
    both = np.isfinite(depth[..., 2]) & np.isfinite(frames[0]["points"][..., 2])
    assert both.sum() > 100000
    # The bag holds millimetres: the frame's 0.2 mm steps rounded.
    assert np.abs(depth[..., 2][both] - frames[0]["points"][..., 2][both]).max() < 0.0006


def test_detect_on_read_bag_is_detect_bag(bag, tmp_path):
    projector = projsurf.read_calibration(EXAMPLE_CALIB)
    ours = [projsurf.detect(f["points"], projector, explain=True) for f in projsurf.read_bag(bag, topic="/camera/depth/image_rect")]
    out = tmp_path / "bag.jsonl"
    cli("detect", "--bag", str(bag), "--calib", EXAMPLE_CALIB, "--explain", "--json", str(out))
    theirs = [json.loads(line) for line in out.read_text().splitlines()]
    assert len(ours) == len(theirs) == 2
    for a, b in zip(ours, theirs):
        assert a["found"] == b["found"]
        np.testing.assert_allclose(a["rectangle"]["corners"], b["rectangle"]["corners"], atol=1e-5)
        assert [c["verdict"] for c in a["candidates"]] == [c["verdict"] for c in b["candidates"]]


def test_read_bag_says_what_is_wrong(bag, tmp_path):
    with pytest.raises(projsurf.InputError, match=r"no topic '/nope' in the bag \(usable topics: /camera/depth/image_rect"):
        projsurf.read_bag(bag, topic="/nope")
    with pytest.raises(projsurf.InputError, match=r"holds sensor_msgs/Image, not sensor_msgs/CameraInfo$"):
        projsurf.read_bag(bag, camera_info_topic="/camera/depth/image_rect")
    with pytest.raises(projsurf.InputError, match="no such file"):
        projsurf.read_bag(tmp_path / "missing.bag")
    with pytest.raises(projsurf.InputError, match="^topic: "):
        projsurf.read_bag(bag, topic=3)
