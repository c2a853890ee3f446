"""Every key of the detector settings file at the edges of its range, through Python's config=
and the CLI's --config: taken at each end, refused just outside with the same one line. The keys,
types and ranges are read from print_config()'s comments ("[double: 0 to 1.5]"), so a new key is
walked here without a line of this file. The node's ~config reads the file with the same reader
(tests/frontend/settings/test_config_edges.cpp walks the edges there in C++)."""
import os
import re
import subprocess
import warnings

import projsurf

CLI = os.environ.get("PROJSURF_CLI", "projsurf")

# Settings checked together: the partner goes to the end that lets every value of the key pass
# (True: the partner's high end).
PARTNERS = {
    "tolerance.min_band": ("tolerance.max_band", True),
    "tolerance.max_band": ("tolerance.min_band", False),
    "wall.noise_min": ("wall.noise_max", True),
    "wall.noise_max": ("wall.noise_min", False),
    "wall.shape.min_points": ("wall.shape.max_points", True),
    "wall.shape.max_points": ("wall.shape.min_points", False),
    "wall.shape.relief.sigma_px": ("wall.shape.relief.node_px", True),
    "wall.shape.relief.node_px": ("wall.shape.relief.sigma_px", False),
}


def declared_keys():
    """{dotted key: (type, range text)} from the comment line above each key of print_config()."""
    keys, path, pending = {}, [], None
    for line in projsurf.print_config().splitlines():
        if not line.strip() or line.startswith("# projsurf") or line.startswith("# Every") or line.startswith(
                "# Keys"):
            continue
        depth = (len(line) - len(line.lstrip())) // 2
        text = line.strip()
        if text.startswith("#"):
            found = re.search(r"\[([a-z ]+): (.*)\]$", text)
            pending = (found.group(1), found.group(2)) if found else None
            continue
        name, _, value = text.partition(":")
        path = path[:depth] + [name]
        if value.strip():
            assert pending, line
            keys[".".join(path)] = pending
        pending = None
    return keys


def numeric_range(text):
    """(lo, hi, lo_open) of "A to B", "> A and <= B", ">= A", "> A"."""
    if m := re.fullmatch(r"(\S+) to (\S+)", text):
        return float(m.group(1)), float(m.group(2)), False
    if m := re.fullmatch(r"> (\S+) and <= (\S+)", text):
        return float(m.group(1)), float(m.group(2)), True
    m = re.fullmatch(r"(>=?) (\S+)", text)
    assert m, text
    return float(m.group(2)), None, m.group(1) == ">"


def edges(kind, text):
    """[(YAML value, inside)] at the ends of the range and just outside."""
    if kind == "bool":
        return [("true", True), ("false", True), ("2", False)]
    if kind == "word":
        return [(w, True) for w in text.split(" | ")] + [("nonsense", False)]
    listed = kind == "list of double"
    if listed:
        text = re.fullmatch(r"1 to \d+ numbers, each (.*)", text).group(1)
    aspect = text.startswith("0, or a ratio")
    if aspect:
        text = re.search(r"within (.*)$", text).group(1)
    lo, hi, lo_open = numeric_range(text)
    whole = kind in ("int", "unsigned")
    step = 1 if whole else (max(1e-9, (hi - lo) * 1e-3) if hi is not None else 1e-3)
    show = (lambda v: str(int(v))) if whole else repr
    out = [(show(lo), not lo_open), (show(lo - step), False)]
    if lo_open:
        out.append((show(lo + step), True))
    if hi is not None:
        out += [(show(hi), True), (show(hi + step), False)]
    if aspect:
        out.append(("0", True))
    return [(f"[{v}]", inside) for v, inside in out] if listed else out


def partner_line(key, keys):
    if key not in PARTNERS:
        return ""
    other, high = PARTNERS[key]
    kind, text = keys[other]
    lo, hi, _ = numeric_range(text)
    value = hi if high else lo
    return f"{other}: {int(value) if kind in ('int', 'unsigned') else repr(value)}\n"


def python_reads(path):
    """(printed settings, None) or (None, the InputError's line)."""
    try:
        with warnings.catch_warnings():  # a paper-only setting in a default run warns
            warnings.simplefilter("ignore", UserWarning)
            return projsurf.print_config(config=str(path)), None
    except projsurf.InputError as e:
        return None, str(e)


def cli_reads(path):
    run = subprocess.run([CLI, "detect", "--print-config", "--config", str(path)], capture_output=True, text=True,
                         timeout=60)
    return (run.stdout, None) if run.returncode == 0 else (None, run.stderr)


def test_every_key_at_its_range_edges_in_python_and_the_cli(tmp_path):
    keys = declared_keys()
    assert len(keys) > 100 and "planes.max_planes" in keys and "wall.shape.relief.sigma_px" in keys
    first, last, refused = [], [], []
    for key, (kind, text) in keys.items():
        inside_values = []
        for n, (value, inside) in enumerate(edges(kind, text)):
            path = tmp_path / f"{key}.{n}.yaml"
            path.write_text(partner_line(key, keys) + f"{key}: {value}\n")
            printed, error = python_reads(path)
            if inside:
                assert error is None, (key, value, error)
                inside_values.append(value)
            else:
                assert printed is None, (key, value)
                assert error.startswith(f"{path}: key '{key}': ") and "\n" not in error, (key, value, error)
                refused.append((path, error))
        first.append(f"{key}: {inside_values[0]}\n")
        last.append(f"{key}: {inside_values[-1]}\n")
    # The CLI: every key at one end of its range in one file, then at the other end, read to the
    # same settings as Python's; a spread of the refusals, each the same line as Python's.
    for name, lines in (("first.yaml", first), ("last.yaml", last)):
        path = tmp_path / name
        path.write_text("".join(lines))
        python, error = python_reads(path)
        assert error is None, (name, error)
        cli, cli_error = cli_reads(path)
        assert cli_error is None, (name, cli_error)
        assert cli == python, name
    for path, error in refused[::20]:
        cli, cli_error = cli_reads(path)
        assert cli_error == f"projsurf: error: {error}\n", (path, cli_error)
