#!/usr/bin/python3
"""Could the walls no matched part explains find the parts the match missed? The measurement that
led to the library's brokenness step 9, "A part placed by its walls" (doc/quality.md), kept to
re-ask the question outside the library, e.g. of the small ground truths that match nothing
(`--whole`, not in the library); doc/validation.md, "Session 43".

Session 42 found that a broken map whose match missed a part explains less of its walls
(doc/quality.md, "Explained walls"): the missed part's walls are the red ones. This script asks
whether those walls, on their own, place the missed part on the ground truth clearly enough to
count it as a break, and how often they would place something that is not a part.

For each case of a validator picture folder (`topoeval_validate --pictures N --out DIR` writes
`DIR/pictures/*.gt.gridmap`, `*.map.gridmap` and `*.counterparts.txt`, the truth):

1. `compare` with the default parameters (the Python module); each brokenness group's fit
   `T_gt_map` explains the map's wall points it puts within 0.3 m of a ground-truth wall point
   (the library's `explained_wall_tolerance_m`); wall points are occupied cells with a free or
   unknown 8-neighbour.
2. The unexplained wall points fall into regions: points within 2 m of each other are one
   region. Regions of fewer than 100 points (5 m of wall at 0.05 m cells) are left.
3. Each region is placed on the ground truth's walls: every unmatched map vertex within its
   clearance + 1 m of the region, paired with every unmatched ground-truth vertex, under turns
   of 3 degrees; the share of the region's points within 0.15 m of a ground-truth wall point
   ranks them; the 20 best distinct placements (5 degrees or 0.5 m apart) are refined by
   point-to-point ICP and ranked again.
4. A placement is *clear* when its share is at least 0.95 and the next distinct one's at most
   0.8 of it. Its pairs: the unmatched ground-truth vertices it puts within 0.5 m of a map
   vertex; true when the truth's counterpart is that map vertex.

`--whole` places the whole map when nothing is matched (the small ground truths: a house, a
flat), in up to three rounds, each on the points the rounds before left unexplained.

    /usr/bin/python3 bench/validation/wall_parts_probe.py [--whole] DIR... > probe.tsv

Debian's python3 with python3-numpy and python3-scipy; the module from `./scripts/build`
(build/python).
"""
import glob
import math
import os
import re
import sys

import numpy as np
from scipy import ndimage
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "../../build/python"))
import mrpt_topoeval as te  # noqa: E402

EXPLAINED_M = 0.3    # the library's explained_wall_tolerance_m
PLACED_M = 0.15      # a region's point on a ground-truth wall
LINK_M = 2.0         # wall points of one region
MIN_POINTS = 100     # the smallest region placed
TURN_STEP_DEG = 3
CLEAR_SHARE = 0.95
CLEAR_RATIO = 0.8
PAIR_M = 0.5


def turn(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.array([[c, -s], [s, c]])


def wall_points(grid):
    """Occupied cells with a free or unknown 8-neighbour, their centres [m], and the mask."""
    p = np.asarray(grid.occupancy(), dtype=float)
    occupied = p > 0.65
    walls = occupied & ndimage.binary_dilation(~occupied, structure=np.ones((3, 3)))
    rows, cols = np.nonzero(walls)
    ox, oy = grid.origin_xy
    r = grid.resolution_m
    return np.c_[ox + (cols + 0.5) * r, oy + (rows + 0.5) * r], walls


class GroundTruthWalls:
    """Distance to the nearest ground-truth wall point, from a distance transform of its grid."""

    def __init__(self, grid):
        self.points, mask = wall_points(grid)
        self.tree = cKDTree(self.points)
        self.res = grid.resolution_m
        self.ox, self.oy = grid.origin_xy
        self.dist = ndimage.distance_transform_edt(~mask) * self.res

    def distance(self, q):
        ix = np.floor((q[:, 0] - self.ox) / self.res).astype(int)
        iy = np.floor((q[:, 1] - self.oy) / self.res).astype(int)
        inside = (ix >= 0) & (iy >= 0) & (ix < self.dist.shape[1]) & (iy < self.dist.shape[0])
        d = np.full(len(q), np.inf)
        d[inside] = self.dist[iy[inside], ix[inside]]
        return d

    def share(self, q):
        return float(np.mean(self.distance(q) <= PLACED_M))


def icp(gt, points, deg, shift, rounds=20, reach=0.5):
    """Point-to-point ICP from (deg, shift): (share, turn [deg], shift)."""
    th, t = math.radians(deg), np.asarray(shift, float)
    for _ in range(rounds):
        q = points @ turn(math.degrees(th)).T + t
        d, i = gt.tree.query(q, distance_upper_bound=reach)
        ok = np.isfinite(d)
        if ok.sum() < 10:
            break
        a, b = points[ok], gt.points[i[ok]]
        am, bm = a.mean(0), b.mean(0)
        a, b = a - am, b - bm
        th = math.atan2(np.sum(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]),
                        np.sum(a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1]))
        t = bm - turn(math.degrees(th)) @ am
        reach = max(PLACED_M, 0.8 * reach)
    deg = math.degrees(th) % 360
    return gt.share(points @ turn(deg).T + t), deg, t


def distinct(placements, k):
    out = []
    for p in placements:
        if all(abs((p[1] - o[1] + 180) % 360 - 180) > 5 or np.hypot(*(p[2] - o[2])) > 0.5
               for o in out):
            out.append(p)
        if len(out) == k:
            break
    return out


