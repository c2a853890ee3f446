#!/usr/bin/python3
"""A gravity for each labelled frame that does not come from the detector: the floor fitted by
this script alone (numpy, its own PNG reader), else the cross product of two labelled walls.

Floor: every 2nd pixel back-projected; planes whose normal is within 50 deg of the camera's
down axis are sampled (3 points, 3000 draws, a fixed seed) and scored by their points within
max(2 cm, 3 sigma of a Kinect-class depth noise); the floor is the lowest of those that hold
at least 4 % of the points (a table top is higher), then least squares reweighted 10 times
(Tukey biweight, scale from the median absolute residual, each point weighted by its depth
noise) over the points within 8 cm of it and nearer than 5 m. Where no such plane exists the
floor is not visible; then two labelled surfaces more than 30 deg apart give gravity as the
cross product of their normals (walls are vertical), else there is no reference.

The labelled surfaces' planes (fitted by the label tool over the drawn regions) are a check on
the floor: a level floor meets each wall at 90 deg; the table prints the largest departure.

usage: floor_gravity.py [--write] [REAL_DIR]   (from the repository root; labels/real/*/*.yaml)
  --write  stores the result as gravity.reference {source, vector} in each label
"""
import glob
import os
import re
import struct
import sys
import zlib

import numpy as np
import yaml


def read_png16(path):
    """A 16-bit greyscale, non-interlaced PNG as a uint16 array (all the frames are that)."""
    data = open(path, 'rb').read()
    pos, idat, width, height = 8, b'', 0, 0
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b'IHDR':
            width, height, depth, colour, _, _, interlace = struct.unpack('>IIBBBBB', body)
            if depth != 16 or colour != 0 or interlace != 0:
                raise ValueError('%s: not a 16-bit greyscale non-interlaced PNG' % path)
        elif kind == b'IDAT':
            idat += body
        pos += 12 + length
    raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(height, 1 + 2 * width)
    out = np.zeros((height, 2 * width), np.uint8)
    prev = np.zeros(2 * width, np.int32)
    for r in range(height):
        f, line = raw[r, 0], raw[r, 1:].astype(np.int32)
        if f == 0:
            cur = line
        elif f == 2:
            cur = (line + prev) & 255
        else:
            cur = np.zeros_like(line)
            for i in range(2 * width):
                a = cur[i - 2] if i >= 2 else 0
                b = prev[i]
                c = prev[i - 2] if i >= 2 else 0
                if f == 1:
                    pred = a
                elif f == 3:
                    pred = (a + b) >> 1
                else:
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                cur[i] = (line[i] + pred) & 255
        out[r] = cur
        prev = cur
    return (out[:, 0::2].astype(np.uint16) << 8) | out[:, 1::2]


def points(frame_dir, step=2):
    cam = yaml.safe_load(open(os.path.join(frame_dir, 'camera.yaml')))['camera']
    depth = read_png16(os.path.join(frame_dir, 'depth.png'))[::step, ::step].astype(np.float64)
    v, u = np.mgrid[0:depth.shape[0], 0:depth.shape[1]] * step
    z = depth / cam['depth_scale']
    ok = (z > 0.3) & (z < 8.0)
    z, u, v = z[ok], u[ok], v[ok]
    return np.stack([(u - cam['cx']) * z / cam['fx'], (v - cam['cy']) * z / cam['fy'], z], axis=1)


def sigma(z):
    """Kinect-class depth noise, m (about 1.5 mm at 1 m, 2.5 cm at 4 m)."""
    return 0.0015 * z * z


def floor_plane(p, rng):
    down = np.array([0.0, 1.0, 0.0])
    band = np.maximum(0.02, 3 * sigma(p[:, 2]))
    found = []
    for _ in range(2000):
        a, b, c = p[rng.integers(0, len(p), 3)]
        n = np.cross(b - a, c - a)
        if np.linalg.norm(n) < 1e-9:
            continue
        n /= np.linalg.norm(n)
        if n @ down < 0:
            n = -n
        if n @ down < np.cos(np.radians(50)):
            continue
        d = -n @ a
        if d >= 0:  # the plane must lie below the camera
            continue
        support = np.count_nonzero(np.abs(p @ n + d) <= band)
        if support >= 0.04 * len(p):
            found.append((n, d, support))
    # The large planes from the lowest up (a table top is higher than the floor): the first
    # whose reweighted fit still holds 4 % of the points, flat (robust scale under 1.5 cm) and
    # within 50 deg of the camera's down axis is the floor.
    found.sort(key=lambda f: f[1])
    tried = []
    for n, d, _ in found:
        if any(n @ m > np.cos(np.radians(5)) and abs(d - e) < 0.10 for m, e in tried):
            continue
        tried.append((n, d))
        fit = refine(p, n, d, band)
        if fit is not None:
            return fit
    return None


