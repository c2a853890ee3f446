"""Python offers what `projsurf detect` offers: every option of `projsurf detect --help` is a
keyword argument of detect() and Detector() under its name (`_` for `-`), or has the documented
counterpart below; so a new CLI option without a Python one fails here. And print_config() is
`detect --print-config`, text for text."""
import os
import re
import subprocess
import warnings

import pytest

import projsurf
from test_frontend_options import EXAMPLE_CALIB, SOURCE_DIR, wall

CLI = os.environ.get("PROJSURF_CLI", "projsurf")
README = os.path.join(SOURCE_DIR, "python", "README.md")

# The options that are not keyword arguments of detect(): what Python offers instead (a module
# function, or a keyword of another name), each named in python/README.md.
COUNTERPARTS = {
    "--cloud": ("read_cloud", None),  # its array is detect()'s points
    "--depth": ("read_depth_cloud", "depth_png"),
    "--camera": ("read_depth_cloud", "camera_yaml"),
    "--bag": ("read_bag", "path"),
    "--topic": ("read_bag", "topic"),
    "--camera-info-topic": ("read_bag", "camera_info_topic"),
    "--calib": ("read_calibration", None),  # its Projector is detect()'s projector
    "--rgb": ("detect", "colour"),
    "--json": ("detect", None),  # the dict it returns (json.dumps of it)
    "--print-config": ("print_config", None),
    "--steady": ("Tracker", None),  # Tracker(...).update() on each cloud read_bag() gives
}