def place(gt, points, gt_pivots, map_pivots):
    """The placements of `points`, best first, distinct, refined."""
    coarse = []
    for deg in range(0, 360, TURN_STEP_DEG):
        r = turn(deg)
        moved = points @ r.T
        for m in map_pivots @ r.T:
            for g in gt_pivots:
                coarse.append((gt.share(moved + (g - m)), deg, g - m))
    coarse.sort(key=lambda p: -p[0])
    refined = [icp(gt, points, p[1], p[2]) for p in distinct(coarse, 20)]
    refined.sort(key=lambda p: -p[0])
    return distinct(refined, 2)


def truth(path):
    """Ground-truth vertex -> its map counterpart (the validator's counterparts file)."""
    out = {}
    if os.path.exists(path):
        for line in open(path):
            m = re.match(r"gt (\d+) -> map (-?\d+)", line)
            if m:
                out[int(m.group(1))] = int(m.group(2))
    return out


def pairs_of(fit, gt_xy, map_xy, gt_free, counterpart):
    share, deg, t = fit
    in_map = (gt_xy - t) @ turn(deg)  # ground truth -> map
    pairs = []
    for g in gt_free:
        d = np.linalg.norm(map_xy - in_map[g], axis=1)
        m = int(np.argmin(d))
        if d[m] <= PAIR_M:
            pairs.append((g, m))
    return len(pairs), sum(1 for g, m in pairs if counterpart.get(g) == m)


def row(case, n, placements, pairs):
    best = placements[0]
    runner = placements[1][0] if len(placements) > 1 else 0.0
    clear = best[0] >= CLEAR_SHARE and runner <= CLEAR_RATIO * best[0]
    return (f"{case}\t{n}\t{best[0]:.3f}\t{best[1]:.1f}\t{runner:.3f}\t{int(clear)}\t"
            f"{pairs[0]}\t{pairs[1]}")


def probe(base, whole):
    gt_grid = te.load_map(base + ".gt.gridmap")
    map_grid = te.load_map(base + ".map.gridmap")
    gt = GroundTruthWalls(gt_grid)
    walls, _ = wall_points(map_grid)
    report = te.compare(base + ".gt.gridmap", base + ".map.gridmap")
    gt_xy = np.asarray(report.gt_graph.vertex_positions)
    map_xy = np.asarray(report.map_graph.vertex_positions)
    clearance = np.asarray(report.map_graph.vertex_clearance_m)
    matched_gt = {p.gt_id for p in report.pairs}
    matched_map = {p.map_id for p in report.pairs}
    gt_free = [g for g in range(len(gt_xy)) if g not in matched_gt]
    counterpart = truth(base + ".counterparts.txt")
    case = os.path.basename(base)
    groups = (report["brokenness"] or {}).get("groups", [])
    if not groups:
        if not whole or len(walls) < MIN_POINTS or len(map_xy) == 0 or len(gt_xy) == 0:
            return []
        rows, rest = [], walls
        for _ in range(3):
            if len(rest) < MIN_POINTS:
                break
            found = place(gt, rest, gt_xy, map_xy)
            rows.append(row(case, len(rest), found,
                            pairs_of(found[0], gt_xy, map_xy, gt_free, counterpart)))
            moved = rest @ turn(found[0][1]).T + found[0][2]
            rest = rest[gt.distance(moved) > EXPLAINED_M]
        return rows
    explained = np.zeros(len(walls), bool)
    for g in groups:
        moved = walls @ turn(g["yaw_deg"]).T + np.array([g["x"], g["y"]])
        explained |= gt.distance(moved) <= EXPLAINED_M
    rest = walls[~explained]
    if len(rest) < MIN_POINTS or not gt_free:
        return []
    links = cKDTree(rest).query_pairs(LINK_M, output_type="ndarray")
    n = len(rest)
    _, label = connected_components(
        coo_matrix((np.ones(len(links)), (links[:, 0], links[:, 1])), shape=(n, n)),
        directed=False)
    rows = []
    sizes = np.bincount(label)
    for region in np.argsort(-sizes, kind="stable"):
        if sizes[region] < MIN_POINTS:
            break
        points = rest[label == region]
        near, _ = cKDTree(points).query(map_xy)
        pivots = [m for m in range(len(map_xy))
                  if m not in matched_map and near[m] <= clearance[m] + 1.0]
        if not pivots:
            continue
        found = place(gt, points, gt_xy[gt_free], map_xy[pivots])
        rows.append(row(case, len(points), found,
                        pairs_of(found[0], gt_xy, map_xy, gt_free, counterpart)))
    return rows


def main():
    args = sys.argv[1:]
    whole = "--whole" in args
    folders = [a for a in args if a != "--whole"]
    if not folders:
        sys.exit(__doc__)
    print("case\tregion_points\tshare\tturn_deg\trunner_up_share\tclear\tpairs\ttrue_pairs")
    for folder in folders:
        cases = sorted(glob.glob(os.path.join(folder, "pictures", "*.map.gridmap")))
        if not cases:
            sys.exit(f"wall_parts_probe: {folder}/pictures: no *.map.gridmap "
                     "(topoeval_validate --pictures N --out DIR writes them)")
        for path in cases:
            for line in probe(path[:-len(".map.gridmap")], whole):
                print(line, flush=True)


if __name__ == "__main__":
    main()
