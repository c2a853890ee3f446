#!/usr/bin/env python3
"""Where `projsurf plan` puts the picture on the labelled real frames (issue 41's check).

For every label in labels/real/*/*.yaml, runs `plan` on its frame as the planning test does
(--calib LABEL, the label's gravity) and scores the proposed picture by the detector's own
rules (eval/real/real_scoring: valid = at least 95 % of it free on one labelled usable surface and
on its plane; `projsurf_label_tool score`). Also, looser: whether each of its four corners
projects into the depth image inside some usable surface's polygons and within --plane-tol m
of its plane (a corner on a dresser in front of a labelled wall has the wall's pixel but not
its depth).

usage: python3 scripts/plan_labels.py [--projsurf build/projsurf] [--out DIR] [--frames DIR]
Frames: DIR/<frame> (default ../shared/data/real), else data/real/<frame>, else data/<frame>.
Prints one line per frame and a count per split (tune, check).
"""
import argparse
import glob
import json
import os
import subprocess
import sys

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def frame_dir(frame, shared):
    for root in (shared, os.path.join(ROOT, "data/real"), os.path.join(ROOT, "data")):
        if os.path.isdir(os.path.join(root, frame)):
            return os.path.join(root, frame)
    return None


def inside(poly, x, y):
    """Even-odd rule; poly is a list of [x, y] pixels."""
    hit = False
    n = len(poly)
    for i in range(n):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % n]
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            hit = not hit
    return hit


def project(cam, p):
    if p[2] <= 1e-6:
        return None
    u = cam["fx"] * p[0] / p[2] + cam["cx"]
    v = cam["fy"] * p[1] / p[2] + cam["cy"]
    if u < -0.5 or v < -0.5 or u > cam["width"] - 0.5 or v > cam["height"] - 0.5:
        return None
    return u, v


def on_surface(surface, cam, p, tol):
    px = project(cam, p)
    if px is None or not any(inside(r["polygon"], *px) for r in surface.get("regions", [])):
        return False
    plane = surface.get("plane")
    if plane is None:
        return True
    n = plane[:3]
    return abs(sum(n[i] * p[i] for i in range(3)) + plane[3]) <= tol


def in_obstacle(label, cam, p):
    px = project(cam, p)
    return px is not None and any(inside(o["polygon"], *px) for o in label.get("obstacles") or [])


def grid(corners, k=5):
    tl, tr, br, bl = corners
    out = []
    for i in range(k):
        for j in range(k):
            a, b = (i + 0.5) / k, (j + 0.5) / k
            top = [tl[m] + a * (tr[m] - tl[m]) for m in range(3)]
            bottom = [bl[m] + a * (br[m] - bl[m]) for m in range(3)]
            out.append([top[m] + b * (bottom[m] - top[m]) for m in range(3)])
    return out


def on_any(label, cam, p, tol):
    """The first labelled surface the point lies on (pixel and depth), or None."""
    for s in label.get("surfaces") or []:
        if on_surface(s, cam, p, tol):
            return s["name"]
    return None


def judge(label, cam, corners, tol):
    """(the surfaces the four corners lie on, or None when a corner is on none; the share of a
    5 x 5 grid over the picture on a labelled surface and off the obstacles)."""
    names = [on_any(label, cam, c, tol) for c in corners]
    if None in names:
        return None, 0.0
    pts = grid(corners)
    good = sum(on_any(label, cam, p, tol) is not None and not in_obstacle(label, cam, p) for p in pts)
    return "+".join(sorted(set(names))), good / len(pts)


