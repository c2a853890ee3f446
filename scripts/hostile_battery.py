#!/usr/bin/python3
"""An independent hostile battery over every reader and command of projsurf (and the Python
module): each case builds one hostile input from a valid run's files, runs the command and
checks the contract (docs/interface.md, docs/limits.md):
  - exit 2 with ONE stderr line `projsurf: error: ...` naming the file (or option) at fault, or
    exit 0 (or a command's documented 3) with at most one `projsurf: warning:` line;
  - no signal, no sanitizer report, done within 30 s, peak RSS under 2 GiB;
  - on failure no output written, an existing output not clobbered, no temporary left;
  - every JSON written is valid (no NaN/Infinity) and its numbers finite.
usage: hostile_battery.py PROJSURF [--work DIR] [--python-dir DIR] [--only REGEX] [--every N] [--list]
  PROJSURF: the CLI binary (build/projsurf, or build-sanitize/projsurf under ASan+UBSan);
  --python-dir: the folder holding the built module (build/python) for the Python cases.
Prints one line per failed case and a summary; exit 1 when any case fails."""
import argparse, json, math, os, re, shutil, signal, stat, struct, subprocess, sys, tarfile, time, zlib

TIMEOUT_S = 30
RSS_LIMIT_KIB = [2 * 1024 * 1024]  # --rss-limit-mib


# ---------------------------------------------------------------- file makers
def write(path, data):
    """Writes a new file at path (unlinked first: fixtures are hard links to the base files)."""
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    if os.path.lexists(path) and not os.path.isdir(path):
        os.remove(path)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())
    return path


def png(w, h, depth=8, colour=0, fill=0, ihdr_only=False, rows=None):
    """A PNG of w x h (colour type 0 grey, 2 RGB), every sample `fill`; ihdr_only: a header
    announcing the size with no image data; rows: the number of rows actually written."""
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    head = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, colour, 0, 0, 0))
    if ihdr_only:
        return head + chunk(b"IEND", b"")
    channels = 3 if colour == 2 else 1
    sample = struct.pack(">H", fill) if depth == 16 else bytes((fill,))
    row = b"\x00" + sample * (w * channels)
    z = zlib.compressobj(6)
    n = h if rows is None else rows
    data = b"".join(z.compress(row) for _ in range(n)) + z.flush()
    return head + chunk(b"IDAT", data) + chunk(b"IEND", b"")


def pcd_ascii(points, width=None, height=1, header_points=None, fields="x y z"):
    n = len(points)
    width = n if width is None else width
    head = ("VERSION 0.7\nFIELDS %s\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH %s\nHEIGHT %s\n"
            "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS %s\nDATA ascii\n" %
            (fields, width, height, n if header_points is None else header_points))
    return head + "".join("%s %s %s\n" % tuple(p) for p in points)


def ply_ascii(points, count=None, extra=""):
    head = ("ply\nformat ascii 1.0\nelement vertex %s\nproperty float x\nproperty float y\n"
            "property float z\n%send_header\n" % (len(points) if count is None else count, extra))
    return head + "".join("%s %s %s\n" % tuple(p) for p in points)


def wall_points(n=40, z=2.0, scale=1.0):
    pts = []
    for i in range(n):
        for j in range(n):
            pts.append(((i - n / 2) * 0.05 * scale, (j - n / 2) * 0.05 * scale, z * scale))
    for i in range(n):  # a floor
        for j in range(n):
            pts.append(((i - n / 2) * 0.05 * scale, 1.0 * scale, (0.5 + j * 0.04) * scale))
    return pts


CAMERA = dict(width=640, height=480, fx=525.0, fy=525.0, cx=319.5, cy=239.5, depth_scale=1000.0)


def camera_yaml(**over):
    c = dict(CAMERA)
    c.update(over)
    return "camera:\n" + "".join("  %s: %s\n" % (k, v) for k, v in c.items() if v is not None)


CALIB = dict(resolution="[1280, 800]", fov_deg="[39.3, 24.0]", origin="[0.0, 0.12, 0.0]",
             direction="[0.0, -0.05, 1.0]")


def calib_yaml(intrinsics=None, extra="", **over):
    c = dict(CALIB)
    c.update(over)
    s = ("projector:\n  resolution: %s\n  fov_deg: %s\n  axis:\n    origin: %s\n    direction: %s\n" %
         (c["resolution"], c["fov_deg"], c["origin"], c["direction"]))
    if intrinsics:
        s += "  intrinsics:\n" + "".join("    %s: %s\n" % kv for kv in intrinsics.items())
    return s + extra