def cli_options(command="detect"):
    """The long options of `projsurf <command> --help`, in order."""
    run = subprocess.run([CLI, command, "--help"], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    options = re.findall(r"^\s+(?:-\w,)?(--[a-z][a-z0-9-]*)", run.stdout, re.MULTILINE)
    return [o for o in options if o != "--help"]


def signature_names(function):
    """The keyword names of a pybind11 function, from its signature line."""
    first = function.__doc__.strip().splitlines()[0]
    return set(re.findall(r"(\w+): object", first))


def detect_keywords():
    """Every keyword detect() takes: its named arguments and the pipeline settings, as the
    InputError for an unknown one lists them."""
    with pytest.raises(projsurf.InputError) as e:
        projsurf.detect(wall(), projsurf.Projector(), no_such_option=1)
    known = re.search(r"\(known: (.*)\)$", str(e.value)).group(1)
    return set(known.split(", "))


def test_the_help_lists_the_options_this_test_knows_of():
    options = cli_options()
    assert len(options) >= 25, options
    for expected in ("--cloud", "--calib", "--explain", "--print-config", "--max-outlier-fraction"):
        assert expected in options


def test_every_detect_option_has_a_python_counterpart():
    keywords = detect_keywords()
    assert signature_names(projsurf.detect) <= keywords, "the unknown-keyword message lists every named argument"
    readme = open(README).read()
    missing = []
    for option in cli_options():
        keyword = option[2:].replace("-", "_")
        if option in COUNTERPARTS:
            function, argument = COUNTERPARTS[option]
            ok = hasattr(projsurf, function) and f"{function}(" in readme
            if argument is not None:
                ok = ok and argument in signature_names(getattr(projsurf, function)) | (
                    keywords if function == "detect" else set())
            if not ok:
                missing.append(f"{option}: projsurf.{function}({argument or ''}) is not there or not in the README")
        elif keyword not in keywords:
            missing.append(f"{option}: detect() has no keyword {keyword}")
        elif f"`{keyword}`" not in readme and f"{keyword}=" not in readme:
            missing.append(f"{option}: the keyword {keyword} is not in python/README.md")
    assert not missing, "CLI options without a Python counterpart:\n" + "\n".join(missing)


def test_detector_takes_what_detect_takes():
    """Detector(...) takes the settings, its .detect() the per-frame ones (colour, explain, overlay)."""
    per_frame = {"points", "colour", "explain", "overlay"}
    assert per_frame <= signature_names(projsurf.Detector.detect)
    setting_names = detect_keywords() - per_frame - {"projector"}
    with pytest.raises(projsurf.InputError) as e:
        projsurf.Detector(projsurf.Projector(), no_such_option=1)
    known = set(re.search(r"\(known: (.*)\)$", str(e.value)).group(1).split(", "))
    assert setting_names <= known


def cli_print_config(*args):
    run = subprocess.run([CLI, "detect", "--print-config", *args], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    return run.stdout


def test_print_config_is_the_cli_text(tmp_path):
    assert projsurf.print_config() == cli_print_config()
    settings = tmp_path / "detector.yaml"
    settings.write_text("planes: {max_planes: 6}\nsuitability.mode: prefer\nobjects.surround.offsets: [0.05, 0.3]\n")
    python = projsurf.print_config(config=settings, aspect=(16, 9), max_planes=3, cell=0.02, max_tilt=0.2, seed=7)
    cli = cli_print_config("--config", str(settings), "--aspect", "16:9", "--max-planes", "3", "--cell", "0.02",
                           "--max-tilt", "0.2", "--seed", "7")
    assert python == cli
    assert "  max_planes: 3\n" in python and 'mode: "prefer"' in python and "\nseed: 7\n" in python
    paper = projsurf.print_config(method="paper", hull="convex", voxel_leaf=0.03, max_outliers=100)
    assert paper == cli_print_config("--method", "paper", "--hull", "convex", "--voxel-leaf", "0.03",
                                     "--max-outliers", "100")
    assert paper != projsurf.print_config()


def test_print_config_reads_back_to_itself(tmp_path):
    text = projsurf.print_config(aspect="4:3", max_planes=5, suitability="off")
    written = tmp_path / "written.yaml"
    written.write_text(text)
    assert projsurf.print_config(config=written) == text
    assert projsurf.detect(wall(), projsurf.read_calibration(EXAMPLE_CALIB), config=written)["found"]


def test_print_config_refuses_what_detect_refuses(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("planes:\n  max_plane: 6\n")
    with pytest.raises(projsurf.InputError, match=r"unknown key 'planes.max_plane' \(did you mean 'planes.max_planes'\?\)$"):
        projsurf.print_config(config=bad)
    with pytest.raises(projsurf.InputError, match="^max_planes: "):
        projsurf.print_config(max_planes=0)
    with pytest.raises(projsurf.InputError, match="^aspcet: unknown keyword argument"):
        projsurf.print_config(aspcet="16:9")


def test_read_depth_cloud_warns_of_unknown_camera_keys_as_the_cli_does(tmp_path):
    frame = os.path.join(SOURCE_DIR, "data", "tum_o3d_fr3_office_partition")
    camera = tmp_path / "camera.yaml"
    camera.write_text(open(os.path.join(frame, "camera.yaml")).read() + "  depth_scal: 1000\n")
    with pytest.warns(UserWarning, match=r"unknown key 'camera.depth_scal' is ignored") as caught:
        points = projsurf.read_depth_cloud(os.path.join(frame, "depth.png"), camera)
    assert points.shape == (480, 640, 3)
    run = subprocess.run([CLI, "detect", "--depth", os.path.join(frame, "depth.png"), "--camera", str(camera),
                          "--calib", EXAMPLE_CALIB, "--json", str(tmp_path / "det.json")],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert f"projsurf: warning: {caught[0].message}" in run.stderr.splitlines()


# plan and correct: each option a keyword of plan() / correct() under its name, or this.
OTHER_COUNTERPARTS = {
    "plan": {
        "--cloud": ("read_cloud", None),
        "--depth": ("read_depth_cloud", "depth_png"),
        "--camera": ("read_depth_cloud", "camera_yaml"),
        "--calib": ("read_calibration", None),
        "--rgb": ("plan", "colour"),
        "--json": ("plan", None),  # the dict it returns
    },
    "correct": {
        "--calib": ("read_calibration", None),
        "--out": ("write_image", None),  # correct() returns the framebuffer
        "--json": ("keystone", None),  # the homography and the framebuffer corners
        "--video": ("correct", None),  # on each frame the caller reads (or keystone() once)
        "--fps": ("correct", None),  # the caller's video writer keeps its rate
        "--depth": ("read_depth_cloud", "depth_png"),  # its array is correct()'s cloud
        "--camera": ("read_depth_cloud", "camera_yaml"),
    },
}


@pytest.mark.parametrize("command", sorted(OTHER_COUNTERPARTS))
def test_plan_and_correct_options_have_python_counterparts(command):
    function = getattr(projsurf, command)
    keywords = signature_names(function)
    readme = open(README).read()
    missing = []
    for option in cli_options(command):
        if option in OTHER_COUNTERPARTS[command]:
            name, argument = OTHER_COUNTERPARTS[command][option]
            ok = hasattr(projsurf, name) and (argument is None or argument in signature_names(getattr(projsurf, name)))
        else:
            ok = option[2:].replace("-", "_") in keywords
        if not ok:
            missing.append(option)
    assert not missing, f"projsurf {command} options without a Python counterpart: {missing}"
    assert f"`{command}(" in readme


def shared_settings():
    """(keyword, option, whole, lo, hi) of each setting the front ends share by name, from
    `projsurf detect --help`, whose lines give the key table's doc and range ("...; 0 to 1.5")."""
    run = subprocess.run([CLI, "detect", "--help"], capture_output=True, text=True, timeout=60)
    found = re.findall(r"^\s+(--[a-z-]+) (FLOAT|INT)\S*\s+[^\n]*; (-?[0-9.e+]+) to ([0-9.e+]+)$", run.stdout,
                       re.MULTILINE)
    return [(o[2:].replace("-", "_"), o, kind == "INT", float(lo), float(hi)) for o, kind, lo, hi in found]


def edges(whole, lo, hi):
    """(value, inside) at the ends of [lo, hi] and just outside them."""
    step = 1 if whole else max(1e-3, (hi - lo) * 1e-3)
    kind = int if whole else float
    return [(kind(lo), True), (kind(hi), True), (kind(lo - step), False), (kind(hi + step), False)]


def test_the_shared_settings_are_accepted_and_refused_alike_at_their_range_edges():
    """The CLI and Python at each shared setting's range edges (the node: ros_params, the same
    edges through its parameter translation), all checked by the one key table."""
    settings = shared_settings()
    assert [s[0] for s in settings] == ["max_tilt", "seed", "voxel_leaf", "ransac_distance", "max_outliers", "cell",
                                        "max_planes", "max_outlier_fraction"]
    for keyword, option, whole, lo, hi in settings:
        for value, inside in edges(whole, lo, hi):
            cli = subprocess.run([CLI, "detect", "--print-config", option, repr(value)], capture_output=True,
                                 text=True, timeout=60)
            assert (cli.returncode == 0) == inside, (option, value, cli.stderr)
            try:
                with warnings.catch_warnings():  # "voxel_leaf is ignored by the default method"
                    warnings.simplefilter("ignore", UserWarning)
                    projsurf.print_config(**{keyword: value})
                python = None
            except projsurf.InputError as e:
                python = str(e)
            assert (python is None) == inside, (keyword, value, python)
            if not inside:  # the one message, from the key table
                assert cli.stderr == f"projsurf: error: {option}: {python.split(': ', 1)[1]}\n", (cli.stderr, python)
