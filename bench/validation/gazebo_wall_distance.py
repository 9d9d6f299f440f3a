#!/usr/bin/python3
"""The Gazebo office's known map error, measured as its README measures it and without the frame.

`../shared/data/gazebo_slam/office/wall_distance_to_gt.csv` gives, for each SLAM system's map,
the median distance of its occupied cells to the nearest ground-truth wall, with every map in
the ground truth's frame through its YAML origin. That figure mixes two things: how well the map
is drawn and how well its frame sits on the ground truth's. The Topology Graph method never
uses the frame (doc/matching.md), so this script gives both: the distance as the README measures
it (it reproduces the CSV), and after one rigid alignment of the map's walls to the ground
truth's (point-to-point ICP, the 10 % farthest pairs left out each round). Used by
doc/validation.md, "Session 25". Debian's python3 with python3-numpy and python3-pil:

    /usr/bin/python3 bench/validation/gazebo_wall_distance.py [../shared/data/gazebo_slam/office]
"""
import os
import sys

import numpy as np
from PIL import Image

SYSTEMS = ["gmapping", "lidar_rtabmap", "slam_toolbox", "rgbd_rtabmap", "cartographer"]


def read_yaml(path):
    """The few flat keys of a ROS map YAML (image, resolution, origin, occupied_thresh)."""
    out = {}
    with open(path) as f:
        for line in f:
            if ":" not in line:
                continue
            key, value = (s.strip() for s in line.split(":", 1))
            out[key] = value
    out["resolution"] = float(out["resolution"])
    out["occupied_thresh"] = float(out["occupied_thresh"])
    out["origin"] = [float(v) for v in out["origin"].strip("[]").split(",")]
    return out


def occupied_cells(folder, name):
    """Centres of the occupied cells [m], in the frame the YAML's origin gives (ROS map_server:
    P(occupied) = (255 - value) / 255 above occupied_thresh; row 0 is the top)."""
    meta = read_yaml(os.path.join(folder, name + ".yaml"))
    image = np.asarray(Image.open(os.path.join(folder, meta["image"])), dtype=float)
    rows, cols = np.nonzero((255.0 - image) / 255.0 > meta["occupied_thresh"])
    res, (ox, oy) = meta["resolution"], meta["origin"][:2]
    return np.c_[ox + (cols + 0.5) * res, oy + (image.shape[0] - 1 - rows + 0.5) * res]


def nearest(points, reference, chunk=2000):
    """Distance from each point to its nearest reference point, and that point's index."""
    dist = np.empty(len(points))
    index = np.empty(len(points), dtype=int)
    for start in range(0, len(points), chunk):
        block = points[start:start + chunk]
        d2 = ((block[:, None, :] - reference[None, :, :]) ** 2).sum(axis=2)
        index[start:start + chunk] = d2.argmin(axis=1)
        dist[start:start + chunk] = np.sqrt(d2.min(axis=1))
    return dist, index


def align(points, reference, rounds=40):
    """Rigid ICP of points onto reference: the aligned points, the turn [deg] and the shift [m]."""
    moved, total_r, total_t = points.copy(), np.eye(2), np.zeros(2)
    for _ in range(rounds):
        dist, index = nearest(moved, reference)
        keep = dist <= np.percentile(dist, 90)
        a, b = moved[keep], reference[index[keep]]
        ca, cb = a.mean(axis=0), b.mean(axis=0)
        u, _, vt = np.linalg.svd((a - ca).T @ (b - cb))
        r = vt.T @ u.T
        if np.linalg.det(r) < 0:
            vt[1] *= -1
            r = vt.T @ u.T
        t = cb - r @ ca
        moved = moved @ r.T + t
        total_r, total_t = r @ total_r, r @ total_t + t
    return moved, np.degrees(np.arctan2(total_r[1, 0], total_r[0, 0])), total_t


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "../../../shared/data/gazebo_slam/office")
    if not os.path.isdir(folder):
        sys.exit(f"gazebo_wall_distance: {folder}: no such folder (../shared/data absent?)")
    reference = occupied_cells(folder, "office_ground_truth")
    print("system          as given: median  within 0.15 m | rigid ICP: turn, shift      "
          "| aligned: median  within 0.15 m")
    for name in SYSTEMS:
        cells = occupied_cells(folder, name + "_map")
        given, _ = nearest(cells, reference)
        moved, turn, shift = align(cells, reference)
        aligned, _ = nearest(moved, reference)
        print(f"{name:15s} {np.median(given):14.3f} {np.mean(given <= 0.15):12.2f} | "
              f"{turn:6.2f} deg ({shift[0]:6.3f}, {shift[1]:6.3f}) m | "
              f"{np.median(aligned):14.3f} {np.mean(aligned <= 0.15):12.2f}")


if __name__ == "__main__":
    main()
