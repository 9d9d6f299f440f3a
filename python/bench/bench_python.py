"""The figures of doc/python.md: the overhead of a Python compare() over the C++ evaluate() it
wraps, and batch throughput (maps/s) on 1 and 2 Dask workers against `topoeval rank` with the
same thread count.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_python.py \
        --topoeval build/apps/topoeval/topoeval [--maps 100] [--repeat 20] [--rounds 3]
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

import mrpt_topoeval as te
from mrpt_topoeval import batch

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MAPS = os.path.join(ROOT, "share", "mrpt_topoeval", "maps")
# compare overhead: the two robot maps of the house (a small, fast pair) and the synthetic
# campus floor against itself broken twice (a larger one).
PAIRS = [(os.path.join(MAPS, "map_2333d24.yaml"), os.path.join(MAPS, "map_6ccdcaa.yaml")),
         (os.path.join(MAPS, "synthetic", "campus.gridmap.gz"),
          os.path.join(MAPS, "synthetic", "campus_broken_2.gridmap.gz"))]
# throughput: the campus floor, against the broken floor and itself alternately.
GT = PAIRS[1][0]
SAMPLES = [PAIRS[1][1], PAIRS[1][0]]


def overhead(repeat):
    """compare() wall time against the C++ time of the same call: evaluate() + reportToJson()
    (Report.cpp_ms, what a C++ caller needs for the same report) and evaluate() alone."""
    print("compare overhead: Python wall time of te.compare(gt, map) on loaded maps, against "
          "the C++ time inside the same call (evaluate + JSON: report.cpp_ms; evaluate alone: "
          "report['timing_ms']['evaluate'])")
    for gt_path, map_path in PAIRS:
        gt, m = te.load_map(gt_path), te.load_map(map_path)
        te.compare(gt, m)  # warm-up
        walls, cpps, evals = [], [], []
        for _ in range(repeat):
            t0 = time.perf_counter()
            r = te.compare(gt, m)
            walls.append((time.perf_counter() - t0) * 1000.0)
            cpps.append(r.cpp_ms)
            evals.append(r["timing_ms"]["evaluate"])
        over = [100.0 * (a - b) / b for a, b in zip(walls, cpps)]
        over_eval = [100.0 * (a - b) / b for a, b in zip(walls, evals)]
        print(f"  {os.path.basename(map_path)} vs {os.path.basename(gt_path)}: Python "
              f"{statistics.median(walls):.2f} ms, C++ {statistics.median(cpps):.2f} ms "
              f"(evaluate {statistics.median(evals):.2f} ms); overhead over the C++ call: median "
              f"{statistics.median(over):.2f} % (min {min(over):.2f}, max {max(over):.2f}); "
              f"over evaluate() alone: median {statistics.median(over_eval):.2f} %; "
              f"{repeat} calls")


def make_maps(folder, n):
    os.makedirs(folder, exist_ok=True)
    maps = []
    for i in range(n):
        dst = os.path.join(folder, f"m{i:04d}.gridmap.gz")
        os.symlink(SAMPLES[i % 2], dst)
        maps.append(dst)
    return maps


def throughput(topoeval, n, tmp, rounds):
    maps = make_maps(os.path.join(tmp, "maps"), n)
    print(f"throughput on {n} maps (campus_broken_2 and campus alternately, links) against "
          f"{os.path.relpath(GT, ROOT)}; {rounds} round(s), interleaved, median:")
    jobs = batch.folder_jobs(GT, os.path.join(tmp, "maps"))
    start_s = []
    real_connect = batch._connect

    def timed_connect(*args):
        t0 = time.perf_counter()
        out = real_connect(*args)
        start_s.append(time.perf_counter() - t0)
        return out

    batch._connect = timed_connect
    results = {}
    for k in range(rounds):
        for threads in (1, 2):
            t0 = time.perf_counter()
            subprocess.run([topoeval, "rank", GT, *maps, "--threads", str(threads)], check=True,
                           stdout=subprocess.DEVNULL)
            results.setdefault(("rank", threads), []).append(time.perf_counter() - t0)
            out = os.path.join(tmp, f"out{threads}_{k}")
            t0 = time.perf_counter()
            rows = batch.run_batch(jobs, out, workers=threads, progress=False)
            total = time.perf_counter() - t0
            assert len(rows) == n and all(r["status"] == "ok" for r in rows)
            results.setdefault(("batch", threads), []).append(total)
            results.setdefault(("batch_nostart", threads), []).append(total - start_s[-1])
    for threads in (1, 2):
        r = statistics.median(results[("rank", threads)])
        b = statistics.median(results[("batch", threads)])
        bn = statistics.median(results[("batch_nostart", threads)])
        print(f"  {threads} thread(s): topoeval rank --threads {threads} {r:.1f} s = "
              f"{n / r:.2f} maps/s; topoeval-batch on a LocalCluster of {threads} worker(s) "
              f"{b:.1f} s = {n / b:.2f} maps/s with the cluster's start, {n / bn:.2f} maps/s "
              f"without ({b - bn:.1f} s start)")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--topoeval", required=True)
    ap.add_argument("--maps", type=int, default=100)
    ap.add_argument("--repeat", type=int, default=20)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--skip-throughput", action="store_true")
    a = ap.parse_args()
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f} at start; "
          f"{sys.executable}")
    overhead(a.repeat)
    if not a.skip_throughput:
        with tempfile.TemporaryDirectory(prefix="topoeval_bench_") as tmp:
            throughput(a.topoeval, a.maps, tmp, a.rounds)


if __name__ == "__main__":
    main()
