"""topoeval-batch on a real Dask cluster: a `dask scheduler` and two `dask worker` processes
over TCP on localhost, one worker killed while the batch runs. Every row is present once, the
results equal `topoeval rank`'s, a failing map is a row with its error, and a second run skips
the rows done. Also: the default LocalCluster listens on the loopback address only."""
import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import time

import pytest

import mrpt_topoeval as te
from mrpt_topoeval import batch
from conftest import CAMPUS, CAMPUS_BROKEN, GT, MAP_A, MAP_B, cli_error, run_topoeval

BATCH_SCRIPT = os.path.join(os.environ.get("PYTHONPATH", "").split(os.pathsep)[0],
                            "topoeval-batch")


def dask_command(verb):
    # `dask scheduler` / `dask worker`, run by the interpreter of these tests.
    return [sys.executable, "-m", f"distributed.cli.dask_{verb}"]


def make_maps(folder, n):
    """n maps (the two samples under several names, as links) and one that cannot be read."""
    os.makedirs(folder)
    maps = []
    for i in range(n):
        src = MAP_A if i % 2 == 0 else MAP_B
        dst = os.path.join(folder, f"m{i:03d}.yaml")
        with open(src) as f:  # the .yaml names its image relative to itself: point at share/
            text = f.read()
        image = text.split("image:")[1].split("\n")[0].strip()
        text = text.replace(image, os.path.join(os.path.dirname(src), image), 1)
        with open(dst, "w") as f:
            f.write(text)
        maps.append(dst)
    bad = os.path.join(folder, "m_bad.yaml")
    with open(bad, "w") as f:
        f.write("image: missing.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n")
    maps.append(bad)
    return maps


def make_campus_maps(folder, n):
    """n synthetic floors (the campus sample broken twice, and itself, alternately; links), each
    a few hundred milliseconds of work, and one map that cannot be read."""
    os.makedirs(folder)
    maps = []
    for i in range(n):
        dst = os.path.join(folder, f"c{i:03d}.gridmap.gz")
        os.symlink(CAMPUS_BROKEN if i % 2 == 0 else CAMPUS, dst)
        maps.append(dst)
    bad = os.path.join(folder, "c_bad.gridmap.gz")
    with open(bad, "wb") as f:
        f.write(b"not a gridmap")
    maps.append(bad)
    return maps


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


class Cluster:
    def __init__(self, tmp):
        self.procs = []
        try:
            self._start_all(tmp)
        except BaseException:
            self.close()  # no orphan scheduler or worker when the start fails half way
            raise

    def _start_all(self, tmp):
        sched_file = os.path.join(tmp, "scheduler.json")
        self.scheduler = self.start(dask_command("scheduler") + [
            "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
            "--scheduler-file", sched_file], os.path.join(tmp, "scheduler.log"))
        # The scheduler creates its file before it has written it: wait until it parses (an
        # empty file once made this fixture fail under a loaded machine, session 19).
        deadline = time.time() + 60
        info = None
        while info is None and time.time() < deadline and self.scheduler.poll() is None:
            try:
                with open(sched_file) as f:
                    info = json.load(f)
            except (OSError, ValueError):
                time.sleep(0.1)
        assert info is not None, f"no scheduler file {sched_file} (scheduler log beside it)"
        self.address = info["address"]
        assert self.address.startswith("tcp://127.0.0.1:")
        self.workers = [self.start(dask_command("worker") + [
            self.address, "--nthreads", "1", "--nworkers", "1", "--no-nanny",
            "--host", "127.0.0.1", "--no-dashboard", "--name", name],
            os.path.join(tmp, f"{name}.log")) for name in ("w1", "w2")]

    def start(self, cmd, log):
        p = subprocess.Popen(cmd, stdout=open(log, "w"), stderr=subprocess.STDOUT,
                             start_new_session=True)
        self.procs.append(p)
        return p

    def close(self):
        for p in reversed(self.procs):
            if p.poll() is None:
                os.killpg(p.pid, signal.SIGTERM)
        for p in self.procs:
            try:
                p.wait(timeout=20)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)


@pytest.fixture
def cluster(tmp_path):
    c = Cluster(str(tmp_path))
    yield c
    c.close()