def yaml_bomb(top="camera"):
    lines = ['a0: &a0 ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    for i in range(1, 12):
        lines.append("a%d: &a%d [%s]" % (i, i, ", ".join("*a%d" % (i - 1) for _ in range(9))))
    return "\n".join(lines) + "\n%s: *a11\n" % top


def deep_yaml(depth=100000):
    return "camera: " + "[" * depth + "]" * depth + "\n"


def deep_json(depth=100000):
    return '{"found": true, "rectangle": ' + "[" * depth + "]" * depth + "}"


# ---------------------------------------------------------------- running a case
class Case:
    def __init__(self, name, argv, fails=True, names=(), outputs=(), ok_codes=(0,), cwd=None, env=None,
                 max_warnings=2, setup=None):
        self.name, self.argv, self.fails, self.names = name, argv, fails, names
        self.outputs, self.ok_codes, self.cwd, self.env = outputs, ok_codes, cwd, env
        self.max_warnings, self.setup = max_warnings, setup


def finite_json(path_or_text, from_text=False):
    """None when the JSON is valid and every number finite, else the problem."""
    def refuse(c):
        raise ValueError("not JSON: " + c)
    try:
        text = path_or_text if from_text else open(path_or_text, "rb").read().decode("utf-8")
        # one document, or JSON Lines (detect --bag: one detection per message)
        docs = [text] if text.lstrip().startswith("{") and "\n{" not in text else text.splitlines()
        value = [json.loads(t, parse_constant=refuse) for t in docs if t.strip()]
    except (ValueError, UnicodeDecodeError) as e:
        return str(e)[:120]
    stack = [value]
    while stack:
        v = stack.pop()
        if isinstance(v, float) and not math.isfinite(v):
            return "a number that is not finite"
        if isinstance(v, dict):
            stack.extend(v.values())
        elif isinstance(v, list):
            stack.extend(v)
    return None


SENTINEL = b"sentinel: must survive a failed run\n"


def run_case(case, work):
    if case.setup:
        case.setup()
    # Outputs: half the cases start with an existing output (must not be clobbered on failure).
    clobber = zlib.crc32(case.name.encode()) % 2 == 0
    for out in case.outputs:
        if out.endswith("/"):  # a folder the command makes: must not be left by a failed run
            clear(out[:-1])
            continue
        if clobber:
            write(out, SENTINEL)
        elif os.path.lexists(out):
            os.remove(out)
    dirs = {os.path.dirname(o.rstrip("/")) or "." for o in case.outputs}
    before = {d: set(os.listdir(d)) if os.path.isdir(d) else set() for d in dirs}
    tag = "%08x" % zlib.crc32(case.name.encode())
    out_f, err_f = os.path.join(work, "stdout-" + tag), os.path.join(work, "stderr-" + tag)
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    env.update(case.env or {})
    t0 = time.time()
    with open(out_f, "wb") as o, open(err_f, "wb") as e:
        p = subprocess.Popen(case.argv, stdin=subprocess.DEVNULL, stdout=o, stderr=e, cwd=case.cwd, env=env,
                             start_new_session=True)
        hung = False
        while True:
            pid, status, rusage = os.wait4(p.pid, os.WNOHANG)
            if pid:
                break
            if time.time() - t0 > TIMEOUT_S:
                os.killpg(p.pid, signal.SIGKILL)
                _, status, rusage = os.wait4(p.pid, 0)
                hung = True
                break
            time.sleep(0.01)
        p.returncode = status  # reaped here: subprocess must not wait for it again
    wall = time.time() - t0
    problems = []
    if hung:
        problems.append("hang (killed after %d s)" % TIMEOUT_S)
        rc = None
    elif os.WIFSIGNALED(status):
        problems.append("killed by signal %d" % os.WTERMSIG(status))
        rc = None
    else:
        rc = os.WEXITSTATUS(status)
    if rusage.ru_maxrss > RSS_LIMIT_KIB[0]:
        problems.append("peak RSS %d MiB" % (rusage.ru_maxrss // 1024))
    err = open(err_f, "rb").read()
    try:
        err_text = err.decode("utf-8")
    except UnicodeDecodeError:
        err_text = err.decode("utf-8", "replace")
        problems.append("stderr is not UTF-8")
    lines = [l for l in err_text.split("\n") if l.strip()]
    if any(re.search(r"Sanitizer|runtime error:", l) for l in lines):
        problems.append("sanitizer report")
    if rc is not None:
        if rc == 2:
            if len(lines) != 1 or not lines[0].startswith("projsurf: error: "):
                problems.append("exit 2 with %d stderr line(s): %s" % (len(lines), " | ".join(lines[:3])[:300]))
            elif case.names and not any(n in lines[0] for n in case.names):
                problems.append("error does not name %s: %s" % (case.names[0], lines[0][:200]))
            if case.fails is False:
                problems.append("refused a valid input: " + (lines[0] if lines else "")[:200])
        elif rc in case.ok_codes:
            if case.fails:
                problems.append("accepted (exit %d)%s" % (rc, (": " + lines[0][:150]) if lines else ""))
            bad = [l for l in lines if not l.startswith("projsurf: warning: ")]
            # calibrate's and verify's exit 3 has one error line (documented), nothing else
            if rc == 3:
                bad = [l for l in bad if not l.startswith("projsurf: error: ")]
            if bad:
                problems.append("exit %d with stderr: %s" % (rc, " | ".join(bad[:2])[:200]))
            if len(lines) > case.max_warnings + (1 if rc == 3 else 0):
                problems.append("exit %d with %d warning lines: %s" % (rc, len(lines), " | ".join(lines[:3])[:300]))
        else:
            problems.append("exit %d: %s" % (rc, " | ".join(lines[:2])[:200]))
    failed = rc is None or rc == 2
    for out in case.outputs:
        if out.endswith("/"):
            if failed and os.path.lexists(out[:-1]):
                problems.append("failed run left the folder " + os.path.basename(out[:-1]))
        elif failed:
            if clobber:
                if not os.path.isfile(out) or open(out, "rb").read() != SENTINEL:
                    problems.append("failed run clobbered " + os.path.basename(out))
            elif not clobber and os.path.lexists(out) and not os.path.isdir(out):
                problems.append("failed run wrote " + os.path.basename(out))
        elif out.endswith(".json") and os.path.isfile(out):
            bad = finite_json(out)
            if bad:
                problems.append("%s: %s" % (os.path.basename(out), bad))
    if rc is not None and rc != 2:
        s = open(out_f, "rb").read()
        if s.lstrip().startswith(b"{"):
            bad = finite_json(s.decode("utf-8", "replace"), from_text=True)
            if bad:
                problems.append("stdout JSON: " + bad)
    for d in dirs:
        if os.path.isdir(d):
            left = [f for f in set(os.listdir(d)) - before[d]
                    if not any(os.path.basename(o.rstrip("/")) == f for o in case.outputs)]
            if failed and left:
                problems.append("failed run left %s" % ", ".join(sorted(left))[:120])
    os.remove(out_f)
    os.remove(err_f)
    return problems, rc, wall, rusage.ru_maxrss // 1024, lines[:1]


# ---------------------------------------------------------------- hostile variants of one input
GARBAGE = bytes((i * 131 + 7) % 256 for i in range(4096))
NON_UTF8 = b"\xff\xfe\x80 \xc3\x28 \xed\xa0\x80 camera: \xe2\x82\n"


def generic(valid):
    """Every input slot gets these: not a regular file, not there, empty, garbage, cut."""
    return [
        ("fifo", lambda p: os.mkfifo(p), True),
        ("device", lambda p: os.symlink("/dev/zero", p), True),
        ("directory", lambda p: os.mkdir(p), True),
        ("link-loop", lambda p: os.symlink(os.path.basename(p), p), True),
        ("dangling-link", lambda p: os.symlink("no/such/target", p), True),
        ("missing", lambda p: None, True),
        ("empty", lambda p: write(p, b""), True),
        ("garbage", lambda p: write(p, GARBAGE), True),
        ("non-utf8", lambda p: write(p, NON_UTF8), True),
        ("half", lambda p: write(p, valid[: len(valid) // 2]), True),
        ("first-40-bytes", lambda p: write(p, valid[:40]), True),
        ("megabyte-of-digits", lambda p: write(p, b"9" * 1000000), True),
    ]


def valid_yaml_cuts(variants):
    """A settings file cut short or empty may still be valid YAML (every key is optional)."""
    return [(n, m, None if n in ("empty", "half", "first-40-bytes") else f) for n, m, f in variants]


def content(items):
    """(name, bytes or str, fails) -> variants that write that content."""
    return [(n, (lambda d: lambda p: write(p, d))(d), f) for n, d, f in items]


def pcd_variants():
    hdr = lambda **k: ("VERSION 0.7\nFIELDS %(fields)s\nSIZE %(size)s\nTYPE %(type)s\nCOUNT %(count)s\nWIDTH %(w)s\n"
                       "HEIGHT %(h)s\nVIEWPOINT %(vp)s\nPOINTS %(n)s\nDATA %(data)s\n" %
                       dict(dict(fields="x y z", size="4 4 4", type="F F F", count="1 1 1", w=3, h=1,
                                 vp="0 0 0 1 0 0 0", n=3, data="ascii"), **k))
    three = "0 0 2\n0.1 0 2\n0 0.1 2\n"
    return content([
        ("width-1e9", hdr(w=1000000000, n=1000000000) + three, True),
        ("width-float-1e9", hdr(w="1e9", n="1e9") + three, True),
        ("organized-65536-square", hdr(w=65536, h=65536, n=65536 * 65536) + three, True),
        ("width-negative", hdr(w=-3, n=-3) + three, True),
        ("points-disagree", hdr(w=3, n=10) + three, True),
        ("width-times-height-disagree", hdr(w=2, h=2, n=3) + three, True),
        ("count-1e9", hdr(count="1 1 1000000000") + three, True),
        ("size-0", hdr(size="0 4 4") + three, True),
        ("size-16", hdr(size="16 4 4") + three, True),
        ("type-unknown", hdr(type="Q F F") + three, True),
        ("no-x-field", hdr(fields="a b c") + three, True),
        ("fields-duplicate", hdr(fields="x x z") + three, None),
        ("binary-short", hdr(w=1000, n=1000, data="binary") + "\0" * 12, True),
        ("binary-compressed-huge-sizes",
         hdr(w=1000, n=1000, data="binary_compressed").encode() + struct.pack("<II", 0xFFFFFFFF, 0xFFFFFFF0) + b"\0" * 16,
         True),
        ("binary-compressed-zero", hdr(w=1000, n=1000, data="binary_compressed").encode() + struct.pack("<II", 0, 0), True),
        ("data-unknown", hdr(data="zip") + three, True),
        ("no-data-line", hdr().replace("DATA ascii\n", "") + three, True),
        ("empty-cloud", hdr(w=0, n=0), None),
        ("all-nan", hdr(w=2000, n=2000) + "nan nan nan\n" * 2000, None),
        ("all-inf", hdr(w=200, n=200) + "inf -inf inf\n" * 200, None),
        ("values-1e300", hdr() + "1e300 1e300 1e300\n-1e300 0 1e300\n0 0 1e300\n", None),
        ("values-1e38-near-float-max", hdr() + "3.4e38 3.4e38 3.4e38\n-3.4e38 0 3.4e38\n0 0 3.4e38\n", None),
        ("single-point-1e20", hdr(w=1, n=1) + "1e20 0 1e20\n", None),
        ("single-point-minus-1e20", hdr(w=1, n=1) + "-1e20 -1e20 1e20\n", None),
        ("wall-plus-far-point", hdr(w=len(wall_points()) + 1, n=len(wall_points()) + 1) +
         "".join("%g %g %g\n" % p for p in wall_points()) + "-1e20 0 1e20\n", None),
        ("millimetres", hdr(w=len(wall_points()), n=len(wall_points())) +
         "".join("%g %g %g\n" % p for p in wall_points(scale=1000)), None),
        ("all-at-origin", hdr(w=5000, n=5000) + "0 0 0\n" * 5000, None),
        ("all-one-point", hdr(w=5000, n=5000) + "0.5 0.2 2\n" * 5000, None),
        ("viewpoint-nan", hdr(vp="nan nan nan nan 0 0 0") + three, None),
        ("text-values", hdr() + "a b c\nd e f\ng h i\n", True),
        ("too-few-values", hdr() + "0 0\n0 0\n0 0\n", True),
        ("non-utf8-fields", hdr(fields="x y \xff").encode("latin-1") + three.encode(), True),
        ("header-1MB-comments", "# c\n" * 240000 + hdr() + three, None),
        ("long-line", hdr() + "0" * 900000 + " 0 2\n0 0 2\n0 0 2\n", None),
    ])


def ply_variants():
    pts = [(0, 0, 2), (0.1, 0, 2), (0, 0.1, 2)]
    return content([
        ("vertex-count-4294967295", ply_ascii(pts, count=4294967295), True),
        ("vertex-count-negative", ply_ascii(pts, count=-1), True),
        ("vertex-count-1e9", ply_ascii(pts, count="1e9"), True),
        ("vertex-count-disagrees", ply_ascii(pts, count=100), True),
        ("face-count-2e9", ply_ascii(pts, extra="element face 2000000000\nproperty list uchar int vertex_indices\n"), None),
        ("binary-count-1e8", b"ply\nformat binary_little_endian 1.0\nelement vertex 100000000\nproperty float x\n"
                             b"property float y\nproperty float z\nend_header\n" + b"\0" * 36, True),
        ("binary-big-endian", b"ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\n"
                              b"property float y\nproperty float z\nend_header\n" +
                              b"".join(struct.pack(">fff", *p) for p in pts), None),
        ("list-in-vertex", "ply\nformat ascii 1.0\nelement vertex 3\nproperty list uchar float x\nproperty float y\n"
                           "property float z\nend_header\n3 0 0 0 0 2\n3 0 0 0 0 2\n3 0 0 0 0 2\n", None),
        ("list-count-255", b"ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                           b"property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n" +
                           struct.pack("<fff", 0, 0, 2) + struct.pack("<I", 0xFFFFFFFF), None),
        ("type-float128", ply_ascii(pts).replace("property float x", "property float128 x"), True),
        ("no-end-header", ply_ascii(pts).replace("end_header\n", ""), True),
        ("format-unknown", ply_ascii(pts).replace("format ascii", "format utf16"), True),
        ("all-nan", ply_ascii([("nan", "nan", "nan")] * 2000), None),
        ("single-point-1e20", ply_ascii([(1e20, 0, 1e20)]), None),
        ("values-1e300", ply_ascii([(1e300, 1e300, 1e300)] * 3), None),
        ("empty-cloud", ply_ascii([]), None),
        ("non-utf8-comment", b"ply\nformat ascii 1.0\ncomment \xff\xfe\nelement vertex 3\nproperty float x\n"
                             b"property float y\nproperty float z\nend_header\n0 0 2\n0.1 0 2\n0 0.1 2\n", None),
        ("header-1MB-comments", "ply\nformat ascii 1.0\n" + "comment c\n" * 90000 + ply_ascii(pts)[21:], None),
    ])


def depth_variants(w, h):
    return content([
        ("all-65535", png(w, h, 16, 0, 65535), None),
        ("all-zero", png(w, h, 16, 0, 0), None),
        ("all-one", png(w, h, 16, 0, 1), None),
        ("eight-bit", png(w, h, 8, 0, 200), None),
        ("rgb-eight-bit", png(w, h, 8, 2, 200), True),
        ("rgb-sixteen-bit", png(w, h, 16, 2, 2000), True),
        ("header-65535-square", png(65535, 65535, 16, 0, ihdr_only=True), True),
        ("header-2147483647-wide", png(2147483647, 1, 16, 0, ihdr_only=True), True),
        ("header-zero-size", png(0, 0, 16, 0, ihdr_only=True), True),
        ("other-size", png(w // 2, h // 2, 16, 0, 2000), True),
        ("one-pixel", png(1, 1, 16, 0, 2000), True),
        ("rows-missing", png(w, h, 16, 0, 2000, rows=h // 3), True),
        ("bad-crc", png(w, h, 16, 0, 2000)[:-5] + b"\0\0\0\0\0", None),
    ])


def camera_variants():
    c = camera_yaml
    return content([
        ("fx-1e-300", c(fx="1e-300", fy="1e-300"), True),
        ("fx-0.001", c(fx=0.001, fy=0.001), True),
        ("fx-zero", c(fx=0), True),
        ("fx-negative", c(fx=-525), True),
        ("fx-nan", c(fx=".nan"), True),
        ("fx-inf", c(fx=".inf"), True),
        ("fx-1e300", c(fx="1e300", fy="1e300"), True),
        ("fx-text", c(fx="abc"), True),
        ("fx-list", c(fx="[1, 2]"), True),
        ("fx-millimetres", c(fx=3.6, fy=3.6), True),
        ("width-zero", c(width=0), True),
        ("width-negative", c(width=-640), True),
        ("width-fraction", c(width=640.5), True),
        ("width-1e9", c(width=1000000000), True),
        ("size-65536-square", c(width=65536, height=65536, cx=32767.5, cy=32767.5), True),
        ("cx-1e300", c(cx="1e300"), True),
        ("cx-nan", c(cx=".nan"), True),
        ("depth-scale-zero", c(depth_scale=0), True),
        ("depth-scale-negative", c(depth_scale=-1000), True),
        ("depth-scale-1e-300", c(depth_scale="1e-300"), True),
        ("depth-scale-nan", c(depth_scale=".nan"), True),
        ("depth-scale-1e300", c(depth_scale="1e300"), True),
        ("depth-scale-metres", c(depth_scale=1), None),
        ("fx-missing", c(fx=None), True),
        ("unknown-key", c(focal=525), None),
        ("yaml-bomb", yaml_bomb("camera"), True),
        ("deep-nesting", deep_yaml(), True),
        ("top-level-list", "- camera\n- 1\n", True),
        ("duplicate-key", c() + "  fx: 600\n", True),
        ("second-document", c() + "---\n" + c(), True),
        ("alias-cycle-deep", "camera: &c\n  width: 640\n  more: {even: *c}\n", True),
        ("thousand-unknown-keys", c() + "".join("  bogus_%d: 1\n" % i for i in range(1000)), False),
        ("newline-key", c() + '  "x\\nprojsurf: error: forged": 1\n', False),
        ("tab-indent", c().replace("  ", "\t"), True),
        ("non-utf8-comment", c().encode() + b"# \xff\xfe\n", None),
        ("seventy-KiB", c() + "#" + "x" * 70000 + "\n", True),
        ("anchor-alias-loop", "camera: &a\n  width: 640\n  more: *a\n", True),
    ])


def calib_variants():
    k = calib_yaml
    return content([
        ("resolution-zero", k(resolution="[0, 0]"), True),
        ("resolution-negative", k(resolution="[-1280, 800]"), True),
        ("resolution-1e9", k(resolution="[1000000000, 1000000000]"), True),
        ("resolution-16384-square", k(resolution="[16384, 16384]"), True),
        ("resolution-fraction", k(resolution="[1280.5, 800]"), True),
        ("resolution-nan", k(resolution="[.nan, 800]"), True),
        ("resolution-one", k(resolution="[1, 1]"), True),
        ("fov-radians", k(fov_deg="[0.6, 0.4]"), True),
        ("fov-zero", k(fov_deg="[0, 0]"), True),
        ("fov-180", k(fov_deg="[180, 180]"), True),
        ("fov-179.9", k(fov_deg="[179.9, 179]"), None),
        ("fov-nan", k(fov_deg="[.nan, 24]"), True),
        ("fov-1e300", k(fov_deg="[1e300, 24]"), True),
        ("fov-negative", k(fov_deg="[-39.3, 24]"), True),
        ("origin-1e300", k(origin="[1e300, 0, 0]"), True),
        ("origin-nan", k(origin="[.nan, 0, 0]"), True),
        ("origin-millimetres", k(origin="[0, 120, 0]"), True),
        ("direction-zero", k(direction="[0, 0, 0]"), True),
        ("direction-nan", k(direction="[.nan, 0, 1]"), True),
        ("direction-backwards", k(direction="[0, 0, -1]"), None),
        ("direction-tiny", k(direction="[1e-300, 0, 1e-300]"), None),
        ("direction-1e300", k(direction="[1e300, 0, 1e300]"), None),
        ("intrinsics-fx-1e-300", k(dict(fx="1e-300", fy="1e-300", cx=639.5, cy=399.5)), True),
        ("intrinsics-fx-0.001", k(dict(fx=0.001, fy=0.001, cx=639.5, cy=399.5)), True),
        ("intrinsics-fx-negative", k(dict(fx=-1800, fy=1800, cx=639.5, cy=399.5)), True),
        ("intrinsics-contradict-fov", k(dict(fx=100, fy=100, cx=639.5, cy=399.5)), True),
        ("intrinsics-cx-1e300", k(dict(fx=1809.6, fy=1811, cx="1e300", cy=399.5)), True),
        ("intrinsics-cy-nan", k(dict(fx=1809.6, fy=1811, cx=639.5, cy=".nan")), True),
        ("intrinsics-partial", k(dict(fx=1809.6)), True),
        ("distortion-1e300", k(extra="  distortion: [1e300, 0, 0, 0, 0]\n"), True),
        ("distortion-nan", k(extra="  distortion: [.nan, 0, 0, 0, 0]\n"), True),
        ("distortion-100", k(extra="  distortion: [%s]\n" % ", ".join(["0"] * 100)), True),
        ("distortion-strong", k(extra="  distortion: [50, -50, 0, 0, 100]\n"), None),
        ("rotation-not-orthonormal", k(extra="  rotation:\n    - [2, 0, 0]\n    - [0, 1, 0]\n    - [0, 0, 1]\n"), True),
        ("rotation-mirror", k(direction="[0, 0, 1]", extra="  rotation:\n    - [-1, 0, 0]\n    - [0, 1, 0]\n    - [0, 0, 1]\n"), True),
        ("rotation-nan", k(extra="  rotation:\n    - [.nan, 0, 0]\n    - [0, 1, 0]\n    - [0, 0, 1]\n"), True),
        ("unknown-key", k(extra="  zoom: 2\n"), None),
        ("alias-cycle", "projector: &p {resolution: [1280, 800], x: *p}\n", True),
        ("key-twice", k() + "projector:\n  resolution: [640, 480]\n", True),
        ("second-document", k() + "---\n" + k(), True),
        ("latin1-key", k().encode() + b"  distorsi\xf3n: [0, 0, 0, 0, 0]\n", False),
        ("newline-key", k() + '  "x\\nprojsurf: error: forged": 1\n', False),
        ("thousand-unknown-keys", k() + "".join("  bogus_%d: 1\n" % i for i in range(1000)), False),
        ("yaml-bomb", yaml_bomb("projector"), True),
        ("deep-nesting", deep_yaml().replace("camera", "projector"), True),
        ("non-utf8-value", k().encode() + b"  note: \xff\xfe\n", None),
        ("seventy-KiB", k() + "#" + "x" * 70000 + "\n", True),
        ("projector-missing", "camera: {}\n", True),
    ])


def detection_variants(valid):
    d = json.loads(valid)
    def mod(f):
        x = json.loads(valid)
        f(x)
        return json.dumps(x)
    corners = lambda v: mod(lambda x: x["rectangle"].__setitem__("corners", v))
    return content([
        ("deep-nesting", deep_json(), True),
        ("nan-literal", valid.replace(str(d["rectangle"]["width_m"]), "NaN", 1), True),
        ("infinity-literal", valid.replace(str(d["rectangle"]["width_m"]), "Infinity", 1), True),
        ("number-1e400", corners([[1e400 if False else 0, 0, 2]] * 4).replace("0, 0, 2", "1e400, 0, 2", 1), True),
        ("corners-1e300", corners([[1e300, 0, 2], [1e300, 1, 2], [0, 1e300, 2], [0, 0, 1e300]]), True),
        ("corners-equal", corners([[0, 0, 2]] * 4), True),
        ("corners-three", corners([[0, 0, 2]] * 3), True),
        ("corners-text", corners("four"), True),
        ("corners-behind", corners([[-0.5, -0.3, -2], [0.5, -0.3, -2], [0.5, 0.3, -2], [-0.5, 0.3, -2]]), True),
        ("corners-1e6-away", corners([[-5e5, -3e5, 1e6], [5e5, -3e5, 1e6], [5e5, 3e5, 1e6], [-5e5, 3e5, 1e6]]), None),
        ("corners-twisted", corners([[-0.5, -0.3, 2], [0.5, 0.3, 2], [0.5, -0.3, 2], [-0.5, 0.3, 2]]), None),
        ("found-without-rectangle", mod(lambda x: x.pop("rectangle")), True),
        ("found-text", mod(lambda x: x.__setitem__("found", "yes")), True),
        ("not-found", mod(lambda x: x.__setitem__("found", False)), True),
        ("top-level-list", "[1, 2, 3]", True),
        ("two-megabytes", valid[:-1] + ', "pad": "' + "x" * 2000000 + '"}', True),
        ("non-utf8-string", valid[:-1].encode() + b', "note": "\xff\xfe"}', True),
        ("trailing-garbage", valid + "}}}", True),
        ("plane-zero", mod(lambda x: x["plane"].__setitem__("coefficients", [0, 0, 0, 0])), None),
        ("plane-nan-string", mod(lambda x: x["plane"].__setitem__("coefficients", ["nan", 0, 0, 0])), None),
    ])


def image_variants():
    return content([
        ("header-65535-square", png(65535, 65535, 8, 2, ihdr_only=True), True),
        ("header-zero-size", png(0, 0, 8, 2, ihdr_only=True), True),
        ("rows-missing", png(640, 480, 8, 2, 100, rows=100), True),
        ("sixteen-bit", png(64, 48, 16, 2, 40000), None),
        ("grey", png(64, 48, 8, 0, 100), None),
        ("one-pixel", png(1, 1, 8, 2, 100), None),
        ("one-row-8000", png(8000, 1, 8, 2, 100), None),
        ("jpeg-header-only", b"\xff\xd8\xff\xe0\x00\x10JFIF\x00\x01\x01\x00\x00\x01\x00\x01\x00\x00"
                             b"\xff\xc0\x00\x11\x08\xff\xff\xff\xff\x03\x01\x22\x00\x02\x11\x01\x03\x11\x01", True),
        ("bmp-huge", b"BM" + struct.pack("<IHHI", 1000, 0, 0, 54) + struct.pack("<IiiHHIIiiII", 40, 100000, 100000, 1, 24, 0, 0, 0, 0, 0, 0) + b"\0" * 64, True),
        ("bmp-negative-height", b"BM" + struct.pack("<IHHI", 1000, 0, 0, 54) + struct.pack("<IiiHHIIiiII", 40, 10, -2147483647, 1, 24, 0, 0, 0, 0, 0, 0) + b"\0" * 64, True),
        ("pnm-huge", b"P6\n100000 100000\n255\n" + b"\0" * 64, True),
        ("pnm-negative", b"P6\n-5 -5\n255\n" + b"\0" * 64, True),
        ("tiff", b"II*\0" + b"\0" * 60, True),
        ("gif", b"GIF89a" + struct.pack("<HH", 10, 10) + b"\0" * 40, True),
    ])


def config_variants():
    return content([
        ("unknown-key", "planes:\n  max_planez: 4\n", True),
        ("unknown-top-key", "colour: red\n", True),
        ("cell-zero", "free_space:\n  cell: 0\n", True),
        ("cell-1e-9", "free_space:\n  cell: 1.0e-9\n", True),
        ("cell-negative", "free_space.cell: -0.01\n", True),
        ("cell-nan", "free_space:\n  cell: .nan\n", True),
        ("cell-1e300", "free_space:\n  cell: 1.0e300\n", True),
        ("max-planes-1e9", "planes:\n  max_planes: 1000000000\n", True),
        ("max-planes-negative", "planes:\n  max_planes: -4\n", True),
        ("ransac-iterations-2e9", "planes:\n  ransac_iterations: 2000000000\n", True),
        ("target-samples-1e9", "planes:\n  target_samples: 1000000000\n", True),
        ("unorganized-max-pixels-1e12", "unorganized:\n  max_pixels: 1000000000000\n", True),
        ("relief-max-nodes-1e9", "wall:\n  shape:\n    relief:\n      max_nodes: 1000000000\n", True),
        ("surround-bins-1e9", "objects:\n  surround:\n    bins: 1000000000\n", True),
        ("surround-offsets-10000", "objects:\n  surround:\n    offsets: [%s]\n" % ", ".join(["0.1"] * 10000), True),
        ("surround-offsets-1e300", "objects:\n  surround:\n    offsets: [1.0e300]\n", None),
        ("regions-cell-zero", "planes:\n  regions:\n    cell: 0\n", True),
        ("paper-voxel-leaf-1e-9", "method: paper\npaper:\n  voxel_leaf: 1.0e-9\n", True),
        ("paper-max-voxels-1e12", "paper:\n  max_voxels: 1000000000000\n", True),
        ("max-tilt-nan", "max_tilt: .nan\n", True),
        ("max-tilt-10", "max_tilt: 10\n", True),
        ("seed-negative", "seed: -1\n", True),
        ("seed-1e30", "seed: 1.0e30\n", True),
        ("method-unknown", "method: magic\n", True),
        ("bool-as-number", "wall:\n  fit_shape: 7\n", True),
        ("number-as-list", "max_tilt: [0.1]\n", True),
        ("map-as-number", "planes: 4\n", True),
        ("yaml-bomb", yaml_bomb("planes"), True),
        ("deep-nesting", "planes: " + "[" * 100000 + "]" * 100000 + "\n", True),
        ("non-utf8", b"method: \xff\xfe\n", True),
        ("aspect-negative", "aspect: -1.6\n", True),
        ("suitability-mode-unknown", "suitability:\n  mode: bright\n", True),
        ("row-step-zero", "suitability:\n  cells:\n    row_step: 0\n", True),
        ("duplicate-key", "seed: 1\nseed: 2\n", True),
        ("block-twice", "planes:\n  max_planes: 4\nplanes:\n  min_plane_points: 50\n", True),
        ("dotted-and-nested", "planes.max_planes: 4\nplanes: {max_planes: 5}\n", True),
        ("alias-cycle", "planes: &p {max_planes: 4, sub: *p}\n", True),
        ("alias-chain-70", "".join("a%d: &a%d {x: %s}\n" % (i, i, "*a%d" % (i - 1) if i else "1") for i in range(70)), True),
        ("second-document", "planes: {max_planes: 4}\n---\nplanes: {max_planes: 5}\n", True),
        ("relief-node-px-1e-300", "wall.shape.relief.node_px: 1.0e-300\n", True),
        ("relief-sigma-px-1e300", "wall.shape.relief.sigma_px: 1.0e300\n", True),
        ("relief-extremes", "wall.shape.relief.node_px: 1\nwall.shape.relief.sigma_px: 10\n"
                            "wall.shape.relief.max_nodes: 1024\n", False),
        ("key-with-newline", '"planes\\nprojsurf: error: forged": 4\n', True),
        ("empty-mapping", "{}\n", False),
        ("top-level-list", "- 1\n- 2\n", True),
    ])


def patterns_yaml_variants(names):
    head = lambda res="[64, 32]", coding="gray_code_inverse": "patterns:\n  resolution: %s\n  coding: %s\n" % (res, coding)
    order = lambda ns: "  order: [%s]\n" % ", ".join(ns)
    return content([
        ("resolution-zero", head("[0, 0]") + order(names), True),
        ("resolution-huge", head("[1000000000, 1000000000]") + order(names), True),
        ("resolution-16384-square", head("[16384, 16384]") + order(names), True),
        ("resolution-nan", head("[.nan, 32]") + order(names), True),
        ("coding-unknown", head(coding="morse") + order(names), True),
        ("order-empty", head() + order([]), True),
        ("order-100000", head() + order(["p%d" % i for i in range(100000)]), True),
        ("order-parent-path", head() + order(["../../../etc/passwd"] + names[1:]), True),
        ("order-absolute-path", head() + order(["/etc/passwd"] + names[1:]), True),
        ("order-duplicates", head() + order([names[0]] * len(names)), True),
        ("order-non-utf8", head().encode() + b"  order: [\xff\xfe]\n", True),
        ("yaml-bomb", yaml_bomb("patterns"), True),
        ("deep-nesting", "patterns: " + "[" * 100000 + "]" * 100000 + "\n", True),
    ])


def corrupt_variants(valid, count=16):
    """Bytes overwritten at spread offsets (all-ones lengths, zeros): the reader must say no or read what is left."""
    out = []
    for i in range(count):
        off = 13 + (len(valid) - 20) * i // count
        for fill, tag in ((b"\xff\xff\xff\x7f", "ff"), (b"\0\0\0\0", "00")):
            data = valid[:off] + fill + valid[off + 4:]
            out.append(("bytes-%s-at-%d" % (tag, off), data, None))
    out.append(("cut-at-99-percent", valid[: len(valid) * 99 // 100], None))
    return content(out)


# ---------------------------------------------------------------- folders
def folder_variants():
    """For a folder argument (captures, pose_0, a depth folder)."""
    return [
        ("folder-missing", lambda p: None, True),
        ("folder-is-a-file", lambda p: write(p, b"not a folder\n"), True),
        ("folder-is-a-fifo", lambda p: os.mkfifo(p), True),
        ("folder-link-loop", lambda p: os.symlink(os.path.basename(p), p), True),
        ("folder-empty", lambda p: os.mkdir(p), True),
    ]


# ---------------------------------------------------------------- options
BAD_NUMBERS = [("nan", True), ("inf", True), ("-inf", True), ("1e300", None), ("-1", None), ("0", None),
               ("1e-300", None), ("abc", True), ("", True), ("0x10", None), ("1e", True)]
BAD_TRIPLES = [("nan,0,0", True), ("0,0,0", True), ("1e300,1,0", None), ("1e-300,1e-300,0", None),
               ("1,2", True), ("1,2,3,4", True), ("abc", True), ("inf,1,0", True)]
BAD_PAIRS = [("nan,24", True), ("0,0", True), ("-1280,800", True), ("1e9,1e9", True), ("16384,16384", True),
             ("1,1", True), ("2,2", None), ("1280.5,800", True), ("abc", True), ("1280", True), ("inf,800", True)]
BAD_ASPECTS = [("0:1", True), ("nan:1", True), ("1e300:1", True), ("-4:3", True), ("4:0", True), ("abc", True),
               ("1:1e-300", True), ("inf:1", True), ("1000000:1", None)]


# ---------------------------------------------------------------- the commands and their inputs
def link_tree(src, dst):
    if os.path.isdir(src):
        shutil.copytree(src, dst, copy_function=os.link, symlinks=True)
    else:
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        os.link(src, dst)


def clear(path):
    if os.path.isdir(path) and not os.path.islink(path):
        shutil.rmtree(path)
    elif os.path.lexists(path):
        os.remove(path)


class Command:
    """argv: a list whose '{key}' words are the case folder's copies of files[key] ('{out}': its output folder).
    slots: key or key/inside -> (variants, words the error may name)."""
    def __init__(self, tag, argv, files, slots, outputs=(), ok_codes=(0,), options=(), max_warnings=2,
                 valid_fails=False):
        self.tag, self.argv, self.files, self.slots = tag, argv, files, slots
        self.valid_fails = valid_fails
        self.max_warnings = max_warnings
        self.outputs, self.ok_codes, self.options = outputs, ok_codes, options


def make_cases(cmd, cli, work):
    cases = []
    def prepared(case_dir):
        def setup():
            clear(case_dir)
            os.makedirs(os.path.join(case_dir, "out"))
            for key, src in cmd.files.items():
                link_tree(src, os.path.join(case_dir, key))
        return setup
    def argv_for(case_dir, extra=()):
        words = []
        for w in cmd.argv:
            for key in cmd.files:
                w = w.replace("{%s}" % key, os.path.join(case_dir, key))
            words.append(w.replace("{out}", os.path.join(case_dir, "out")))
        return [cli] + words + list(extra)
    outputs = lambda case_dir: [os.path.join(case_dir, "out", o) for o in cmd.outputs]
    n = [0]
    def new_dir():
        n[0] += 1
        return os.path.join(work, "c", "%s-%d" % (cmd.tag, n[0]))
    # The valid run first: every hostile case is a change of it.
    d = new_dir()
    cases.append(Case("%s: valid" % cmd.tag, argv_for(d), fails=cmd.valid_fails, outputs=outputs(d), ok_codes=cmd.ok_codes,
                      setup=prepared(d), max_warnings=cmd.max_warnings))
    for slot, (variants, names) in cmd.slots.items():
        for vname, maker, fails in variants:
            d = new_dir()
            target = os.path.join(d, slot)
            def setup(d=d, target=target, maker=maker):
                prepared(d)()
                clear(target)
                os.makedirs(os.path.dirname(target), exist_ok=True)
                maker(target)
            cases.append(Case("%s: %s: %s" % (cmd.tag, slot, vname), argv_for(d), fails=fails,
                              names=tuple(names) + (slot.split("/")[0],), outputs=outputs(d),
                              ok_codes=cmd.ok_codes, setup=setup, max_warnings=cmd.max_warnings))
    for option, values in cmd.options:
        for value, fails in values:
            d = new_dir()
            argv = argv_for(d, [option, value] if value != "" else [option + "="])
            names = (option.lstrip("-"),) if fails else ()
            cases.append(Case("%s: %s %r" % (cmd.tag, option, value), argv, fails=fails, names=names,
                              outputs=outputs(d), ok_codes=cmd.ok_codes, setup=prepared(d),
                              max_warnings=cmd.max_warnings))
    return cases


def sh(argv, **kw):
    r = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, **kw)
    if r.returncode not in (0, 3):
        sys.exit("battery: setup failed: %s: %s" % (" ".join(argv), r.stderr.decode(errors="replace")[-400:]))
    return r


def build_base(cli, base):
    """The valid files every case starts from, made with the CLI itself."""
    if os.path.isdir(base):
        shutil.rmtree(base)
    os.makedirs(base)
    B = lambda *p: os.path.join(base, *p)
    sh([cli, "simulate", "--scenario", "wall", "--captures", "3", "--out", B("sim")])
    sh([cli, "simulate", "--scenario", "wall", "--structured-light", "--out", B("slsim")])
    sh([cli, "detect", "--cloud", B("sim", "cloud.pcd"), "--calib", B("sim", "calib.yaml"), "--json", B("det.json")])
    write(B("picture.png"), png(320, 200, 8, 2, 128))
    sh([cli, "correct", "--calib", B("sim", "calib.yaml"), "--detection", B("det.json"), "--image", B("picture.png"),
        "--out", B("fb.png")])
    os.makedirs(B("vcap"))
    for f in ("camera.yaml", "depth.png", "rgb.png"):
        os.link(B("sim", f), B("vcap", f))
    os.makedirs(B("depthdir"))
    for k in range(3):
        os.link(B("sim", "depth.png"), B("depthdir", "d%02d.png" % k))
    sh([cli, "bag", "--depth-dir", B("depthdir"), "--camera", B("sim", "camera.yaml"), "--out", B("depth.bag")])
    os.makedirs(B("frames"))
    for k in range(5):
        write(B("frames", "f_%03d.png" % k), png(160, 100, 8, 2, 40 * k))
    sh([cli, "correct", "--calib", B("sim", "calib.yaml"), "--detection", B("det.json"), "--video",
        B("frames", "f_%03d.png"), "--out", B("video.avi")])
    write(B("cloud.ply"), ply_ascii(wall_points()))
    write(B("small.pcd"), pcd_ascii(wall_points()))
    shutil.copy("config/detector.yaml", B("detector.yaml"))
    # Chessboard captures (two poses of the real excerpt) and a procam folder.
    with tarfile.open("tests/data/procam_excerpt/capture_1.tar") as tar:
        tar.extractall(B("excerpt"))
    for k in (1, 2):
        shutil.copytree(B("excerpt", "capture_1"), B("chess", "capture_%d" % k), copy_function=os.link)
    shutil.copytree(B("chess"), B("procam"), copy_function=os.link)
    write(B("procam", "calibration_result.xml"), PROCAM_XML)
    # The labelled frame the eval-labels cases read: one that ships in data/, so that the cases
    # run on a plain clone (the labelled frames of ../shared/data/real are not redistributed).
    os.makedirs(B("labels"))
    shutil.copy("labels/real/check/%s.yaml" % LABELLED_FRAME, B("labels", LABELLED_FRAME + ".yaml"))
    return B


PROCAM_XML = """<?xml version="1.0"?>
<opencv_storage>
<img_shape>1280 1024</img_shape>
<rms>0.5</rms>
<cam_int type_id="opencv-matrix"><rows>3</rows><cols>3</cols><dt>d</dt>
  <data>1000. 0. 640. 0. 1000. 512. 0. 0. 1.</data></cam_int>
<cam_dist type_id="opencv-matrix"><rows>1</rows><cols>5</cols><dt>d</dt><data>0. 0. 0. 0. 0.</data></cam_dist>
<proj_int type_id="opencv-matrix"><rows>3</rows><cols>3</cols><dt>d</dt>
  <data>1500. 0. 512. 0. 1500. 384. 0. 0. 1.</data></proj_int>
<proj_dist type_id="opencv-matrix"><rows>1</rows><cols>5</cols><dt>d</dt><data>0. 0. 0. 0. 0.</data></proj_dist>
<rotation type_id="opencv-matrix"><rows>3</rows><cols>3</cols><dt>d</dt><data>1. 0. 0. 0. 1. 0. 0. 0. 1.</data></rotation>
<translation type_id="opencv-matrix"><rows>3</rows><cols>1</cols><dt>d</dt><data>0.1 0. 0.</data></translation>
</opencv_storage>
"""


def procam_xml_variants():
    x = PROCAM_XML
    return content([
        ("rows-1e9", x.replace("<rows>3</rows><cols>3</cols>", "<rows>1000000000</rows><cols>1000000000</cols>", 1), True),
        ("data-nan", x.replace("1000. 0. 640.", "nan 0. 640.", 1), True),
        ("data-1e300", x.replace("1000. 0. 640.", "1e300 0. 640.", 1), True),
        ("deep-nesting", "<?xml version=\"1.0\"?>\n<opencv_storage>" + "<a>" * 50000 + "</a>" * 50000 + "</opencv_storage>\n", True),
        ("entity-bomb", "<?xml version=\"1.0\"?>\n<!DOCTYPE l [<!ENTITY a \"aaaaaaaaaa\">" +
         "".join("<!ENTITY a%d \"%s\">" % (i, ("&a%d;" % (i - 1) if i else "&a;") * 10) for i in range(9)) +
         "]>\n<opencv_storage><rms>&a8;</rms></opencv_storage>\n", True),
        ("matrix-missing", x.replace("proj_int", "proj_intx"), True),
        ("img-shape-zero", x.replace("1280 1024", "0 0"), True),
        ("non-utf8", x.encode().replace(b"<rms>0.5", b"<rms>\xff\xfe"), True),
    ])


# A labelled frame of the repository's data/ (labels/real/ holds its label).
LABELLED_FRAME = "tum_o3d_fr3_office_partition"


def label_variants(valid):
    return content([
        ("yaml-bomb", yaml_bomb("surfaces"), True),
        ("deep-nesting", "frame: " + "[" * 100000 + "]" * 100000 + "\n", True),
        ("frame-parent-path", valid.replace("frame: " + LABELLED_FRAME, "frame: ../../../../etc"), True),
        ("polygon-1e300", re.sub(r"polygon: \[\[[^\n]*\]\]", "polygon: [[0, 0], [1e300, 0], [1e300, 1e300], [0, 1e300]]", valid, count=1), True),
        ("polygon-nan", re.sub(r"polygon: \[\[[^\n]*\]\]", "polygon: [[0, 0], [.nan, 0], [10, 10], [0, 10]]", valid, count=1), True),
        ("polygon-100000-points", re.sub(r"polygon: \[\[[^\n]*\]\]", "polygon: [%s]" % ", ".join("[%d, %d]" % (i % 640, i % 480) for i in range(100000)), valid, count=1), True),
        ("gravity-zero", re.sub(r"vector: \[[^\]]*\]", "vector: [0, 0, 0]", valid, count=1), True),
        ("projector-fov-radians", valid.replace("fov_deg: [39.3, 24]", "fov_deg: [0.6, 0.4]"), True),
        ("non-utf8", valid.encode() + b"note2: \xff\xfe\n", None),
    ])


def read(path, text=True):
    data = open(path, "rb").read()
    return data.decode() if text else data


def commands(B):
    """Every reader and command, its inputs as slots."""
    g = lambda path: generic(read(path, False))
    calib, cam, depth, pcd = B("sim", "calib.yaml"), B("sim", "camera.yaml"), B("sim", "depth.png"), B("sim", "cloud.pcd")
    det = read(B("det.json"))
    w, h = 640, 480
    C = {}
    detect_opts = [("--gravity", BAD_TRIPLES), ("--aspect", BAD_ASPECTS), ("--min-width", BAD_NUMBERS),
                   ("--min-area", BAD_NUMBERS), ("--max-tilt", BAD_NUMBERS), ("--seed", BAD_NUMBERS),
                   ("--cell", BAD_NUMBERS), ("--max-planes", BAD_NUMBERS), ("--max-outlier-fraction", BAD_NUMBERS),
                   ("--method", [("magic", True), ("", True)])]
    paper_opts = [("--voxel-leaf", BAD_NUMBERS), ("--ransac-distance", BAD_NUMBERS), ("--max-outliers", BAD_NUMBERS),
                  ("--hull", [("magic", True)])]
    C["detect-cloud"] = Command("detect-cloud", ["detect", "--cloud", "{cloud.pcd}", "--calib", "{calib.yaml}",
                                                 "--json", "{out}/det.json", "--overlay", "{out}/ov.png"],
                                {"cloud.pcd": B("small.pcd"), "calib.yaml": calib},
                                {"cloud.pcd": (pcd_variants() + g(B("small.pcd")), ()),
                                 "calib.yaml": (calib_variants() + g(calib), ())},
                                outputs=("det.json", "ov.png"), options=detect_opts)
    C["detect-real-pcd"] = Command("detect-real-pcd", ["detect", "--cloud", "{cloud.pcd}", "--calib", "{calib.yaml}",
                                                       "--json", "{out}/det.json"],
                                   {"cloud.pcd": pcd, "calib.yaml": calib},
                                   {"cloud.pcd": (corrupt_variants(read(pcd, False)), ())}, outputs=("det.json",))
    C["detect-paper"] = Command("detect-paper", ["detect", "--method", "paper", "--cloud", "{cloud.pcd}", "--calib",
                                                 "{calib.yaml}", "--json", "{out}/det.json"],
                                {"cloud.pcd": B("small.pcd"), "calib.yaml": calib},
                                {"cloud.pcd": (pcd_variants(), ())}, outputs=("det.json",), options=paper_opts)
    C["detect-ply"] = Command("detect-ply", ["detect", "--cloud", "{cloud.ply}", "--calib", "{calib.yaml}",
                                             "--json", "{out}/det.json"],
                              {"cloud.ply": B("cloud.ply"), "calib.yaml": calib},
                              {"cloud.ply": (ply_variants() + g(B("cloud.ply")), ())}, outputs=("det.json",))
    C["detect-depth"] = Command("detect-depth", ["detect", "--depth", "{depth.png}", "--camera", "{camera.yaml}",
                                                 "--rgb", "{rgb.png}", "--calib", "{calib.yaml}", "--json",
                                                 "{out}/det.json", "--overlay", "{out}/ov.png"],
                                {"depth.png": depth, "camera.yaml": cam, "rgb.png": B("sim", "rgb.png"), "calib.yaml": calib},
                                {"depth.png": (depth_variants(w, h) + g(depth), ()),
                                 "camera.yaml": (camera_variants() + g(cam), ()),
                                 "rgb.png": (image_variants() + content([("other-size", png(320, 240, 8, 2, 9), True),
                                                                         ("grey-right-size", png(w, h, 8, 0, 9), None)]) +
                                             g(B("sim", "rgb.png")), ())},
                                outputs=("det.json", "ov.png"), max_warnings=3)
    C["detect-config"] = Command("detect-config", ["detect", "--cloud", "{cloud.pcd}", "--calib", "{calib.yaml}",
                                                   "--config", "{detector.yaml}", "--json", "{out}/det.json"],
                                 {"cloud.pcd": pcd, "calib.yaml": calib, "detector.yaml": B("detector.yaml")},
                                 {"detector.yaml": (config_variants() + valid_yaml_cuts(g(B("detector.yaml"))), ())},
                                 outputs=("det.json",))
    C["detect-bag"] = Command("detect-bag", ["detect", "--bag", "{depth.bag}", "--calib", "{calib.yaml}",
                                             "--json", "{out}/det.json"],
                              {"depth.bag": B("depth.bag"), "calib.yaml": calib},
                              {"depth.bag": (corrupt_variants(read(B("depth.bag"), False), 40) + g(B("depth.bag")), ())},
                              outputs=("det.json",), options=[("--topic", [("/no/such/topic", True), ("", True)])])
    correct_opts = [("--fps", BAD_NUMBERS)]
    C["correct"] = Command("correct", ["correct", "--calib", "{calib.yaml}", "--detection", "{det.json}", "--image",
                                       "{picture.png}", "--out", "{out}/fb.png", "--json", "{out}/c.json"],
                           {"calib.yaml": calib, "det.json": B("det.json"), "picture.png": B("picture.png")},
                           {"calib.yaml": (calib_variants() + g(calib), ("det.json",)),
                            "det.json": (detection_variants(det) + g(B("det.json")), ()),
                            "picture.png": (image_variants() + g(B("picture.png")), ())},
                           outputs=("fb.png", "c.json"))
    C["correct-blank-cloud"] = Command("correct-blank-cloud", ["correct", "--calib", "{calib.yaml}", "--detection",
                                                               "{det.json}", "--image", "{picture.png}", "--out",
                                                               "{out}/fb.png", "--json", "{out}/c.json", "--cloud", "{now.pcd}"],
                                       {"calib.yaml": calib, "det.json": B("det.json"), "picture.png": B("picture.png"),
                                        "now.pcd": B("small.pcd")},
                                       {"now.pcd": (pcd_variants() + g(B("small.pcd")), ())}, outputs=("fb.png", "c.json"))
    C["correct-blank-depth"] = Command("correct-blank-depth", ["correct", "--calib", "{calib.yaml}", "--detection",
                                                               "{det.json}", "--image", "{picture.png}", "--out",
                                                               "{out}/fb.png", "--depth", "{depth.png}", "--camera", "{camera.yaml}"],
                                       {"calib.yaml": calib, "det.json": B("det.json"), "picture.png": B("picture.png"),
                                        "depth.png": depth, "camera.yaml": cam},
                                       {"depth.png": (depth_variants(w, h) + g(depth), ()),
                                        "camera.yaml": (camera_variants(), ())}, outputs=("fb.png",))
    C["correct-video"] = Command("correct-video", ["correct", "--calib", "{calib.yaml}", "--detection", "{det.json}",
                                                   "--video", "{in.avi}", "--out", "{out}/v.avi"],
                                 {"calib.yaml": calib, "det.json": B("det.json"), "in.avi": B("video.avi")},
                                 {"in.avi": (corrupt_variants(read(B("video.avi"), False), 12) +
                                             [(n, m, None if n == "half" else f) for n, m, f in g(B("video.avi"))], ())},
                                 outputs=("v.avi",), options=correct_opts)
    C["correct-sequence"] = Command("correct-sequence", ["correct", "--calib", "{calib.yaml}", "--detection", "{det.json}",
                                                         "--video", "{frames}/f_%03d.png", "--out", "{out}/v.avi"],
                                    {"calib.yaml": calib, "det.json": B("det.json"), "frames": B("frames")},
                                    {"frames/f_001.png": (image_variants() + [(n, m, None if n == "missing" else f) for n, m, f in
                                                                              g(B("frames", "f_001.png"))], ("f_001",)),
                                     "frames/f_000.png": (content([("other-size", png(320, 100, 8, 2, 9), None)]), ())},
                                    outputs=("v.avi",))
    plan_opts = [("--width", BAD_NUMBERS), ("--max-move", BAD_NUMBERS), ("--gravity", BAD_TRIPLES),
                 ("--aspect", BAD_ASPECTS)]
    C["plan-cloud"] = Command("plan-cloud", ["plan", "--cloud", "{cloud.pcd}", "--calib", "{calib.yaml}", "--json",
                                             "{out}/plan.json", "--overlay", "{out}/ov.png"],
                              {"cloud.pcd": B("small.pcd"), "calib.yaml": calib},
                              {"cloud.pcd": (pcd_variants() + g(B("small.pcd")), ()),
                               "calib.yaml": (calib_variants(), ())},
                              outputs=("plan.json", "ov.png"), options=plan_opts)
    C["plan-depth"] = Command("plan-depth", ["plan", "--depth", "{depth.png}", "--camera", "{camera.yaml}", "--calib",
                                             "{calib.yaml}", "--json", "{out}/plan.json", "--config", "{detector.yaml}"],
                              {"depth.png": depth, "camera.yaml": cam, "calib.yaml": calib,
                               "detector.yaml": B("detector.yaml")},
                              {"depth.png": (depth_variants(w, h) + g(depth), ()),
                               "camera.yaml": (camera_variants(), ()),
                               "detector.yaml": (config_variants(), ())}, outputs=("plan.json",))
    C["verify"] = Command("verify", ["verify", "--calib", "{calib.yaml}", "--detection", "{det.json}", "--framebuffer",
                                     "{fb.png}", "--captures", "{vcap}", "--json", "{out}/v.json"],
                          {"calib.yaml": calib, "det.json": B("det.json"), "fb.png": B("fb.png"), "vcap": B("vcap")},
                          {"calib.yaml": (calib_variants(), ()),
                           "det.json": (detection_variants(det), ()),
                           "fb.png": (image_variants() + g(B("fb.png")), ()),
                           "vcap": (folder_variants(), ()),
                           "vcap/camera.yaml": (camera_variants() + g(cam), ("camera.yaml",)),
                           "vcap/depth.png": (depth_variants(w, h) + g(depth), ("depth.png",)),
                           "vcap/rgb.png": (image_variants() + content([("other-size", png(320, 240, 8, 2, 9), True)]) +
                                            g(B("sim", "rgb.png")), ("rgb.png",))},
                          outputs=("v.json",), ok_codes=(0, 3),
                          options=[("--tolerance", BAD_NUMBERS)])
    C["verify-card"] = Command("verify-card", ["verify", "--write-card", "{out}/card.png"], {}, {},
                               outputs=("card.png",), options=[("--resolution", BAD_PAIRS)])
    disc = B("sim", "captures")
    C["calibrate-disc"] = Command("calibrate-disc", ["calibrate", "--captures", "{captures}", "--out", "{out}/calib.yaml"],
                                  {"captures": disc},
                                  {"captures": (folder_variants(), ()),
                                   "captures/camera.yaml": (camera_variants() + g(os.path.join(disc, "camera.yaml")), ("camera.yaml",)),
                                   "captures/capture_0_rgb.png": (image_variants() + content([("other-size", png(320, 240, 8, 2, 9), True)]) +
                                                                  g(os.path.join(disc, "capture_0_rgb.png")), ("capture_0_rgb",)),
                                   "captures/capture_0_depth.png": (depth_variants(w, h) + g(os.path.join(disc, "capture_0_depth.png")),
                                                                    ("capture_0_depth",)),
                                   "captures/capture_100_rgb.png": (content([("beyond-99", read(os.path.join(disc, "capture_0_rgb.png"), False), None)]), ())},
                                  outputs=("calib.yaml",), ok_codes=(0, 3),
                                  options=[("--fov-deg", BAD_PAIRS[:1] + [("0.6,0.4", True), ("180,180", True)]),
                                           ("--resolution", BAD_PAIRS), ("--threshold", BAD_NUMBERS + [("300", True)])])
    C["calibrate-picture"] = Command("calibrate-picture", ["calibrate", "--write-picture", "{out}/pic.png"], {}, {},
                                     outputs=("pic.png",), options=[("--resolution", BAD_PAIRS)])
    sl = B("slsim", "structured")
    names = [l.strip() for l in re.findall(r"order:\s*\[([^\]]*)\]", read(os.path.join(sl, "patterns.yaml")))[0].split(",")] \
        if "order: [" in read(os.path.join(sl, "patterns.yaml")) else \
        re.findall(r"^\s+- (\S+)$", read(os.path.join(sl, "patterns.yaml")), re.M)
    first = names[0]
    C["calibrate-structured"] = Command(
        "calibrate-structured", ["calibrate", "--captures", "{structured}", "--out", "{out}/calib.yaml"],
        {"structured": sl},
        {"structured/patterns.yaml": (patterns_yaml_variants(names) + g(os.path.join(sl, "patterns.yaml")), ("patterns.yaml",)),
         "structured/camera.yaml": (camera_variants() + content([("camera-3490-square", camera_yaml(width=3490, height=3490, cx=1744.5, cy=1744.5, fx=2800, fy=2800), True)]), ("camera.yaml",)),
         "structured/pose_0": (folder_variants(), ("pose_0",)),
         "structured/pose_0/depth.png": (depth_variants(w, h) + g(os.path.join(sl, "pose_0", "depth.png")), ("depth.png",)),
         "structured/pose_0/%s.png" % first: (image_variants() + content([("other-size", png(320, 240, 8, 0, 9), True)]) +
                                              g(os.path.join(sl, "pose_0", first + ".png")), (first,)),
         "structured/pose_1": (content([("pose-1-a-file", b"x", True)]) +
                               [("pose-1-links-to-pose-0", lambda p: os.symlink("pose_0", p), None)], ("pose_1",)),
         "structured/pose_7": ([("pose-gap-link", lambda p: os.symlink("pose_0", p), None)], ())},
        outputs=("calib.yaml",), ok_codes=(0, 3))
    chess = B("chess")
    C["calibrate-chessboard"] = Command(
        "calibrate-chessboard", ["calibrate", "--captures", "{chess}", "--square-m", "0.075", "--resolution", "1024,768",
                                 "--out", "{out}/calib.yaml"],
        {"chess": chess},
        {"chess/capture_1/graycode_00.png": (image_variants() + content([("other-size", png(80, 80, 8, 0, 9), True)]) +
                                             g(os.path.join(chess, "capture_1", "graycode_00.png")), ("graycode_00",)),
         "chess/capture_2": (folder_variants()[1:4], ("capture_2",))},
        outputs=("calib.yaml",), ok_codes=(0, 3), valid_fails=None,
        options=[("--square-m", BAD_NUMBERS)])
    C["patterns"] = Command("patterns", ["patterns", "--out", "{out}/pat"], {}, {},
                            outputs=("pat/",), options=[("--resolution", BAD_PAIRS)])
    C["patterns-out"] = Command("patterns-out", ["patterns", "--resolution", "64,32", "--out", "{target}"],
                                {"target": B("frames")}, {"target": (folder_variants()[1:4], ())})
    C["bag"] = Command("bag", ["bag", "--depth-dir", "{depthdir}", "--camera", "{camera.yaml}", "--out", "{out}/o.bag"],
                       {"depthdir": B("depthdir"), "camera.yaml": cam},
                       {"depthdir": (folder_variants(), ()),
                        "depthdir/d01.png": (depth_variants(w, h) + [(n, m, None if n == "missing" else f) for n, m, f in
                                                                     g(os.path.join(B("depthdir"), "d01.png"))], ("d01",)),
                        "camera.yaml": (camera_variants() + g(cam), ())},
                       outputs=("o.bag",),
                       options=[("--fps", BAD_NUMBERS), ("--start", BAD_NUMBERS),
                                ("--frame-id", [("\udcff\udcfe", True), ("x" * 100000, None)]),
                                ("--topic", [("", True), ("\udcff", True)])])
    C["simulate"] = Command("simulate", ["simulate", "--scenario", "wall", "--calib", "{calib.yaml}", "--out", "{out}/s"],
                            {"calib.yaml": calib}, {"calib.yaml": (calib_variants() + g(calib), ())},
                            options=[("--distance", BAD_NUMBERS), ("--angle-deg", BAD_NUMBERS),
                                     ("--roll-deg", BAD_NUMBERS), ("--pitch-deg", BAD_NUMBERS),
                                     ("--captures", BAD_NUMBERS + [("1000000000", True), ("200", True)]),
                                     ("--unit", BAD_NUMBERS + [("1000000000", True)]), ("--seed", BAD_NUMBERS),
                                     ("--sensor", [("magic", True)]), ("--scenario", [("magic", True)]),
                                     ("--aspect", BAD_ASPECTS)])
    C["show"] = Command("show", ["show", "--seconds", "1", "--image", "{fb.png}"], {"fb.png": B("fb.png")},
                        {"fb.png": (image_variants() + g(B("fb.png")), ("display",))}, valid_fails=None,
                        options=[("--seconds", BAD_NUMBERS), ("--screen-index", BAD_NUMBERS)])
    C["eval-procam"] = Command("eval-procam", ["eval", "--no-progress", "--procam", "{procam}", "--out", "{out}/e",
                                               "--json", "{out}/p.json"],
                               {"procam": B("procam")},
                               {"procam/calibration_result.xml": (procam_xml_variants() + g(os.path.join(B("procam"), "calibration_result.xml")),
                                                                  ("calibration_result.xml",)),
                                "procam": (folder_variants(), ())},
                               outputs=("p.json",), options=[("--square-m", BAD_NUMBERS)], valid_fails=None)
    lab = read(B("labels", LABELLED_FRAME + ".yaml"))
    C["eval-labels"] = Command("eval-labels", ["eval", "--no-progress", "--labelled-only", "--labels", "{labels}",
                                               "--real-dir", os.path.abspath("data"), "--out", "{out}/e"],
                               {"labels": B("labels")},
                               {"labels/%s.yaml" % LABELLED_FRAME: (label_variants(lab) + g(B("labels", LABELLED_FRAME + ".yaml")),
                                                                    (LABELLED_FRAME,)),
                                "labels": (folder_variants(), ())})
    C["eval-options"] = Command("eval-options", ["eval", "--no-progress", "--quick", "--out", "{out}/e"], {}, {},
                                options=[("--rounds", [("0", True), ("-1", True), ("nan", True), ("1000000000", True)]),
                                         ("--seed", [("nan", True), ("-1", True)])])
    return C


# ---------------------------------------------------------------- the Python module
PY_PRELUDE = """
import sys, math
sys.path.insert(0, %(pydir)r)
import numpy as np
import projsurf
P = projsurf.read_calibration(%(calib)r)
def wall(h=48, w=64, z=2.0, f=52.5):
    v, u = np.mgrid[0:h, 0:w].astype(np.float32)
    pts = np.stack([(u - w / 2) / f * z, (v - h / 2) / f * z, np.full((h, w), z, np.float32)], -1)
    pts[h * 2 // 3:, :, 1] = 1.0
    return pts.astype(np.float32)
DET = projsurf.detect(wall(480, 640, f=525), P)
try:
    result = (%(expr)s)
except projsurf.InputError as e:
    text = str(e)
    if "\\n" in text or not text:
        print("InputError of %%d lines" %% len(text.split("\\n")), file=sys.stderr)
        sys.exit(1)
    print("projsurf: error: " + text, file=sys.stderr)
    sys.exit(2)
print("ok")
"""


def python_cases(cli, pydir, B, work):
    calib = B("sim", "calib.yaml")
    exprs = [
        # images and depth: sizes before any copy, types, dtypes
        ("correct-huge-broadcast", "projsurf.correct(np.broadcast_to(np.uint8(1), (2**20, 2**20, 3)), P, DET)", True),
        ("write-image-huge-broadcast", "projsurf.write_image(%r, np.broadcast_to(np.uint8(1), (2**20, 2**20, 3)))" % os.path.join(work, "py.png"), True),
        ("depth-to-cloud-huge-broadcast", "projsurf.depth_to_cloud(np.broadcast_to(np.uint16(1000), (2**20, 2**20)), fx=525, fy=525, cx=320, cy=240)", True),
        ("correct-zero-size", "projsurf.correct(np.zeros((0, 0, 3), np.uint8), P, DET)", True),
        ("correct-4d", "projsurf.correct(np.zeros((4, 4, 3, 2), np.uint8), P, DET)", True),
        ("correct-5-channels", "projsurf.correct(np.zeros((4, 4, 5), np.uint8), P, DET)", True),
        ("correct-float64", "projsurf.correct(np.zeros((4, 4, 3), np.float64), P, DET)", None),
        ("correct-float-nan", "projsurf.correct(np.full((4, 4, 3), np.nan, np.float32), P, DET)", None),
        ("correct-object-array", "projsurf.correct(np.array([[None]]), P, DET)", True),
        ("correct-strided", "projsurf.correct(np.zeros((64, 64, 3), np.uint8)[::-3, ::7], P, DET)", None),
        ("correct-tolerance-nan", "projsurf.correct(np.zeros((8, 8, 3), np.uint8), P, DET, tolerance_px=math.nan)", True),
        ("correct-tolerance-negative", "projsurf.correct(np.zeros((8, 8, 3), np.uint8), P, DET, tolerance_px=-1)", True),
        ("correct-detection-corners-nan", "projsurf.correct(np.zeros((8, 8, 3), np.uint8), P, np.full((4, 3), np.nan))", True),
        ("correct-detection-corners-1e300", "projsurf.correct(np.zeros((8, 8, 3), np.uint8), P, np.full((4, 3), 1e300))", True),
        ("correct-detection-corners-shape", "projsurf.correct(np.zeros((8, 8, 3), np.uint8), P, np.zeros((3, 3)))", True),
        ("correct-detection-dict-empty", "projsurf.correct(np.zeros((8, 8, 3), np.uint8), P, {})", True),
        ("correct-detection-not-found", "projsurf.correct(np.zeros((8, 8, 3), np.uint8), P, {'found': False})", True),
        ("correct-detection-string", "projsurf.correct(np.zeros((8, 8, 3), np.uint8), P, 'det.json')", True),
        ("keystone-size-nan", "projsurf.keystone(P, DET, (math.nan, 10))", True),
        ("keystone-size-huge", "projsurf.keystone(P, DET, (1e300, 1e300))", True),
        ("write-image-path-nul", "projsurf.write_image('a\\0b.png', np.zeros((4, 4), np.uint8))", True),
        ("write-image-bool", "projsurf.write_image(%r, np.zeros((4, 4), bool))" % os.path.join(work, "pyb.png"), None),
        ("write-image-int64", "projsurf.write_image(%r, np.zeros((4, 4), np.int64))" % os.path.join(work, "pyi.png"), True),
        ("write-image-to-fifo-dir", "projsurf.write_image('/proc/self/nonexistent/x.png', np.zeros((4, 4), np.uint8))", True),
        ("depth-to-cloud-fx-nan", "projsurf.depth_to_cloud(np.zeros((48, 64), np.uint16), fx=math.nan, fy=525, cx=32, cy=24)", True),
        ("depth-to-cloud-fx-1e-300", "projsurf.depth_to_cloud(np.zeros((48, 64), np.uint16), fx=1e-300, fy=1e-300, cx=32, cy=24)", True),
        ("depth-to-cloud-scale-zero", "projsurf.depth_to_cloud(np.zeros((48, 64), np.uint16), fx=52, fy=52, cx=32, cy=24, depth_scale=0)", True),
        ("depth-to-cloud-float", "projsurf.depth_to_cloud(np.zeros((48, 64), np.float32), fx=52, fy=52, cx=32, cy=24)", None),
        ("depth-to-cloud-3d", "projsurf.depth_to_cloud(np.zeros((48, 64, 3), np.uint16), fx=52, fy=52, cx=32, cy=24)", True),
        ("depth-to-cloud-all-65535", "projsurf.depth_to_cloud(np.full((48, 64), 65535, np.uint16), fx=52, fy=52, cx=32, cy=24)", None),
        # points
        ("detect-broadcast-2-40", "projsurf.detect(np.broadcast_to(np.float32(1), (2**40, 3)), P)", True),
        ("detect-over-limit-by-one", "projsurf.detect(np.broadcast_to(np.float32(1), (2**24 + 1, 3)), P)", True),
        ("detect-organized-over-limit", "projsurf.detect(np.broadcast_to(np.float32(1), (4097, 4096, 3)), P)", True),
        ("detect-empty", "projsurf.detect(np.zeros((0, 3), np.float32), P)", None),
        ("detect-all-nan", "projsurf.detect(np.full((1000, 3), np.nan, np.float32), P)", None),
        ("detect-one-far-point", "projsurf.detect(np.array([[1e20, 0, 1e20]], np.float32), P)", None),
        ("detect-inf", "projsurf.detect(np.full((1000, 3), np.inf, np.float32), P)", None),
        ("detect-float64-1e300", "projsurf.detect(np.full((1000, 3), 1e300), P)", None),
        ("detect-two-columns", "projsurf.detect(np.zeros((1000, 2), np.float32), P)", True),
        ("detect-strings", "projsurf.detect(np.array([['a', 'b', 'c']]), P)", True),
        ("detect-list", "projsurf.detect([[0, 0, 2]] * 10, P)", None),
        ("detect-gravity-nan", "projsurf.detect(wall(), P, gravity=(math.nan, 1, 0))", True),
        ("detect-gravity-zero", "projsurf.detect(wall(), P, gravity=(0, 0, 0))", True),
        ("detect-aspect-zero", "projsurf.detect(wall(), P, aspect=0)", True),
        ("detect-aspect-nan", "projsurf.detect(wall(), P, aspect=math.nan)", True),
        ("detect-seed-huge", "projsurf.detect(wall(), P, seed=2**80)", True),
        ("detect-min-width-nan", "projsurf.detect(wall(), P, min_width=math.nan)", True),
        ("detect-unknown-setting", "projsurf.detect(wall(), P, max_planez=3)", True),
        ("detect-setting-out-of-range", "projsurf.detect(wall(), P, cell=1e-9)", True),
        ("detect-colour-wrong-size", "projsurf.detect(wall(), P, colour=np.zeros((2, 2, 3), np.uint8))", True),
        ("detect-colour-broadcast-huge", "projsurf.detect(wall(), P, colour=np.broadcast_to(np.uint8(1), (2**20, 2**20, 3)))", True),
        ("detect-config-bomb", "projsurf.detect(wall(), P, config=%r)" % os.path.join(work, "py-bomb.yaml"), True),
        ("detect-config-non-utf8", "projsurf.detect(wall(), P, config=%r)" % os.path.join(work, "py-nonutf8.yaml"), True),
        ("detect-config-fifo", "projsurf.detect(wall(), P, config=%r)" % os.path.join(work, "py-fifo"), True),
        ("detector-detect-huge", "projsurf.Detector(P).detect(np.broadcast_to(np.float32(1), (2**40, 3)))", True),
        ("plan-far-point", "projsurf.plan(np.array([[-1e20, 0, 2]] * 10, np.float32), P)", None),
        ("plan-max-move-1e300", "projsurf.plan(wall(), P, max_move=1e300)", True),
        ("plan-width-nan", "projsurf.plan(wall(), P, width=math.nan)", True),
        ("plan-huge-broadcast", "projsurf.plan(np.broadcast_to(np.float32(1), (2**40, 3)), P)", True),
        # the projector
        ("projector-radians", "projsurf.Projector(fov_deg=(0.6, 0.4))", True),
        ("projector-origin-1e300", "projsurf.Projector(origin=[1e300, 0, 0])", True),
        ("projector-origin-nan", "projsurf.Projector(origin=[math.nan, 0, 0])", True),
        ("projector-direction-zero", "projsurf.Projector(direction=[0, 0, 0])", True),
        ("projector-resolution-huge", "projsurf.Projector(resolution=(16384, 16384))", True),
        ("projector-resolution-negative", "projsurf.Projector(resolution=(-1, 800))", True),
        ("projector-resolution-bool", "projsurf.Projector(resolution=(True, True))", True),
        ("projector-fov-180", "projsurf.Projector(fov_deg=(180, 180))", True),
        ("projector-fov-string", "projsurf.Projector(fov_deg='wide')", True),
        ("projector-fov-dict", "projsurf.Projector(fov_deg={1: 2})", True),
        ("projector-fov-generator", "projsurf.Projector(fov_deg=(x for x in (39.3, 24)))", None),
        ("to-pixel-nan", "P.to_pixel([math.nan, 0, 2])", None),
        ("to-pixel-wrong", "P.to_pixel('x')", True),
        ("to-pixel-behind", "P.to_pixel([0, 0, -2])", None),
        # files
        ("read-calibration-fifo", "projsurf.read_calibration(%r)" % os.path.join(work, "py-fifo"), True),
        ("read-calibration-bomb", "projsurf.read_calibration(%r)" % os.path.join(work, "py-bomb.yaml"), True),
        ("read-calibration-bytes-path", "projsurf.read_calibration(b'\\xff\\xfe')", True),
        ("read-calibration-none", "projsurf.read_calibration(None)", True),
        ("read-calibration-int", "projsurf.read_calibration(3)", True),
        ("read-cloud-fifo", "projsurf.read_cloud(%r)" % os.path.join(work, "py-fifo"), True),
        ("read-cloud-width-1e9", "projsurf.read_cloud(%r)" % os.path.join(work, "py-huge.pcd"), True),
        ("read-cloud-dev-zero", "projsurf.read_cloud('/dev/zero')", True),
        ("read-image-fifo", "projsurf.read_image(%r)" % os.path.join(work, "py-fifo"), True),
        ("read-image-header-huge", "projsurf.read_image(%r)" % os.path.join(work, "py-huge.png"), True),
        ("read-depth-cloud-degenerate-camera", "projsurf.read_depth_cloud(%r, %r)" % (B("sim", "depth.png"), os.path.join(work, "py-cam.yaml")), True),
        ("read-depth-cloud-fifo", "projsurf.read_depth_cloud(%r, %r)" % (os.path.join(work, "py-fifo"), B("sim", "camera.yaml")), True),
        ("write-calibration-not-projector", "projsurf.write_calibration(%r, 'P')" % os.path.join(work, "pyc.yaml"), True),
        ("write-calibration-to-dir", "projsurf.write_calibration(%r, P)" % work, True),
    ]
    def setup():
        if not os.path.exists(os.path.join(work, "py-fifo")):
            os.mkfifo(os.path.join(work, "py-fifo"))
        write(os.path.join(work, "py-bomb.yaml"), yaml_bomb("projector"))
        write(os.path.join(work, "py-nonutf8.yaml"), b"method: \xff\xfe\n")
        write(os.path.join(work, "py-huge.pcd"), pcd_ascii([(0, 0, 2)] * 3, width=1000000000, header_points=1000000000))
        write(os.path.join(work, "py-huge.png"), png(65535, 65535, 8, 2, ihdr_only=True))
        write(os.path.join(work, "py-cam.yaml"), camera_yaml(fx="1e-300", fy="1e-300"))
    cases = []
    for name, expr, fails in exprs:
        code = PY_PRELUDE % dict(pydir=pydir, calib=calib, expr=expr)
        cases.append(Case("python: " + name, ["/usr/bin/python3", "-c", code], fails=fails, setup=setup,
                          env={"PYTHONWARNINGS": "ignore"}, cwd=work))
    return cases


# ---------------------------------------------------------------- main
def main():
    global TIMEOUT_S
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cli")
    ap.add_argument("--work", default="/tmp/projsurf-hostile")
    ap.add_argument("--python-dir")
    ap.add_argument("--only", help="run the cases whose name matches this regular expression")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--verbose", action="store_true", help="a line per case, passed or not")
    ap.add_argument("--jobs", type=int, default=2, help="cases run at once (default 2)")
    ap.add_argument("--rss-limit-mib", type=int, default=2048,
                    help="peak memory a case may take (default 2048; ASan's shadow memory needs more)")
    ap.add_argument("--every", type=int, default=1,
                    help="run every Nth case of each input (its valid run always), for slow builds")
    ap.add_argument("--timeout-s", type=int, default=TIMEOUT_S,
                    help="a case running longer is a hang (default %d s; ASan runs several times slower)" % TIMEOUT_S)
    ap.add_argument("--offset", type=int, default=0,
                    help="with --every N: start at this case (0..N-1), so two runs can take different cases")
    a = ap.parse_args()
    cli = os.path.abspath(a.cli)
    RSS_LIMIT_KIB[0] = a.rss_limit_mib * 1024
    TIMEOUT_S = a.timeout_s
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    work = os.path.abspath(a.work)
    B = build_base(cli, os.path.join(work, "base"))
    if os.path.isdir(os.path.join(work, "c")):
        shutil.rmtree(os.path.join(work, "c"))
    cases = []
    for cmd in commands(B).values():
        cases += make_cases(cmd, cli, work)
    cases = [c for c in cases if not (c.name.startswith("eval-options: valid"))]
    if a.python_dir:
        cases += python_cases(cli, os.path.abspath(a.python_dir), B, work)
    if a.only:
        cases = [c for c in cases if re.search(a.only, c.name)]
    if a.every > 1:
        cases = [c for i, c in enumerate(cases) if i % a.every == a.offset % a.every or c.name.endswith(": valid")]
    if a.list:
        print("\n".join(c.name for c in cases))
        return 0
    failed, worst_rss, worst_time = [], (0, ""), (0, "")
    t0 = time.time()
    import concurrent.futures
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs)
    for c, (problems, rc, wall, rss, first) in zip(cases, pool.map(lambda c: run_case(c, work), cases)):
        worst_rss = max(worst_rss, (rss, c.name))
        worst_time = max(worst_time, (wall, c.name))
        if problems:
            failed.append(c.name)
            print("FAIL %s [exit %s, %.1f s, %d MiB]: %s" % (c.name, rc, wall, rss, "; ".join(problems)), flush=True)
        elif a.verbose:
            print("ok   %s [exit %s, %.1f s, %d MiB] %s" % (c.name, rc, wall, rss, first[0][:150] if first else ""), flush=True)
    print("battery: %d cases, %d passed, %d failed; peak RSS %d MiB (%s), longest %.1f s (%s); %.0f s in all" %
          (len(cases), len(cases) - len(failed), len(failed), worst_rss[0], worst_rss[1], worst_time[0],
           worst_time[1], time.time() - t0))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
