"""The Python API gives what the `topoeval` command gives: the same JSON fields and values on the
sample maps of share/mrpt_topoeval, the same ranks, the same graphs, the same messages."""
import json
import os

import numpy as np
import pytest

import mrpt_topoeval as te
from conftest import (CAMPUS, CAMPUS_BROKEN, GT, MAP_A, MAP_B, cli_compare_json, cli_error,
                      run_topoeval, without_timing)

# Every sample pair: two robot maps of one house, the house's ground truth (which matches
# nothing: an empty match is a report too), a synthetic floor against itself broken twice.
PAIRS = [(MAP_B, MAP_A), (GT, MAP_B), (CAMPUS, CAMPUS_BROKEN)]


@pytest.mark.parametrize("gt,map", PAIRS, ids=["2333d24-6ccdcaa", "house-2333d24", "campus"])
def test_compare_equals_cli_json(tmp_path, gt, map):
    text, cli = cli_compare_json(tmp_path, gt, map)
    report = te.compare(gt, map)
    assert isinstance(report, dict)
    # Every field, every value; and the text itself, byte for byte, but for timing_ms.
    assert report.without_timing() == {k: v for k, v in cli.items() if k != "timing_ms"}
    assert without_timing(report.json_text) == without_timing(text)
    assert set(report["timing_ms"]) >= {"evaluate", "total"}
    # The matched pairs with both positions, from the graphs' vertices.
    pairs = cli["matches"]["pairs"]
    assert len(report.pairs) == len(pairs)
    for p, q in zip(report.pairs, pairs):
        assert (p.gt_id, p.map_id, p.stage) == (q["ground_truth"], q["map"], q["stage"])
        assert p.gt_xy == tuple(report.gt_graph.vertex_positions[p.gt_id])
        assert p.map_xy == tuple(report.map_graph.vertex_positions[p.map_id])
    assert report.gt_positions.shape == report.map_positions.shape == (len(pairs), 2)
    assert report.quality == cli["quality"] and 0 <= report.quality <= 1
    assert report.scores["quality"] == pytest.approx(cli["quality"], abs=5e-5)  # JSON: 4 decimals


def test_compare_with_config_file_and_dict_equals_cli(tmp_path):
    ini = tmp_path / "c.ini"
    ini.write_text("[GraphBuilder]\nmin_clearance_m = 0.35\n[VertexSimilarity]\nmode = attributes\n")
    _, cli = cli_compare_json(tmp_path, MAP_B, MAP_A, "--config", ini)
    cli.pop("timing_ms")
    assert cli["quality"] > 0
    assert te.compare(MAP_B, MAP_A, te.Config.from_ini(ini)).without_timing() == cli
    d = {"GraphBuilder": {"min_clearance_m": 0.35}, "VertexSimilarity": {"mode": "attributes"}}
    assert te.compare(MAP_B, MAP_A, d).without_timing() == cli
    assert float(te.Config(d).to_dict()["GraphBuilder"]["min_clearance_m"]) == 0.35
    # to_dict() gives back a Config equal to the one it came from.
    assert te.Config(te.Config(d).to_dict()).ini_text() == te.Config(d).ini_text()


@pytest.mark.parametrize("text", [
    "[GraphBuilder]\nmin_clearance_m = -1\n",
    "[GraphBuilder]\nmin_clerance_m = 0.3\n",
    "[NoSuchSection]\nx = 1\n",
    "[VertexSimilarity]\nmode = magic\n",
])
def test_bad_config_raises_the_cli_message(tmp_path, text):
    ini = tmp_path / "bad.ini"
    ini.write_text(text)
    code, _, err = run_topoeval("compare", GT, MAP_A, "--config", ini)
    assert code == 2
    with pytest.raises(te.InputError) as e:
        te.Config.from_ini(ini)
    assert str(e.value) == cli_error(err)
    assert isinstance(e.value, ValueError)
    # From a dict: the same message, "config dict" where the command names the file.
    section = text.split("]")[0][1:]
    key, value = text.split("\n")[1].split(" = ")
    with pytest.raises(te.InputError) as e:
        te.Config({section: {key: value}})
    assert str(e.value) == "config dict" + cli_error(err)[len(str(ini)):]


