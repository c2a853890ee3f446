"""The detection dict is the detection JSON: for the same frame, `projsurf detect --json` read
with json.load and the module's dict have the same keys and the same values, nested keys and
numbers included, because the dict is converted from the JSON writer's own tree. A key the
writer gains (as `focus` once was missing here) is in the dict too."""
import json
import os
import subprocess

import numpy as np

import projsurf

SOURCE_DIR = os.environ.get("PROJSURF_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
FRAME = os.path.join(SOURCE_DIR, "data", "tum_o3d_fr3_office_partition")
CLI = os.environ.get("PROJSURF_CLI", "projsurf")


def as_json_reads_it(value):
    """The dict with its numpy arrays as the lists json.load gives for them."""
    if isinstance(value, dict):
        return {k: as_json_reads_it(v) for k, v in value.items()}
    if isinstance(value, list):
        return [as_json_reads_it(v) for v in value]
    if isinstance(value, np.ndarray):
        return value.tolist()
    return value


def cli_detection(tmp_path, *args):
    out = tmp_path / "detection.json"
    run = subprocess.run([CLI, "detect", "--depth", os.path.join(FRAME, "depth.png"), "--camera",
                          os.path.join(FRAME, "camera.yaml"), "--rgb", os.path.join(FRAME, "rgb.png"), "--calib",
                          os.path.join(FRAME, "calib.yaml"), "--json", str(out), *args],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    with open(out, encoding="utf-8") as f:
        return json.load(f)


def same_but_times(det, cli):
    """Equal keys and values; each run's times are its own, so timing_ms is compared by its keys."""
    det, cli = as_json_reads_it(det), dict(cli)
    assert sorted(det["timing_ms"]) == sorted(cli["timing_ms"])
    assert all(isinstance(v, float) and v >= 0 for v in det["timing_ms"].values())
    det["timing_ms"] = cli["timing_ms"] = None
    assert sorted(det) == sorted(cli)
    for key in cli:
        assert det[key] == cli[key], key


def test_the_dict_is_the_json_file(tmp_path):
    points = projsurf.read_depth_cloud(os.path.join(FRAME, "depth.png"), os.path.join(FRAME, "camera.yaml"))
    rgb = projsurf.read_image(os.path.join(FRAME, "rgb.png"))
    projector = projsurf.read_calibration(os.path.join(FRAME, "calib.yaml"))
    det = projsurf.detect(points, projector, colour=rgb, gravity="auto", aspect=(16, 9), explain=True)
    cli = cli_detection(tmp_path, "--gravity", "auto", "--aspect", "16:9", "--explain")
    assert det["found"] and cli["found"]
    # The keys that the hand-made dict once lacked or that only some detections carry are here.
    for key in ("focus", "candidates", "suitability", "method", "gravity"):
        assert key in cli and key in det, key
    same_but_times(det, cli)
    # The vectors stay numpy arrays.
    assert det["rectangle"]["corners"].shape == (4, 3) and det["rectangle"]["corners"].dtype == np.float64
    assert det["plane"]["coefficients"].shape == (4,) and det["gravity"].shape == (3,)


def test_a_detection_that_found_nothing_is_the_json_file_too(tmp_path):
    points = projsurf.read_depth_cloud(os.path.join(FRAME, "depth.png"), os.path.join(FRAME, "camera.yaml"))
    rgb = projsurf.read_image(os.path.join(FRAME, "rgb.png"))
    projector = projsurf.read_calibration(os.path.join(FRAME, "calib.yaml"))
    det = projsurf.detect(points, projector, colour=rgb, min_width=9.0)
    cli = cli_detection(tmp_path, "--min-width", "9")
    assert not det["found"] and not cli["found"]
    assert isinstance(det["reason"], str) and "is narrower than min_width" in det["reason"]
    assert "focus" in det and "suitability" in det
    # The reason names the option as each front end spells it; the rest of it is the same.
    assert cli["reason"] == det["reason"].replace("min_width", "--min-width")
    cli["reason"] = det["reason"]
    same_but_times(det, cli)
