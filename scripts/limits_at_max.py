#!/usr/bin/env python3
"""Inputs at projsurf's limits (docs/limits.md), each run through the CLI under GNU time:
prints peak memory and wall time per case. usage: limits_at_max.py PROJSURF_BINARY WORK_DIR [GROUPS]
GROUPS: a comma-separated subset of readers,structured,plan,round3 (default all of them).
(needs about 2 GB of disk in WORK_DIR; takes a few minutes)."""
import array, os, struct, subprocess, sys, zlib

cli, work = sys.argv[1], sys.argv[2]
groups = sys.argv[3].split(",") if len(sys.argv) > 3 else ["readers", "structured", "plan", "round3"]
os.makedirs(work, exist_ok=True)
P = lambda n: os.path.join(work, n)

def calib(path, w, h):
    open(path, "w").write("projector:\n  resolution: [%d, %d]\n  fov_deg: [39.3, 24]\n  axis:\n"
                          "    origin: [0, 0.12, 0]\n    direction: [0, -0.05, 0.9987]\n" % (w, h))

def png_gray16(path, w, h, value):
    # A valid 16-bit grey PNG, every pixel `value`, written row by row.
    raw = zlib.compressobj(9)
    row = b"\x00" + struct.pack(">H", value) * w
    data = b"".join(raw.compress(row) for _ in range(h)) + raw.flush()
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    open(path, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 16, 0, 0, 0, 0)) +
                           chunk(b"IDAT", data) + chunk(b"IEND", b""))

def png_rgb8(path, w, h):
    raw = zlib.compressobj(6)
    row = b"\x00" + bytes((x * 7) & 255 for x in range(3 * w))
    data = b"".join(raw.compress(row) for _ in range(h)) + raw.flush()
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    open(path, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                           chunk(b"IDAT", data) + chunk(b"IEND", b""))

def wall_pcd(path, w, h):
    # An organized binary PCD of a wall 2 m ahead seen by a w x h pinhole camera.
    f = 0.8 * w
    with open(path, "wb") as out:
        out.write(("VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH %d\nHEIGHT %d\n"
                   "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS %d\nDATA binary\n" % (w, h, w * h)).encode())
        for v in range(h):
            y = (v - h / 2) / f * 2.0
            row = array.array("f")
            for u in range(w):
                row.extend(((u - w / 2) / f * 2.0, y, 2.0))
            out.write(row.tobytes())

def lzf_zeros(n):
    # An LZF stream of n zero bytes: one literal, then back references of 264 bytes.
    out = bytearray(b"\x00\x00")
    left = n - 1
    while left > 0:
        k = min(left, 264)
        if k >= 9: out += bytes((7 << 5, k - 9, 0))
        elif k >= 3: out += bytes(((k - 2) << 5, 0))
        else:
            out += bytes((k - 1,)) + b"\x00" * k
        left -= k
    return bytes(out)

def compressed_pcd(path, points, pad):
    raw = points * 4 * (3 + pad)
    comp = lzf_zeros(raw)
    with open(path, "wb") as out:
        out.write(("VERSION 0.7\nFIELDS x y z pad\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 %d\nWIDTH %d\nHEIGHT 1\n"
                   "POINTS %d\nDATA binary_compressed\n" % (pad, points, points)).encode())
        out.write(struct.pack("<II", len(comp), raw) + comp)

def run(name, args):
    r = subprocess.run(["/usr/bin/time", "-f", "%M %e", cli] + args, capture_output=True, text=True)
    kib, secs = r.stderr.strip().splitlines()[-1].split()
    err = r.stderr.strip().splitlines()[:-1]
    print("| %s | %d | %.1f MiB | %s s | %s |" % (name, r.returncode, int(kib) / 1024, secs, (err[0] if err else "")[:90]))
    sys.stdout.flush()

print("| case | exit | peak memory | wall time | stderr |\n|---|---:|---:|---:|---|")
calib(P("calib.yaml"), 1280, 800)