def test_rank_equals_cli_rank_csv(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("image: nowhere.png\nresolution: 0.05\norigin: [0, 0, 0]\n")
    maps = [MAP_A, GT, str(bad), MAP_A]
    csv = tmp_path / "rank.csv"
    code, _, err = run_topoeval("rank", MAP_B, *maps, "--csv", csv, "--threads", 2)
    assert code == 2  # a map could not be read
    ranking = te.rank(MAP_B, maps, threads=2)
    assert ranking.to_csv() == csv.read_text()
    assert [r["error"] is None for r in ranking] == [True, True, False, True]
    assert ranking[2]["error"] == cli_error(err)
    assert ranking[0]["rank"] == ranking[3]["rank"]  # the same map twice: a shared rank


def test_build_graph_equals_cli_graph_json(tmp_path):
    out = tmp_path / "g.json"
    run_topoeval("graph", MAP_B, "--json", out, check=0)
    cli = json.loads(out.read_text())
    g = te.build_graph(te.load_map(MAP_B))
    mine = json.loads(g.to_json())
    for k in ("map", "summary", "vertices", "edges", "outer_boundary", "warnings"):
        assert mine[k] == cli[k], k
    # Arrays and objects agree with the JSON.
    assert g.vertex_positions.shape == (len(cli["vertices"]), 2)
    assert g.edge_ends.shape == (len(cli["edges"]), 2)
    assert len(g.edge_paths) == len(g.edges) == len(cli["edges"])
    for e, arr in zip(g.edges, g.edge_paths):
        assert np.array_equal(e.path, arr) and arr.shape[1] == 2
        assert tuple(g.edge_ends[e.id]) == (e.source, e.target)
    v = g.vertices[0]
    assert v.position == tuple(g.vertex_positions[0]) and v.degree == g.vertex_degree[0]


def test_map_from_array_probability_and_ros_values_equal_the_file():
    loaded = te.load_map(MAP_A)
    occ = loaded.occupancy()
    assert occ.shape == (loaded.height, loaded.width) and occ.dtype == np.float32
    expected = te.compare(MAP_B, loaded).without_timing()
    assert expected["quality"] > 0
    from_prob = te.Map.from_array(occ, loaded.resolution_m, loaded.origin_xy, name=MAP_A)
    assert from_prob.format == "array"
    got = te.compare(MAP_B, from_prob).without_timing()
    assert got == expected
    # The same map as a ROS OccupancyGrid (int8: -1, 0, 100): a trinary map survives exactly.
    ros = np.where(occ > 0.65, 100, np.where(occ < 0.196, 0, -1)).astype(np.int8)
    assert set(np.unique(occ.round(2))) <= {0.0, 0.5, 1.0}  # the sample is trinary
    from_ros = te.Map.from_array(ros, loaded.resolution_m, loaded.origin_xy, name=MAP_A)
    assert te.compare(MAP_B, from_ros).without_timing() == expected


def test_map_from_array_bad_values_raise_value_errors():
    with pytest.raises(te.InputError, match=r"cell \(row 1, column 0\) = 2 violates"):
        te.Map.from_array(np.array([[0.0], [2.0]]), 0.05)
    with pytest.raises(ValueError, match="is not an OccupancyGrid value"):
        te.Map.from_array(np.array([[0, 50, 101]], dtype=np.int16), 0.05)
    with pytest.raises(ValueError, match="1-dimensional array is not a grid"):
        te.Map.from_array(np.zeros(5), 0.05)
    with pytest.raises(ValueError, match="resolution_m = 0 violates"):
        te.Map.from_array(np.zeros((3, 3)), 0.0)


def test_errors_are_value_and_os_errors():
    assert issubclass(te.InputError, ValueError)
    assert issubclass(te.OutputError, OSError)
    code, _, err = run_topoeval("graph", "/nonexistent/map.yaml")
    assert code == 2
    with pytest.raises(te.InputError) as e:
        te.load_map("/nonexistent/map.yaml")
    assert str(e.value) == cli_error(err)
    with pytest.raises(TypeError):
        te.Config(42)
    assert os.path.basename(te.load_map(MAP_A).file) == "map_6ccdcaa.yaml"


def test_load_map_notes_a_ros_unknown_grey_kept_unknown(tmp_path):
    # nav2 Humble's map_saver wrote free_thresh 0.25, which reads its unknown grey 205 as free.
    pixels = np.array([[0, 254, 205], [254, 205, 254]], dtype=np.uint8)
    (tmp_path / "m.pgm").write_bytes(b"P5\n3 2\n255\n" + pixels.tobytes())
    (tmp_path / "m.yaml").write_text("image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
                                     "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.25\n")
    kept = te.load_map(str(tmp_path / "m.yaml"))
    assert len(kept.notes) == 1 and "free_thresh 0.25" in kept.notes[0]
    assert kept.occupancy()[0, 1] == pytest.approx(0.5)  # bottom row, middle: grey 205
    literal = te.load_map(str(tmp_path / "m.yaml"), {"MapLoad": {"trinary_unknown_grey": -1}})
    assert literal.notes == []
    assert literal.occupancy()[0, 1] < 0.1
