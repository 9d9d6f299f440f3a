"""Batch scoring on a Dask cluster: ``topoeval-batch`` and :func:`run_batch` (doc/batch.md).

A batch is a list of jobs (ground truth, map, optional INI configuration): a manifest CSV with
the columns ``gt,map[,config]`` (paths relative to the manifest's folder), or every map file of
a folder against one ground truth. Each job is one Dask task that runs :func:`score_job` on a
worker; the ground truth's graph is built once per worker process and reused, as
``topoeval rank`` builds it once.

Results go to ``OUT/results.csv`` (the columns of ``topoeval rank --csv`` after ``gt, map,
config, status, error``) and ``OUT/results.json`` (the same rows with each map's full report),
rows in the order of the jobs, written atomically at the end, also when the batch is stopped;
while it runs, each row is appended to ``OUT/results.journal`` as it arrives, so that even a
killed client keeps what it did (the next run reads the journal). Running the same batch again skips the rows already there (status ``ok``
and ``error``; ``--retry-errors`` scores the errors again). A map that fails is a row with
status ``error`` and the command's message; a worker that dies mid-task has its task run again
on another worker by the Dask scheduler; a task that still cannot finish (it killed several
workers) is a row with status ``failed``, scored again by the next run. Ranks are given among
the rows with the same ground truth and configuration, as ``topoeval rank`` would give them.
"""

import argparse
import csv
import io
import json
import os
import sys
import threading
import time

import mrpt_topoeval as te

__all__ = ["Job", "read_manifest", "folder_jobs", "score_job", "run_batch", "main",
           "CSV_COLUMNS"]

CSV_COLUMNS = ["gt", "map", "config", "status", "error"] + te.RANK_CSV_COLUMNS[1:]
# One JSON line per row as it arrives: what a stopped run did, without rewriting both result
# files for every map (which, with thousands of rows, would cost more than the maps).
JOURNAL = "results.journal"


class Job(tuple):
    """(gt, map, config): paths as the worker opens them; config "" = defaults."""

    __slots__ = ()

    def __new__(cls, gt, map, config=""):
        return super().__new__(cls, (gt, map, config or ""))

    gt = property(lambda self: self[0])
    map = property(lambda self: self[1])
    config = property(lambda self: self[2])


class BatchError(Exception):
    """A batch that cannot start: unreadable manifest, missing folder, bad option."""


def _resolve(base, p):
    p = p.strip()
    return p if not p or os.path.isabs(p) else os.path.normpath(os.path.join(base, p))


def read_manifest(path, default_config=""):
    """Jobs of a manifest CSV: a header row naming ``gt``, ``map`` and optionally ``config``
    (any order, other columns ignored), then one job per row. Relative paths are relative to
    the manifest's folder; an empty config is ``default_config``."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
    except OSError as e:
        raise BatchError(f"{path}: cannot be read ({e.strerror or e})") from e
    except UnicodeDecodeError as e:
        raise BatchError(f"{path}: not a UTF-8 text file") from e
    rows = [r for r in rows if any(c.strip() for c in r)]
    if not rows:
        raise BatchError(f"{path}: empty manifest (expected a header row gt,map[,config])")
    header = [c.strip().lower() for c in rows[0]]
    if "gt" not in header or "map" not in header:
        raise BatchError(f"{path}: the header row must name the columns gt and map "
                         f"(and optionally config), got {','.join(rows[0])}")
    base = os.path.dirname(os.path.abspath(path))
    ig, im = header.index("gt"), header.index("map")
    ic = header.index("config") if "config" in header else None
    jobs = []
    for n, r in enumerate(rows[1:], start=2):
        cell = lambda i: r[i] if i is not None and i < len(r) else ""  # noqa: E731
        if not cell(ig).strip() or not cell(im).strip():
            raise BatchError(f"{path}: row {n}: the gt and map columns must not be empty")
        jobs.append(Job(_resolve(base, cell(ig)), _resolve(base, cell(im)),
                        _resolve(base, cell(ic)) or default_config))
    return jobs


def folder_jobs(gt, folder, config=""):
    """Every map file of ``folder`` (by name, as ``topoeval series`` picks them), sorted, the
    ground truth's own path left out, against ``gt``."""
    if not os.path.isdir(folder):
        raise BatchError(f"{folder}: no such folder")
    jobs = []
    for name in sorted(os.listdir(folder)):
        p = os.path.join(folder, name)
        if not os.path.isfile(p) or not te.is_map_file(p):
            continue
        # The ground truth's own path only: a link or copy of it is a map like any other.
        if os.path.abspath(p) == os.path.abspath(gt):
            continue
        jobs.append(Job(gt, p, config))
    if not jobs:
        raise BatchError(f"{folder}: no map file (.yaml .png .pgm .gridmap ...) in it")
    return jobs


