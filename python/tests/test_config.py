"""config=: the detector settings YAML of `projsurf detect --config`, read by the same reader;
the other keyword arguments override it."""
import os

import pytest

import projsurf
from test_frontend_options import EXAMPLE_CALIB, SOURCE_DIR, wall


@pytest.fixture(scope="module")
def projector():
    return projsurf.read_calibration(EXAMPLE_CALIB)


def write(tmp_path, text, name="detector.yaml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_config_reaches_the_detector_and_arguments_override_it(projector, tmp_path):
    paper = write(tmp_path, "method: paper\npaper:\n  hull: convex\n")
    assert projsurf.detect(wall(), projector)["method"] == "default"
    assert projsurf.detect(wall(), projector, config=str(paper))["method"] == "paper"
    assert projsurf.detect(wall(), projector, config=paper)["method"] == "paper"  # a pathlib.Path too
    assert projsurf.Detector(projector, config=str(paper)).detect(wall())["method"] == "paper"
    assert projsurf.detect(wall(), projector, config=str(paper), method="default")["method"] == "default"


def test_a_setting_from_the_file_changes_the_answer(projector, tmp_path):
    square = write(tmp_path, "aspect: 1.0\n")
    a = projsurf.detect(wall(), projector, config=str(square))["rectangle"]
    assert a["width_m"] == pytest.approx(a["height_m"], rel=1e-6)
    wide = projsurf.detect(wall(), projector, config=str(square), aspect="2:1")["rectangle"]
    assert wide["width_m"] == pytest.approx(2 * wide["height_m"], rel=1e-6)


def test_the_shipped_example_reads(projector):
    example = os.path.join(SOURCE_DIR, "config", "detector.yaml")
    assert projsurf.detect(wall(), projector, config=example)["found"]


def test_a_bad_file_is_one_input_error_naming_file_and_key(projector, tmp_path):
    bad = write(tmp_path, "planes:\n  max_plane: 6\n")
    with pytest.raises(projsurf.InputError) as e:
        projsurf.detect(wall(), projector, config=str(bad))
    assert str(e.value) == f"{bad}: unknown key 'planes.max_plane' (did you mean 'planes.max_planes'?)"
    out_of_range = write(tmp_path, "check.max_outlier_fraction: 2\n", "range.yaml")
    with pytest.raises(projsurf.InputError, match=r"key 'check.max_outlier_fraction': must be a number from 0 to 1, got '2'$"):
        projsurf.Detector(projector, config=str(out_of_range))
    with pytest.raises(projsurf.InputError, match=r"key 'objects.avoid': must be true or false, got 'maybe'$"):
        projsurf.detect(wall(), projector, config=str(write(tmp_path, "objects.avoid: maybe\n", "type.yaml")))
    with pytest.raises(projsurf.InputError, match="no such file"):
        projsurf.detect(wall(), projector, config=str(tmp_path / "missing.yaml"))
    with pytest.raises(projsurf.InputError, match="^config: "):
        projsurf.detect(wall(), projector, config=3)