def test_scheduler_two_workers_one_killed(tmp_path, cluster):
    from distributed import Client
    maps = make_campus_maps(str(tmp_path / "maps"), 16)
    manifest = tmp_path / "jobs.csv"
    with open(manifest, "w") as f:
        f.write("gt,map\n")
        for m in maps:
            f.write(f"{CAMPUS},{os.path.relpath(m, tmp_path)}\n")
    out = tmp_path / "out"
    client = Client(cluster.address, timeout=60)
    client.wait_for_workers(2, timeout=60)
    w1 = [a for a, w in client.scheduler_info()["workers"].items() if w["name"] == "w1"][0]
    run = subprocess.Popen([sys.executable, BATCH_SCRIPT, "--manifest", str(manifest),
                            "--scheduler", cluster.address, "-o", str(out), "--no-progress"],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    # Kill w1 (SIGKILL, no goodbye to the scheduler) while it works on a map.
    lost = []
    deadline = time.time() + 300
    while run.poll() is None and time.time() < deadline and not lost:
        busy = client.processing().get(w1)
        if busy:
            os.killpg(cluster.workers[0].pid, signal.SIGKILL)
            lost = list(busy)
        time.sleep(0.02)
    stdout, stderr = run.communicate(timeout=600)
    survivors = list(client.scheduler_info()["workers"])
    client.close()
    assert lost, "the batch ended before a worker could be killed: " + stderr
    assert w1 not in survivors and len(survivors) == 1
    assert run.returncode == 2, stderr  # the bad map
    rows = read_csv(out / "results.csv")
    assert [r["map"] for r in rows] == maps  # every row once, in the manifest's order
    assert [r["status"] for r in rows] == ["ok"] * 16 + ["error"]
    # The tasks w1 had were run again, on w2 (keys are "topoeval-<row>").
    for key in lost:
        assert rows[int(key.split("-")[1])]["status"] == "ok"

    # The same maps ranked by the command, with the thread count of the cluster.
    rank_csv = tmp_path / "rank.csv"
    code, _, err = run_topoeval("rank", CAMPUS, *maps, "--csv", rank_csv, "--threads", 2)
    assert code == 2
    expected = read_csv(rank_csv)
    for mine, theirs in zip(rows, expected):
        assert mine["map"] == theirs["file"]
        for c in te.RANK_CSV_COLUMNS[1:]:
            assert mine[c] == theirs[c], (mine["map"], c)
    assert rows[-1]["error"] == cli_error(err)
    data = json.loads((out / "results.json").read_text())
    assert [r["map"] for r in data["rows"]] == maps
    assert data["rows"][0]["report"]["quality"] == float(rows[0]["quality"]) or \
        abs(data["rows"][0]["report"]["quality"] - float(rows[0]["quality"])) < 1e-4

    # A second run skips every row done and changes nothing.
    before = (out / "results.csv").read_text(), (out / "results.json").read_text()
    again = subprocess.run([sys.executable, BATCH_SCRIPT, "--manifest", str(manifest),
                            "--scheduler", "tcp://127.0.0.1:1", "-o", str(out)],
                           capture_output=True, text=True, timeout=120)
    assert again.returncode == 2, again.stderr
    assert "17 of 17 rows already done" in again.stderr
    assert ((out / "results.csv").read_text(), (out / "results.json").read_text()) == before


def test_local_cluster_on_loopback_folder_mode_and_rerun(tmp_path, monkeypatch):
    maps = make_maps(str(tmp_path / "maps"), 3)
    seen = {}
    real_connect = batch._connect

    def spy(scheduler, workers, host):
        client, cluster = real_connect(scheduler, workers, host)
        seen["address"] = cluster.scheduler_address
        seen["workers"] = list(client.scheduler_info()["workers"])
        return client, cluster

    monkeypatch.setattr(batch, "_connect", spy)
    out = str(tmp_path / "out")
    rows = batch.run_batch(batch.folder_jobs(GT, str(tmp_path / "maps")), out, workers=2,
                           progress=False)
    assert seen["address"].startswith("tcp://127.0.0.1:")
    assert all(w.startswith("tcp://127.0.0.1:") for w in seen["workers"])
    assert [r["map"] for r in rows] == sorted(maps)
    assert [r["status"] for r in rows] == ["ok", "ok", "ok", "error"]
    # The rows equal Python's rank() of the same maps.
    ranking = te.rank(GT, sorted(maps))
    for r, q in zip(rows, ranking):
        for c in te.RANK_CSV_COLUMNS[1:]:
            assert r[c] == q[c], c
    # Rerun with one more map: only that one is scored.
    shutil.copy(maps[0], os.path.join(tmp_path, "maps", "m_new.yaml"))
    seen.clear()
    rows2 = batch.run_batch(batch.folder_jobs(GT, str(tmp_path / "maps")), out, workers=1,
                            progress=False)
    assert "address" in seen and len(rows2) == 5
    assert rows2[4]["map"].endswith("m_new.yaml") and rows2[4]["status"] == "ok"


def test_manifest_errors_are_reported(tmp_path):
    bad = tmp_path / "m.csv"
    bad.write_text("ground,truth\na,b\n")
    r = subprocess.run([sys.executable, BATCH_SCRIPT, "--manifest", str(bad), "-o",
                        str(tmp_path / "o")], capture_output=True, text=True, timeout=60)
    assert r.returncode == 2
    assert "must name the columns gt and map" in r.stderr


def test_a_killed_client_keeps_its_rows_in_the_journal(tmp_path):
    maps = make_maps(str(tmp_path / "maps"), 2)
    out = tmp_path / "out"
    jobs = batch.folder_jobs(GT, str(tmp_path / "maps"))
    batch.run_batch(jobs, str(out), workers=1, progress=False)
    assert not (out / batch.JOURNAL).exists()
    csv_text, json_text = (out / "results.csv").read_text(), (out / "results.json").read_text()
    # What a client killed before writing the result files leaves: the journal only, its last
    # line cut. The next run takes every whole row from it and scores only the cut one.
    rows = json.loads(json_text)["rows"]
    lines = [json.dumps(r) for r in rows]
    (out / batch.JOURNAL).write_text("\n".join(lines[:-1]) + "\n" + lines[-1][:20])
    (out / "results.csv").unlink()
    (out / "results.json").unlink()
    again = batch.run_batch(jobs, str(out), workers=1, progress=False)
    assert [r["map"] for r in again] == sorted(maps)
    assert (out / "results.csv").read_text() == csv_text
    assert (out / "results.json").read_text() == json_text
    assert not (out / batch.JOURNAL).exists()