# ---------------------------------------------------------------- on the workers

_cache_lock = threading.Lock()
_gt_cache = {}  # (gt, config, their mtimes) -> (Config, gt Map, gt graph), per worker process


def _stamp(p):
    try:
        return os.stat(p).st_mtime_ns
    except OSError:
        return None


def _prepared(gt, config):
    key = (gt, config, _stamp(gt), _stamp(config) if config else None)
    with _cache_lock:  # one build per ground truth, even with several threads per worker
        if key not in _gt_cache:
            cfg = te.Config.from_ini(config) if config else te.Config()
            gt_map = te.load_map(gt, cfg)
            graph = te._core.build_graph(gt_map._m, cfg._p)
            if len(_gt_cache) > 16:
                _gt_cache.clear()
            _gt_cache[key] = (cfg, gt_map, graph)
        return _gt_cache[key]


def score_job(gt, map, config=""):
    """One row: the map scored against the ground truth as ``topoeval rank`` scores it. Never
    raises for bad input: the row's status is then ``error`` with the command's message."""
    row = {"gt": gt, "map": map, "config": config, "status": "ok", "error": ""}
    try:
        cfg, gt_map, gt_graph = _prepared(gt, config)
        c = te._core.score(gt_graph, gt_map._m, te.load_map(map, cfg)._m, cfg._p)
    except te.InputError as e:
        return dict(row, status="error", error=str(e), scores=None, report=None)
    except MemoryError:
        return dict(row, status="error", error="out of memory", scores=None, report=None)
    except Exception as e:  # a bug: the row says so, the batch goes on
        return dict(row, status="error", error=f"internal error: {e}", scores=None, report=None)
    report = json.loads(c.json)
    report.pop("timing_ms", None)  # the one part that varies between runs
    return dict(row, scores=dict(c.scores), report=report)


# ---------------------------------------------------------------- the client side

def _key(row):
    return (row["gt"], row["map"], row["config"] or "")


def _load_previous(out_dir):
    """The rows of an earlier run: results.json, then the journal of a run that was stopped
    before it could write it (later rows win)."""
    json_path = os.path.join(out_dir, "results.json")
    rows = {}
    try:
        with open(json_path, encoding="utf-8") as f:
            rows = {_key(r): r for r in json.load(f).get("rows", [])}
    except FileNotFoundError:
        pass
    except (OSError, ValueError) as e:
        raise BatchError(f"{json_path}: cannot read the previous results ({e}); move it away "
                         "to start afresh") from e
    try:
        with open(os.path.join(out_dir, JOURNAL), encoding="utf-8") as f:
            for line in f:
                try:
                    r = json.loads(line)
                except ValueError:
                    break  # the last line of a killed run may be cut
                rows[_key(r)] = r
    except FileNotFoundError:
        pass
    return rows


def _ranked_rows(rows):
    out = []
    for r in rows:
        r = dict(r)
        for c in te.RANK_CSV_COLUMNS[1:]:
            r.setdefault(c, None)
        if r["status"] == "ok":
            for c in te._FIGURES:  # a row of an older run may lack a newer figure
                r[c] = r["scores"].get(c)
        out.append(r)
    groups = {}
    for r in out:
        groups.setdefault((r["gt"], r["config"]), []).append(r)
    for group in groups.values():
        ok = [r for r in group if r["status"] == "ok"]
        te.add_ranks(ok)
        for r in group:
            if r["status"] != "ok":
                for c, _ in te._RANKED:
                    r[c] = None
    return out


