#!/usr/bin/env python3
"""Inputs at projsurf's limits (docs/limits.md), each run through the CLI under GNU time:
prints peak memory and wall time per case. usage: limits_at_max.py PROJSURF_BINARY WORK_DIR
(needs about 2 GB of disk in WORK_DIR; takes a few minutes)."""
import array, os, struct, subprocess, sys, zlib

cli, work = sys.argv[1], sys.argv[2]
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