def readers():
  wall_pcd(P("wall_4096.pcd"), 4096, 4096)
  run("detect: 4096 x 4096 organized cloud (2^24 points, the limit)", ["detect", "--calib", P("calib.yaml"), "--cloud", P("wall_4096.pcd"), "--json", P("o1.json")])
  run("detect --method paper: the same cloud", ["detect", "--calib", P("calib.yaml"), "--cloud", P("wall_4096.pcd"), "--method", "paper", "--json", P("o2.json")])
  run("detect --overlay: the same cloud", ["detect", "--calib", P("calib.yaml"), "--cloud", P("wall_4096.pcd"), "--json", P("o3.json"), "--overlay", P("o3.png")])
  compressed_pcd(P("lzf_max.pcd"), 1 << 24, 5)
  run("detect: binary_compressed, 2^24 points of 32 B = 512 MiB decompressed (the limit)", ["detect", "--calib", P("calib.yaml"), "--cloud", P("lzf_max.pcd"), "--json", P("o4.json")])
  open(P("camera.yaml"), "w").write("camera: {width: 4096, height: 4096, fx: 3277, fy: 3277, cx: 2048, cy: 2048}\n")
  png_gray16(P("depth_4096.png"), 4096, 4096, 2000)
  run("detect --depth: 4096 x 4096 depth PNG (2^24 pixels, the limit) + overlay", ["detect", "--calib", P("calib.yaml"), "--depth", P("depth_4096.png"), "--camera", P("camera.yaml"), "--json", P("o5.json"), "--overlay", P("o5.png")])
  png_rgb8(P("picture_8k.png"), 7680, 4320)
  calib(P("calib_8k.yaml"), 7680, 4320)
  run("detect for correct (8K framebuffer)", ["detect", "--calib", P("calib_8k.yaml"), "--cloud", P("wall_4096.pcd"), "--json", P("det8k.json")])
  run("correct: 7680 x 4320 picture into a 7680 x 4320 framebuffer (the limits)", ["correct", "--calib", P("calib_8k.yaml"), "--detection", P("det8k.json"), "--image", P("picture_8k.png"), "--out", P("fb8k.png"), "--json", P("k8k.json")])

def png_gray8_rows(path, w, h, row_of):
    # An 8-bit grey PNG whose row y is row_of(y) (bytes of length w); equal rows cost nothing.
    raw = zlib.compressobj(1)
    data = b"".join(raw.compress(b"\x00" + row_of(y)) for y in range(h)) + raw.flush()
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    open(path, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0)) +
                           chunk(b"IDAT", data) + chunk(b"IEND", b""))