def _csv_text(rows):
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(CSV_COLUMNS)
    for r in rows:
        ok = r["status"] == "ok"
        vals = [r["gt"], r["map"], r["config"], r["status"], r["error"]]
        vals += te._rank_fields(r) if ok else [""] * (len(te.RANK_CSV_COLUMNS) - 1)
        w.writerow(vals)
    return buf.getvalue()


def _json_text(rows):
    keys = CSV_COLUMNS + ["scores", "report"]
    return json.dumps({"rows": [{k: r.get(k) for k in keys} for r in rows]}, indent=2) + "\n"


def _write_atomic(path, text):
    tmp = f"{path}.part"
    with open(tmp, "w", encoding="utf-8", newline="") as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def _save(out_dir, jobs, done):
    rows = _ranked_rows([done[j] for j in jobs if j in done])
    _write_atomic(os.path.join(out_dir, "results.json"), _json_text(rows))
    _write_atomic(os.path.join(out_dir, "results.csv"), _csv_text(rows))
    return rows


class _Progress:
    """A one-line bar on a terminal, a line per tenth of the work elsewhere (logs)."""

    def __init__(self, total, skipped, stream, enabled):
        self.total, self.skipped, self.stream, self.enabled = total, skipped, stream, enabled
        self.done = self.errors = self.failed = 0
        self.t0 = time.monotonic()
        self.tty = enabled and hasattr(stream, "isatty") and stream.isatty()
        self.next_tenth = 1

    def update(self, status):
        self.done += 1
        self.errors += status == "error"
        self.failed += status == "failed"
        if not self.enabled:
            return
        rate = self.done / max(time.monotonic() - self.t0, 1e-9)
        n = max(self.total, 1)
        bar = "#" * (30 * self.done // n)
        line = (f"[{bar:<30}] {self.done}/{self.total} maps, {rate:.2f} maps/s, "
                f"{self.errors} errors, {self.failed} failed")
        if self.tty:
            self.stream.write("\r" + line + ("\n" if self.done == self.total else ""))
            self.stream.flush()
        elif self.done * 10 >= self.next_tenth * n or self.done == self.total:
            self.stream.write("topoeval-batch: " + line + "\n")
            self.stream.flush()
            self.next_tenth = self.done * 10 // n + 1


def _connect(scheduler, workers, host):
    from distributed import Client, LocalCluster
    if scheduler:
        try:
            return Client(scheduler, timeout="30s"), None
        except (OSError, TimeoutError) as e:
            raise BatchError(f"cannot reach the Dask scheduler at {scheduler}: {e}") from e
    # One single-threaded process per worker, as `topoeval rank --threads N` runs N maps.
    cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                           processes=True, host=host, dashboard_address=None)
    return Client(cluster), cluster


def run_batch(jobs, out_dir, scheduler=None, workers=None, host="127.0.0.1",
              retry_errors=False, progress=True, stream=sys.stderr):
    """Scores ``jobs`` on a Dask cluster and writes OUT_DIR/results.csv and results.json.

    ``scheduler``: the address of a running scheduler (``tcp://host:8786``); else a
    LocalCluster of ``workers`` single-threaded processes (default: one per core) listening on
    ``host`` (loopback unless asked otherwise). Returns the rows, in the order of ``jobs``."""
    jobs = list(dict.fromkeys(Job(*j) for j in jobs))  # each job once, first order kept
    os.makedirs(out_dir, exist_ok=True)
    wanted = set(jobs)
    done = {k: r for k, r in _load_previous(out_dir).items() if k in wanted}
    redo = ("failed", "error") if retry_errors else ("failed",)
    todo = [j for j in jobs if j not in done or done[j]["status"] in redo]
    bar = _Progress(len(todo), len(jobs) - len(todo), stream, progress)
    if progress and len(todo) < len(jobs):
        stream.write(f"topoeval-batch: {len(jobs) - len(todo)} of {len(jobs)} rows already "
                     f"done in {out_dir}, skipped\n")
    journal_path = os.path.join(out_dir, JOURNAL)
    try:
        if todo:
            from distributed import as_completed
            client, cluster = _connect(scheduler, workers, host)
            bar.t0 = time.monotonic()  # maps per second of scoring, not of the cluster's start
            try:
                futures = {client.submit(score_job, *j, pure=False, key=f"topoeval-{i}"): j
                           for i, j in enumerate(todo)}
                with open(journal_path, "a", encoding="utf-8") as journal:
                    for fut in as_completed(futures):
                        j = futures[fut]
                        try:
                            row = fut.result()
                        except Exception as e:  # KilledWorker: it brought down several workers
                            row = {"gt": j.gt, "map": j.map, "config": j.config,
                                   "status": "failed", "error": f"{type(e).__name__}: {e}",
                                   "scores": None, "report": None}
                        done[j] = row
                        journal.write(json.dumps(row) + "\n")
                        journal.flush()
                        bar.update(row["status"])
            finally:
                client.close()
                if cluster is not None:
                    cluster.close()
    finally:
        # Also when stopped (Ctrl-C, a lost scheduler): the files hold every row done.
        rows = _save(out_dir, jobs, done)
    if os.path.exists(journal_path):
        os.remove(journal_path)  # everything it held is in results.json now
    return rows


