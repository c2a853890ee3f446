#!/usr/bin/env python3
"""projsurf from Python: read a calibration, get a cloud, find where the projector can show a
picture upright on a wall, and warp the picture into the projector's framebuffer.

    python3 examples/python/detect_and_correct.py CALIB.yaml FRAMEBUFFER.png
        [--cloud scan.pcd | --depth depth.png --camera camera.yaml] [--image picture.png]

Without a cloud it makes one with numpy: a level depth camera 0.8 m above the floor, 2.5 m
from a wall. An Open3D cloud works as it is: projsurf.detect(o3d.io.read_point_cloud(...), ...).
Needs the module on the path: PYTHONPATH=build/python (build tree) or the installed
<prefix>/lib/python3/dist-packages.
"""
import argparse
import sys

import numpy as np

import projsurf


def wall_and_floor(width=640, height=480, f=525.0):
    """(H, W, 3) float32 points, camera frame (x right, y down, z forward), metres."""
    u, v = np.meshgrid(np.arange(width), np.arange(height))
    rays = np.stack([(u - (width - 1) / 2) / f, (v - (height - 1) / 2) / f, np.ones(u.shape)], axis=-1)
    with np.errstate(divide="ignore"):
        z = np.minimum(2.5, np.where(rays[..., 1] > 0, 0.8 / rays[..., 1], np.inf))  # wall or floor
    return (rays * z[..., None]).astype(np.float32)


def main():
    # The docstring's first paragraph (whole sentences) as the description, the rest after the options.
    first, rest = __doc__.split("\n\n", 1)
    parser = argparse.ArgumentParser(description=first, epilog=rest,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("calib")
    parser.add_argument("framebuffer")
    parser.add_argument("--cloud", help="PCD or PLY file")
    parser.add_argument("--depth", help="16-bit depth PNG (with --camera)")
    parser.add_argument("--camera", help="camera intrinsics YAML")
    parser.add_argument("--image", help="the picture to show (default: colour bars)")
    args = parser.parse_args()

    try:
        projector = projsurf.read_calibration(args.calib)
        if args.cloud:
            points = projsurf.read_cloud(args.cloud)
        elif args.depth:
            points = projsurf.read_depth_cloud(args.depth, args.camera or "camera.yaml")
        else:
            points = wall_and_floor()

        # Gravity in the camera frame: the robot's IMU if it has one, e.g. gravity=[0, 1, 0];
        # "auto" takes it from the floor.
        det = projsurf.detect(points, projector, aspect="16:9", gravity="auto")
        if not det["found"]:
            print("no surface:", det["reason"])
            return 0
        rect = det["rectangle"]
        print(f"rectangle {rect['width_m']:.2f} x {rect['height_m']:.2f} m, corners (m, camera frame):")
        print(np.array2string(rect["corners"], precision=3))

        if args.image:
            picture = projsurf.read_image(args.image)
        else:
            picture = np.zeros((360, 640, 3), np.uint8)  # eight colour bars, B, G, R
            for bar in range(8):
                picture[:, bar * 80:(bar + 1) * 80] = [255 * (bar & 1), 255 * (bar >> 1 & 1), 255 * (bar >> 2 & 1)]
        framebuffer = projsurf.correct(picture, projector, det)  # (800, 1280, 3): the calibration's resolution
        projsurf.write_image(args.framebuffer, framebuffer)
        print(f"framebuffer {framebuffer.shape[1]}x{framebuffer.shape[0]} -> {args.framebuffer}")
    except projsurf.InputError as e:  # a file or value projsurf cannot use: "<file>: <problem>"
        print(f"detect_and_correct: error: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