def structured_folder(d, w, h, lit, poses=1):
    # patterns.yaml for 1280 x 800, camera.yaml of w x h, pose_0 with a capture of every pattern:
    # lit: the framebuffer seen scaled onto the whole camera image (every pixel decodes) on a
    # flat wall 2 m away; else all black. Further poses are links to pose_0.
    os.makedirs(os.path.join(d, "pose_0"), exist_ok=True)
    subprocess.run([cli, "patterns", "--out", d, "--resolution", "1280,800"], check=True, capture_output=True)
    names = [l.strip()[2:] for l in open(os.path.join(d, "patterns.yaml")) if l.strip().startswith("- ")]
    open(os.path.join(d, "camera.yaml"), "w").write(
        "camera: {width: %d, height: %d, fx: %g, fy: %g, cx: %g, cy: %g, depth_scale: 1000}\n"
        % (w, h, 0.8 * w, 0.8 * w, (w - 1) / 2, (h - 1) / 2))
    png_gray16(os.path.join(d, "pose_0", "depth.png"), w, h, 2000 if lit else 0)
    u = [x * 1280 // w for x in range(w)]
    v = [y * 800 // h for y in range(h)]
    for n in names:
        if not lit or n == "black":
            const = bytes(w) if (n == "black" or not lit) else None
            png_gray8_rows(os.path.join(d, "pose_0", n + ".png"), w, h, lambda y: const)
            continue
        if n == "white":
            png_gray8_rows(os.path.join(d, "pose_0", n + ".png"), w, h, lambda y: b"\xff" * w)
            continue
        axis, bit = n.split("_")[0], int(n.split("_")[1])
        inv = n.endswith("_inv")
        on = lambda i: (((i ^ (i >> 1)) >> bit) & 1) != inv
        if axis == "col":
            row = bytes(255 if on(c) else 0 for c in u)
            png_gray8_rows(os.path.join(d, "pose_0", n + ".png"), w, h, lambda y: row)
        else:
            rows = {False: bytes(w), True: b"\xff" * w}
            png_gray8_rows(os.path.join(d, "pose_0", n + ".png"), w, h, lambda y: rows[on(v[y])])
    for k in range(1, poses):
        if not os.path.exists(os.path.join(d, "pose_%d" % k)): os.symlink("pose_0", os.path.join(d, "pose_%d" % k))

def structured():
  structured_folder(P("sl_dark"), 3490, 3490, lit=False)
  run("calibrate: structured light, 44 all-black 3490 x 3490 captures (2 MB of PNG)", ["calibrate", "--captures", P("sl_dark"), "--out", P("sl1.yaml")])
  structured_folder(P("sl_dark39"), 3490, 3490, lit=False, poses=39)
  run("calibrate: the same, 39 poses (38 links)", ["calibrate", "--captures", P("sl_dark39"), "--out", P("sl2.yaml")])
  structured_folder(P("sl_lit"), 3740, 3740, lit=True)
  run("calibrate: structured light, one pose of 44 lit 3740 x 3740 captures, every pixel decoded (at the byte limit)", ["calibrate", "--captures", P("sl_lit"), "--out", P("sl3.yaml")])
  structured_folder(P("sl_lit1080"), 1920, 1080, lit=True, poses=14)
  run("calibrate: 14 poses of 44 lit 1920 x 1080 captures (13 links), every pixel decoded (at the byte limit)", ["calibrate", "--captures", P("sl_lit1080"), "--out", P("sl4.yaml")])

def walls_pcd(path, dist, width, walls, n):
    # An unorganized binary PCD (under 1 MB): `walls` walls `width` m wide, `dist` m away, fanned
    # over 120 deg, and a floor patch; random points, seed 1.
    import math, random
    random.seed(1)
    pts = array.array("f")
    for k in range(walls):
        a = math.radians(-60 + 120 * k / max(1, walls - 1))
        for _ in range(n // walls):
            s = (random.random() - 0.5) * width
            pts.extend((dist * math.sin(a) + s * math.cos(a), 1.0 - random.random() * width / 2, dist * math.cos(a) - s * math.sin(a)))
    for _ in range(n // 10):
        pts.extend(((random.random() - 0.5) * 10, 1.0, random.random() * 10))
    count = len(pts) // 3
    with open(path, "wb") as out:
        out.write(("VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH %d\nHEIGHT 1\n"
                   "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS %d\nDATA binary\n" % (count, count)).encode())
        out.write(pts.tobytes())

def plan():
  walls_pcd(P("walls.pcd"), 40, 100, 10, 75000)
  run("plan --cloud: ten 100 m walls 40 m away (82,500 points, 0.99 MB)", ["plan", "--calib", P("calib.yaml"), "--cloud", P("walls.pcd"), "--json", P("plan_walls.json")])
  open(P("camera_vga.yaml"), "w").write("camera: {width: 640, height: 480, fx: 525, fy: 525, cx: 319.5, cy: 239.5, depth_scale: 1000}\n")
  for raw in (10000, 20000, 65535):
    png_gray16(P("far_%d.png" % raw), 640, 480, raw)
    run("plan --depth: 640 x 480, a wall at %.3f m" % (raw / 1000), ["plan", "--calib", P("calib.yaml"), "--depth", P("far_%d.png" % raw), "--camera", P("camera_vga.yaml"), "--json", P("plan_%d.json" % raw)])
  open(P("camera.yaml"), "w").write("camera: {width: 4096, height: 4096, fx: 3277, fy: 3277, cx: 2048, cy: 2048}\n")
  png_gray16(P("far_4096.png"), 4096, 4096, 65535)
  run("plan --depth: 4096 x 4096 (the limit), a wall at 65.535 m", ["plan", "--calib", P("calib.yaml"), "--depth", P("far_4096.png"), "--camera", P("camera.yaml"), "--json", P("plan_4096.json")])

def bag_bytes(chunks):
  # A bag (format 2.0): connections 0 (/points) and 1 (/other) in a stored chunk, then `chunks`.
  import bz2
  rec = lambda fields, data: (struct.pack("<I", len(fields)) + fields + struct.pack("<I", len(data)) + data)
  fld = lambda pairs: b"".join(struct.pack("<I", len(k) + 1 + len(v)) + k + b"=" + v for k, v in pairs)
  conn = lambda i, t: rec(fld([(b"op", b"\x07"), (b"conn", struct.pack("<I", i)), (b"topic", t)]),
                          fld([(b"topic", t), (b"type", b"sensor_msgs/PointCloud2"), (b"md5sum", b"1158d486dd51d683ce2f1be655c3c181"), (b"message_definition", b"-")]))
  conns = conn(0, b"/points") + conn(1, b"/other")
  body = rec(fld([(b"op", b"\x05"), (b"compression", b"none"), (b"size", struct.pack("<I", len(conns)))]), conns)
  body += b"".join(chunks)
  magic = b"#ROSBAG V2.0\n"
  def header(ip):
    f = fld([(b"op", b"\x03"), (b"index_pos", struct.pack("<Q", ip)), (b"conn_count", struct.pack("<I", 2)), (b"chunk_count", struct.pack("<I", len(chunks) + 1))])
    return rec(f, b" " * (4096 - 8 - len(f)))
  return magic + header(len(magic) + 4096 + len(body)) + body + conns, rec, fld

def bz2_zero_chunk(mib):
  # A bz2 chunk holding one message of `mib` MiB of zeros on /other.
  import bz2
  _, rec, fld = bag_bytes([])
  msg = rec(fld([(b"op", b"\x02"), (b"conn", struct.pack("<I", 1)), (b"time", struct.pack("<II", 1, 0))]), bytes(mib << 20))
  return rec(fld([(b"op", b"\x05"), (b"compression", b"bz2"), (b"size", struct.pack("<I", len(msg)))]), bz2.compress(msg, 9))

def chessboard_folder(d, w, h, poses):
  # capture_0 .. poses-1 of a 1024 x 768 projector (42 captures, OpenCV's order), all links to
  # four w x h PNGs: noise A for each pattern, noise B for its inverse, white, black. Every pixel
  # is lit and decodes to garbage: both decoding passes run.
  import random
  random.seed(39)
  os.makedirs(d, exist_ok=True)
  for name, row in (("a", None), ("b", None), ("white", b"\xff" * w), ("black", bytes(w))):
    f = os.path.join(d, name + ".png")
    if not os.path.exists(f):
      rows = [random.randbytes(w) for _ in range(64)] if row is None else None
      png_gray8_rows(f, w, h, (lambda y, rows=rows: rows[y % 64]) if row is None else (lambda y, row=row: row))
  for k in range(poses):
    pd = os.path.join(d, "capture_%d" % k)
    os.makedirs(pd, exist_ok=True)
    for i in range(42):
      src = "white" if i == 40 else "black" if i == 41 else ("a" if i % 2 == 0 else "b")
      link = os.path.join(pd, "graycode_%02d.png" % i)
      if not os.path.lexists(link): os.symlink(os.path.join("..", src + ".png"), link)

def round3():
  # Issue 39's bounds: YAML trees, bz2 bag chunks, the chessboard mode, simulate --structured-light.
  open(P("cycle.yaml"), "w").write("planes: &p {max_planes: 4, sub: *p}\n")
  run("detect --print-config: a settings file holding an alias cycle (refused)", ["detect", "--print-config", "--config", P("cycle.yaml")])
  laughs = "l0: &l0 [" + ", ".join(["1"] * 9) + "]\n" + "".join("l%d: &l%d [%s]\n" % (i, i, ", ".join(["*l%d" % (i - 1)] * 9)) for i in range(1, 6))
  open(P("laughs.yaml"), "w").write(laughs)
  run("detect --print-config: 9^6 nodes by aliases (refused at 100,000)", ["detect", "--print-config", "--config", P("laughs.yaml")])
  one, _, _ = bag_bytes([])
  chunk = bz2_zero_chunk(60)
  data, _, _ = bag_bytes([chunk] * 40)
  open(P("bomb.bag"), "wb").write(data)
  run("detect --bag: 40 bz2 chunks of 60 MiB of zeros (%d KB; refused after 1 GiB)" % (len(data) // 1000), ["detect", "--calib", P("calib.yaml"), "--bag", P("bomb.bag"), "--topic", "/points"])
  data, _, _ = bag_bytes([bz2_zero_chunk(500)])
  open(P("bomb1.bag"), "wb").write(data)
  run("detect --bag: one bz2 chunk of 500 MiB of zeros (%d KB; refused from its header)" % (len(data) // 1000), ["detect", "--calib", P("calib.yaml"), "--bag", P("bomb1.bag"), "--topic", "/points"])
  data, _, _ = bag_bytes([chunk] * 2)
  open(P("two.bag"), "wb").write(data)
  run("detect --bag: two bz2 chunks of 60 MiB of zeros (valid)", ["detect", "--calib", P("calib.yaml"), "--bag", P("two.bag"), "--topic", "/points"])
  chessboard_folder(P("cb_max"), 3260, 3260, 1)
  run("calibrate: chessboard, one pose of 42 lit 3260 x 3260 noise captures (at the 1.5 GiB budget)", ["calibrate", "--captures", P("cb_max"), "--square-m", "0.075", "--resolution", "1024,768", "--out", P("cb1.yaml")])
  chessboard_folder(P("cb_over"), 3300, 3300, 1)
  run("calibrate: chessboard, one pose of 3300 x 3300 (refused from the header)", ["calibrate", "--captures", P("cb_over"), "--square-m", "0.075", "--resolution", "1024,768", "--out", P("cb1.yaml")])
  chessboard_folder(P("cb_many"), 1280, 1024, 19)
  run("calibrate: chessboard, 19 poses (links) of 42 lit 1280 x 1024 captures (at the captures' bound)", ["calibrate", "--captures", P("cb_many"), "--square-m", "0.075", "--resolution", "1024,768", "--out", P("cb3.yaml")])
  chessboard_folder(P("cb_many20"), 1280, 1024, 20)
  run("calibrate: chessboard, 20 such poses (refused from the listing)", ["calibrate", "--captures", P("cb_many20"), "--square-m", "0.075", "--resolution", "1024,768", "--out", P("cb3.yaml")])
  calib(P("calib_4k.yaml"), 3840, 2160)
  import shutil
  shutil.rmtree(P("sim4k"), ignore_errors=True)
  run("simulate --structured-light: 3840 x 2160 framebuffer (the bound)", ["simulate", "--structured-light", "--calib", P("calib_4k.yaml"), "--out", P("sim4k")])
  calib(P("calib_wide.yaml"), 16384, 2048)
  run("simulate --structured-light: 16384 x 2048 (refused)", ["simulate", "--structured-light", "--calib", P("calib_wide.yaml"), "--out", P("simw")])

for g in groups:
  {"readers": readers, "structured": structured, "plan": plan, "round3": round3}[g]()