def main(argv=None):
    ap = argparse.ArgumentParser(
        prog="topoeval-batch",
        description="Scores many maps against their ground truths on a Dask cluster (a local "
        "one by default) and writes OUT/results.csv and OUT/results.json; running it again "
        "skips the rows already done. Exit codes: 0 ok, 1 a task failed, 2 bad input (a map "
        "that cannot be read is a row with its error, and exit code 2). See doc/batch.md.")
    src = ap.add_mutually_exclusive_group(required=True)
    src.add_argument("--manifest", metavar="JOBS.csv",
                     help="CSV with a header row gt,map[,config]; paths relative to its folder")
    src.add_argument("--maps", metavar="DIR", help="score every map file of DIR against --gt")
    ap.add_argument("--gt", help="the ground truth for --maps")
    ap.add_argument("--config", default="", metavar="F.ini",
                    help="INI configuration for rows without one (default: the defaults)")
    ap.add_argument("-o", "--out", required=True, metavar="OUT",
                    help="folder of results.csv and results.json")
    ap.add_argument("--scheduler", metavar="ADDRESS",
                    help="a running Dask scheduler (tcp://host:8786); default: a local cluster")
    ap.add_argument("--workers", type=int, default=0,
                    help="local cluster: worker processes (default: one per core)")
    ap.add_argument("--host", default="127.0.0.1",
                    help="local cluster: address to listen on (default 127.0.0.1, loopback)")
    ap.add_argument("--retry-errors", action="store_true",
                    help="score again the rows whose map failed in an earlier run")
    ap.add_argument("--no-progress", action="store_true", help="no progress bar")
    a = ap.parse_args(argv)
    try:
        if a.maps is not None:
            if not a.gt:
                raise BatchError("--maps needs --gt")
            jobs = folder_jobs(a.gt, a.maps, a.config)
        else:
            if a.gt:
                raise BatchError("--gt goes with --maps; a manifest names each row's gt")
            jobs = read_manifest(a.manifest, a.config)
        if a.workers < 0:
            raise BatchError(f"--workers {a.workers} violates workers >= 0")
        rows = run_batch(jobs, a.out, scheduler=a.scheduler, workers=a.workers or None,
                         host=a.host, retry_errors=a.retry_errors, progress=not a.no_progress)
    except BatchError as e:
        print(f"topoeval-batch: error: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("topoeval-batch: interrupted; the rows done are saved", file=sys.stderr)
        return 130
    for r in rows:
        if r["status"] != "ok":
            print(f"topoeval-batch: {r['status']}: {r['map']}: {r['error']}", file=sys.stderr)
    print(f"topoeval-batch: {len(rows)} rows in {os.path.join(a.out, 'results.csv')} and "
          "results.json")
    if any(r["status"] == "failed" for r in rows):
        return 1
    return 2 if any(r["status"] == "error" for r in rows) else 0


if __name__ == "__main__":
    sys.exit(main())