def score(tool, frame_dir, label_path, corners):
    """The label tool's verdict: (valid, free share, surface, why)."""
    pts = [",".join("%.9g" % v for v in c) for c in corners]
    r = subprocess.run([tool, "score", frame_dir, label_path] + pts, capture_output=True, text=True)
    if r.returncode != 0:
        return False, 0.0, "", "label tool: " + r.stderr.strip()
    w = r.stdout.split()
    why = r.stdout.split(" why ", 1)[1].strip() if " why " in r.stdout else ""
    return w[1] == "1", float(w[3]), w[5] if w[4] == "surface" and w[5] != "why" else "", why


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--projsurf", default=os.path.join(ROOT, "build/projsurf"))
    ap.add_argument("--out", default="/tmp/plan_labels")
    ap.add_argument("--label-tool", default=os.path.join(ROOT, "build/tests/projsurf_label_tool"))
    ap.add_argument("--frames", default=os.path.join(ROOT, "../shared/data/real"))
    ap.add_argument("--plane-tol", type=float, default=0.10, help="m, a corner's distance to the labelled plane")
    ap.add_argument("--extra", default="", help="more plan arguments, one string")
    ap.add_argument("--judge-only", action="store_true", help="judge the JSONs already in --out, run nothing")
    ap.add_argument("--with-rgb", action="store_true", help="pass the frame's rgb.png when it has one")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    tally = {}
    for path in sorted(glob.glob(os.path.join(ROOT, "labels/real/*/*.yaml"))):
        label = yaml.safe_load(open(path))
        frame = label["frame"]
        split = label.get("split", "")
        d = frame_dir(frame, a.frames)
        if d is None:
            print(f"{frame}: no frame", file=sys.stderr)
            continue
        cam = yaml.safe_load(open(os.path.join(d, "camera.yaml")))["camera"]
        g = ",".join("%.17g" % x for x in label["gravity"]["vector"])
        out = os.path.join(a.out, frame + ".json")
        cmd = [a.projsurf, "plan", "--depth", os.path.join(d, "depth.png"), "--camera", os.path.join(d, "camera.yaml"),
               "--calib", path, "--gravity", g, "--json", out] + a.extra.split()
        if a.with_rgb and os.path.exists(os.path.join(d, "rgb.png")):
            cmd += ["--rgb", os.path.join(d, "rgb.png")]
        r = subprocess.CompletedProcess(cmd, 0, "", "") if a.judge_only else subprocess.run(cmd, capture_output=True, text=True)
        t = tally.setdefault(split, {"frames": 0, "found": 0, "moves": 0, "valid": 0, "moves_valid": 0,
                                     "corners_on": 0, "assumed": 0})
        t["frames"] += 1
        if r.returncode != 0:
            print(f"{frame} [{split}]: exit {r.returncode}: {r.stderr.strip()}")
            continue
        j = json.load(open(out))
        if not j["found"]:
            print(f"{frame} [{split}]: not found: {j['reason']}")
            continue
        t["found"] += 1
        moves = j["move"]["words"] != "stay where you are"
        t["moves"] += moves
        assumed = bool(j.get("assumed", False))
        t["assumed"] += assumed
        corners = j["predicted"]["corners"]
        valid, free, surface, why = score(a.label_tool, d, path, corners)
        t["valid"] += valid
        t["moves_valid"] += valid and moves
        name, _ = judge(label, cam, corners, a.plane_tol)
        t["corners_on"] += name is not None
        print(f"{frame} [{split}]: {'move' if moves else 'stay'} {j['predicted']['area_m2']:.2f} m^2: "
              f"{'VALID' if valid else 'not valid'} ({free:.0%} free on {surface or '-'}{'; ' + why if why else ''}); "
              f"corners {'on ' + name if name else 'not all on a labelled surface'}"
              f"{'; ASSUMED %.0f %%' % (100 * j.get('assumed_share', 0)) if assumed else ''}: {j['move']['words']}")
    for split, t in sorted(tally.items()):
        print(f"split {split or '-'}: {t['frames']} frames, {t['found']} proposals ({t['moves']} move): "
              f"valid on a labelled surface {t['valid']} (of the moves {t['moves_valid']}), "
              f"all four corners on one {t['corners_on']}; marked assumed {t['assumed']}")

if __name__ == "__main__":
    main()