def refine(p, n, d, band):
    s = 0.0
    for _ in range(10):
        r = p @ n + d
        near = (np.abs(r) < 0.08) & (p[:, 2] < 5.0)
        if np.count_nonzero(near) < 100:
            return None
        q, rq = p[near], r[near]
        s = max(1.4826 * np.median(np.abs(rq)), 0.003)
        t = rq / (4.685 * s)
        w = np.where(np.abs(t) < 1, (1 - t * t) ** 2, 0.0) / sigma(np.maximum(q[:, 2], 0.5)) ** 2
        mean = (w[:, None] * q).sum(0) / w.sum()
        cov = ((q - mean) * w[:, None]).T @ (q - mean)
        n_new = np.linalg.eigh(cov)[1][:, 0]
        if n_new @ n < 0:
            n_new = -n_new
        n, d = n_new, -n_new @ mean
    support = int(np.count_nonzero(np.abs(p @ n + d) <= band))
    if support < 0.04 * len(p) or s > 0.015 or n[1] < np.cos(np.radians(50)):
        return None
    return n, d, support


def wall_gravity(label, prior):
    normals = [np.array(s['plane'][:3], float) for s in label.get('surfaces') or [] if 'plane' in s]
    best = None
    for i in range(len(normals)):
        for j in range(i + 1, len(normals)):
            g = np.cross(normals[i], normals[j])
            if np.linalg.norm(g) > np.sin(np.radians(30)) and (best is None or np.linalg.norm(g) > np.linalg.norm(best)):
                best = g
    if best is None:
        return None
    best /= np.linalg.norm(best)
    return best if best @ prior > 0 else -best


def wall_departure(label, g):
    """Largest departure from 90 deg between gravity and a labelled surface's normal, deg."""
    normals = [np.array(s['plane'][:3], float) for s in label.get('surfaces') or [] if 'plane' in s]
    return max((np.degrees(np.arcsin(min(1.0, abs(n @ g) / np.linalg.norm(n)))) for n in normals), default=float('nan'))


def angle(a, b):
    return np.degrees(np.arccos(np.clip(a @ b / np.linalg.norm(a) / np.linalg.norm(b), -1, 1)))


def write_reference(path, source, g):
    text = open(path).read()
    text = re.sub(r'\n  reference:\n    source: \w+\n    vector: .*', '', text)
    entry = '\n  reference:\n    source: %s\n    vector: [%.5f, %.5f, %.5f]' % (source, g[0], g[1], g[2])
    text, count = re.subn(r'(gravity:\n  source: \w+\n  vector: [^\n]*)', lambda m: m.group(1) + entry, text, 1)
    if count != 1:
        raise ValueError('%s: no gravity block to extend' % path)
    open(path, 'w').write(text)


def main():
    args = [a for a in sys.argv[1:] if a != '--write']
    write = '--write' in sys.argv[1:]
    real = args[0] if args else '../shared/data/real'
    print('| frame | label source | reference source | floor points | reference vs label, deg | '
          'walls off 90 deg (reference), deg | walls off 90 deg (label), deg |')
    print('|---|---|---|---:|---:|---:|---:|')
    for path in sorted(glob.glob('labels/real/*/*.yaml')):
        label = yaml.safe_load(open(path))
        frame = label['frame']
        stored = np.array(label['gravity']['vector'], float)
        p = points(os.path.join(real, frame))
        floor = floor_plane(p, np.random.default_rng(7))
        source, g, count = 'none', None, 0
        if floor is not None:
            source, g, count = 'floor_fit', floor[0], floor[2]
        else:
            g = wall_gravity(label, stored)
            if g is not None:
                source = 'walls'
        if g is None:
            print('| %s | %s | none | 0 | - | - | %.2f |' % (frame, label['gravity']['source'],
                                                           wall_departure(label, stored / np.linalg.norm(stored))))
            continue
        print('| %s | %s | %s | %d | %.2f | %.2f | %.2f |' %
              (frame, label['gravity']['source'], source, count, angle(g, stored), wall_departure(label, g),
               wall_departure(label, stored / np.linalg.norm(stored))))
        if write:
            write_reference(path, source, g)


if __name__ == '__main__':
    main()
