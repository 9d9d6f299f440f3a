"""The walk-through of doc/python.md as one script: load, compare, plot the match.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/walkthrough.py [OUT.png]
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import mrpt_topoeval as te  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MAPS = os.path.join(ROOT, "share", "mrpt_topoeval", "maps")

# 1. Load the reference (here one robot's map of a house) and the map to score (another
#    robot's map of the same house).
gt = te.load_map(os.path.join(MAPS, "map_2333d24.yaml"))
robot = te.load_map(os.path.join(MAPS, "map_6ccdcaa.yaml"))
print(gt)
print(robot)

# 2. Compare: the report is the dict of `topoeval compare --json`.
report = te.compare(gt, robot)
print(f"quality {report['quality']:.3f}, coverage {report['coverage']:.3f}, "
      f"brokenness degree {report['brokenness']['degree']}")
print(f"{len(report.pairs)} matched pairs; first: {report.pairs[0]}")

# 3. Plot both maps side by side, their graphs, and a line per matched pair. Each map keeps its
#    own frame; the robot map is drawn through the relative-accuracy transform T_gt_map so that
#    matched vertices land near each other.
t = report["relative_accuracy"]["transform"]
yaw = np.radians(t["yaw_deg"] or 0.0)
R = np.array([[np.cos(yaw), -np.sin(yaw)], [np.sin(yaw), np.cos(yaw)]])
shift = np.array([t["x"] or 0.0, t["y"] or 0.0])


def to_gt(xy):
    return np.asarray(xy) @ R.T + shift


fig, ax = plt.subplots(figsize=(8, 8))
ax.imshow(1.0 - gt.occupancy(), cmap="gray", origin="lower", extent=gt.extent(), vmin=0, vmax=1)
for path in report.gt_graph.edge_paths:
    ax.plot(path[:, 0], path[:, 1], color="tab:blue", lw=1)
for path in report.map_graph.edge_paths:
    p = to_gt(path)
    ax.plot(p[:, 0], p[:, 1], color="tab:orange", lw=1)
g, m = report.gt_positions, to_gt(report.map_positions)
for a, b in zip(g, m):
    ax.plot([a[0], b[0]], [a[1], b[1]], color="tab:green", lw=1.5)
ax.scatter(g[:, 0], g[:, 1], s=18, color="tab:blue", label="reference vertices", zorder=3)
ax.scatter(m[:, 0], m[:, 1], s=18, color="tab:orange", label="map vertices (T_gt_map)", zorder=3)
ax.set_title(f"{os.path.basename(robot.file)} against {os.path.basename(gt.file)}: quality "
             f"{report['quality']:.3f}, {len(report.pairs)} pairs")
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.legend(loc="lower right")
out = sys.argv[1] if len(sys.argv) > 1 else "match.png"
fig.savefig(out, dpi=80, bbox_inches="tight")
print("wrote", out)
