"""Paths the Python tests share, from the environment ctest sets (python/CMakeLists.txt)."""
import json
import os
import subprocess

import pytest

SHARE = os.environ.get("TOPOEVAL_SHARE_DIR", os.path.join(os.path.dirname(__file__), "..", "..",
                                                          "share", "mrpt_topoeval"))
TESTS = os.environ.get("TOPOEVAL_TESTS_DIR", os.path.join(os.path.dirname(__file__), "..", "..",
                                                          "tests"))
MAPS = os.path.join(SHARE, "maps")
GT = os.path.join(MAPS, "house_gt_trinary_res0.05.yaml")
MAP_A = os.path.join(MAPS, "map_6ccdcaa.yaml")
MAP_B = os.path.join(MAPS, "map_2333d24.yaml")
CAMPUS = os.path.join(MAPS, "synthetic", "campus.gridmap.gz")
CAMPUS_BROKEN = os.path.join(MAPS, "synthetic", "campus_broken_2.gridmap.gz")


def topoeval_bin():
    b = os.environ.get("TOPOEVAL_BIN", "")
    if not b or not os.path.exists(b):
        pytest.fail("TOPOEVAL_BIN does not name the built topoeval command")
    return b


def run_topoeval(*args, check=None):
    """(exit code, stdout, stderr) of `topoeval ARGS`."""
    r = subprocess.run([topoeval_bin(), *map(str, args)], capture_output=True, text=True,
                       timeout=300)
    if check is not None:
        assert r.returncode == check, r.stderr
    return r.returncode, r.stdout, r.stderr


def cli_error(stderr):
    """The message of the command's one `topoeval: error: ` line."""
    lines = [ln for ln in stderr.splitlines() if ln.startswith("topoeval: error: ")]
    assert len(lines) == 1, stderr
    return lines[0][len("topoeval: error: "):]


def cli_compare_json(tmp_path, gt, map, *extra):
    out = tmp_path / "compare.json"
    run_topoeval("compare", gt, map, "--json", out, "--force", *extra, check=0)
    text = out.read_text()
    return text, json.loads(text)


def without_timing(text):
    """JSON text without its last member, timing_ms (as tests/support withoutTiming())."""
    at = text.rfind(',\n  "timing_ms"')
    return text[:at] if at >= 0 else text
