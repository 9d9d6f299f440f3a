"""mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013), in Python.

A thin layer over the C++ library (module ``mrpt_topoeval._core``); doc/python.md walks through
it. Everything the ``topoeval`` command computes is here with the same numbers and messages:

    >>> import mrpt_topoeval as te
    >>> report = te.compare("gt.yaml", "map.yaml")        # topoeval compare gt.yaml map.yaml
    >>> report["quality"], report.pairs[0].gt_xy

Bad input raises :class:`InputError` (a ``ValueError``), an output that cannot be written
:class:`OutputError` (an ``OSError``), each with the message the command prints after
``topoeval: error:``. Calls that compute release the GIL; ``Map``, ``Graph`` and ``Config``
objects never change once made, so threads may share them.
"""

import functools
import json
import os
from concurrent.futures import ThreadPoolExecutor
from typing import NamedTuple

import numpy as np

from . import _core
from ._core import InputError, OutputError

__all__ = [
    "Config", "Map", "Graph", "Report", "MatchedPair", "Ranking", "InputError", "OutputError",
    "load_map", "build_graph", "compare", "rank", "rank_positions", "is_map_file",
    "RANK_CSV_COLUMNS",
]

InputError.__doc__ = "Bad input (file, array or parameter): the command's exit code 2."
OutputError.__doc__ = "An output cannot be written: the command's exit code 3."


class Config:
    """Every stage's parameters, as the command's ``--config`` INI file sets them.

    ``Config()`` is the documented default (``topoeval config``); ``Config.from_ini(path)``
    reads an INI file and ``Config.from_dict({"GraphBuilder": {"min_clearance_m": 0.4}})``
    the same sections and keys from a dict, with the command's checks and messages (unknown
    section or key, value out of range). ``Config(x)`` accepts a path, a dict or a Config.
    """

    def __init__(self, source=None):
        if source is None:
            self._p = _core.Parameters()
        elif isinstance(source, Config):
            self._p = source._p
        elif isinstance(source, dict):
            self._p = Config.from_dict(source)._p
        elif isinstance(source, (str, os.PathLike)):
            self._p = Config.from_ini(source)._p
        else:
            raise TypeError(f"Config: expected a path, a dict or a Config, not {type(source)}")

    @classmethod
    def _wrap(cls, params):
        c = cls.__new__(cls)
        c._p = params
        return c

    @classmethod
    def from_ini(cls, path):
        """Reads an INI file as ``topoeval ... --config PATH`` does. Raises InputError."""
        return cls._wrap(_core.Parameters.from_ini_file(os.fspath(path)))

    @classmethod
    def from_dict(cls, sections, source="config dict"):
        """``{section: {key: value}}`` as an INI file would hold it; messages start with
        ``source`` where the command names the INI file. Raises InputError."""
        if not isinstance(sections, dict):
            raise InputError(f"{source}: expected {{section: {{key: value}}}}, got {sections!r}")
        lines = []
        for section, keys in sections.items():
            if not isinstance(keys, dict):
                raise InputError(f"{source}: [{section}] must map keys to values, got {keys!r}")
            lines.append(f"[{section}]")
            for key, value in keys.items():
                lines.append(f"{key} = {_ini_value(value)}")
        return cls._wrap(_core.Parameters.from_ini_text("\n".join(lines) + "\n", source))

    def ini_text(self):
        """The effective configuration as INI text (what ``topoeval config`` prints)."""
        return self._p.ini_text()

    def to_dict(self):
        """``{section: {key: text}}`` of every key (values as the INI file writes them)."""
        out, section = {}, None
        for line in self.ini_text().splitlines():
            line = line.split("//")[0].split("#")[0].strip() if not line.startswith("[") else line
            if line.startswith("[") and line.endswith("]"):
                section = out.setdefault(line[1:-1], {})
            elif "=" in line and section is not None:
                key, value = line.split("=", 1)
                section[key.strip()] = value.strip()
        return out

    def __repr__(self):
        return f"Config({self.to_dict()!r})"


def _ini_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return repr(v)
    return str(v)


def _params(config):
    if config is None:
        return _DEFAULT.__dict__.setdefault("_p", _core.Parameters())
    return config._p if isinstance(config, Config) else Config(config)._p


class _Default:
    pass


_DEFAULT = _Default()


class Map:
    """An occupancy grid map: from a file (:func:`load_map`) or an array (:meth:`from_array`).

    ``file`` is the path as given (or the array's name), ``format`` one of ros_yaml, image,
    gridmap, simplemap, array; ``notes`` what the loader read otherwise than literally (e.g. a
    ROS map whose free_thresh would make its unknown cells free). ``occupancy()`` gives
    P(occupied) per cell as float32 (rows, columns) with row 0 at the lowest y (ROS
    OccupancyGrid order; plot it with ``origin="lower"``).
    """

    def __init__(self, loaded):
        self._m = loaded

    @classmethod
    def from_array(cls, array, resolution_m, origin_xy=(0.0, 0.0), *, encoding="auto",
                   name="array", config=None):
        """A map from a 2-D numpy array, row 0 at the lowest y, cell (0, 0)'s lower-left corner
        at ``origin_xy`` [m] (snapped to the cell grid like a ROS origin).

        ``encoding``: ``"probability"`` — P(occupied) in [0, 1], NaN unknown, kept as
        probabilities; ``"ros"`` — nav_msgs/OccupancyGrid values (-1 unknown, 0..100 percent,
        classified with [MapLoad] occupied_thresh / free_thresh like map_server's trinary
        mode); ``"auto"`` — integer arrays are ROS values, floating arrays probabilities.
        Raises InputError naming ``name`` (bad value: its row, column and value)."""
        a = np.asarray(array)
        if encoding == "auto":
            encoding = "ros" if np.issubdtype(a.dtype, np.integer) else "probability"
        if encoding not in ("ros", "probability"):
            raise InputError(f"{name}: encoding '{encoding}' must be auto, ros or probability")
        if a.dtype == np.bool_:
            a = a.astype(np.float64)
        x0, y0 = origin_xy
        return cls(_core.map_from_cells(a, float(resolution_m), float(x0), float(y0),
                                        encoding == "ros", _params(config), name))

    file = property(lambda self: self._m.file)
    format = property(lambda self: self._m.format)
    notes = property(lambda self: list(self._m.notes),
                     doc="Where the file was read otherwise than literally, and why (e.g. a ROS "
                         "map's unknown grey kept unknown under a high free_thresh).")
    width = property(lambda self: self._m.width, doc="Cells along x.")
    height = property(lambda self: self._m.height, doc="Cells along y.")
    resolution_m = property(lambda self: self._m.resolution_m)
    origin_xy = property(lambda self: self._m.origin_xy, doc="Lower-left corner [m].")

    def occupancy(self):
        return self._m.occupancy()

    def extent(self):
        """(x_min, x_max, y_min, y_max) [m], for matplotlib's imshow(extent=...)."""
        x0, y0 = self.origin_xy
        return (x0, x0 + self.width * self.resolution_m, y0, y0 + self.height * self.resolution_m)

    def __repr__(self):
        return (f"Map({self.file!r}, {self.format}, {self.width} x {self.height} cells of "
                f"{self.resolution_m:g} m)")


def load_map(path, config=None):
    """Reads a map file as the command does ([MapLoad] of ``config``): ROS .yaml, image,
    .gridmap[.gz], .simplemap[.gz]. Raises InputError with the command's message."""
    return Map(_core.load_map(os.fspath(path), _params(config)))


def _as_map(m, config):
    return m if isinstance(m, Map) else load_map(m, config)


class Graph:
    """A Topology Graph (paper II), as numpy arrays and as plain objects.

    Arrays: ``vertex_positions`` (n, 2) [m], ``vertex_clearance_m``, ``vertex_degree``,
    ``vertex_spurious``; ``edge_ends`` (m, 2) vertex ids, ``edge_length_m``, ``edge_spurious``,
    ``edge_paths`` (list of (k, 2) polylines [m]), ``outer_boundary`` (k, 2).
    Objects: ``vertices`` (id, position, clearance_m, spurious, degree, angle_diffs_rad) and
    ``edges`` (id, source, target, path, clearance_m, length_m, ...). ``to_json()`` is the
    ``graph`` object of ``topoeval graph --json`` without build statistics and timing.
    """

    def __init__(self, g):
        self._g = g

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        return getattr(self._g, name)

    def __repr__(self):
        return (f"Graph({self._g.file!r}: {len(self._g.vertices)} vertices, "
                f"{len(self._g.edges)} edges)")


def build_graph(map, config=None):
    """The Topology Graph of a Map (or a map file) with [GraphBuilder] of ``config``."""
    return Graph(_core.build_graph(_as_map(map, config)._m, _params(config)))


class MatchedPair(NamedTuple):
    """One matched vertex pair with both positions, each in its own map's frame [m]."""
    gt_id: int
    map_id: int
    stage: str
    similarity: float
    gt_xy: tuple
    map_xy: tuple


class Report(dict):
    """A quality report: the dict of ``topoeval compare --json`` (every field, same values),
    plus, as attributes:

    - ``pairs``: the matched pairs as :class:`MatchedPair` (ids, stage, similarity, both
      positions); ``gt_positions`` / ``map_positions``: the same positions as (n, 2) arrays;
    - ``gt_graph``, ``map_graph``: both :class:`Graph` objects;
    - ``scores``: the ranked figures at full precision (the JSON rounds to 6 decimals);
    - ``json_text``: the exact JSON the command writes (timing_ms aside);
    - ``cpp_ms``: the time this call spent in the C++ library, evaluation and JSON [ms];
    - ``quality``, ``coverage``: shorthands for the dict's entries.
    """

    def __init__(self, comparison):
        super().__init__(json.loads(comparison.json))
        self.json_text = comparison.json
        self._c = comparison
        self.scores = dict(comparison.scores)
        self.cpp_ms = comparison.cpp_ms

    # Built on first use: a compare() in a loop that reads only the scores pays for none of it.
    @functools.cached_property
    def gt_graph(self):
        return Graph(self._c.gt_graph)

    @functools.cached_property
    def map_graph(self):
        return Graph(self._c.map_graph)

    @functools.cached_property
    def pairs(self):
        gt_xy, map_xy = self.gt_graph.vertex_positions, self.map_graph.vertex_positions
        return [MatchedPair(p["ground_truth"], p["map"], p["stage"], p["similarity"],
                            tuple(gt_xy[p["ground_truth"]]), tuple(map_xy[p["map"]]))
                for p in self["matches"]["pairs"]]

    @property
    def gt_positions(self):
        return np.array([p.gt_xy for p in self.pairs], dtype=float).reshape(-1, 2)

    @property
    def map_positions(self):
        return np.array([p.map_xy for p in self.pairs], dtype=float).reshape(-1, 2)

    quality = property(lambda self: self["quality"])
    coverage = property(lambda self: self["coverage"])

    def without_timing(self):
        """The dict without ``timing_ms``, the only part that changes between runs."""
        return {k: v for k, v in self.items() if k != "timing_ms"}


def compare(gt, map, config=None):
    """Scores ``map`` against the ground truth ``gt`` (each a Map or a path) as
    ``topoeval compare GT MAP [--config]`` does; returns a :class:`Report`."""
    p = _params(config)
    return Report(_core.compare(_as_map(gt, config)._m, _as_map(map, config)._m, p))


# The columns of `topoeval rank --csv`, in its order.
RANK_CSV_COLUMNS = [
    "file", "rank", "quality", "coverage", "relative_accuracy_rmse_m", "relative_accuracy_score",
    "consistency_short", "consistency_medium", "consistency_long", "brokenness", "rank_coverage",
    "rank_relative_accuracy", "rank_consistency", "rank_brokenness", "map_scale",
    "explained_walls",
]
# Its measured figures (numbers, written by format_number), the rest after "file" are ranks.
_FIGURES = [c for c in RANK_CSV_COLUMNS[2:] if not c.startswith("rank")]

_RANKED = [("rank", "quality"), ("rank_coverage", "coverage"),
           ("rank_relative_accuracy", "relative_accuracy_score"),
           ("rank_consistency", "consistency_score"), ("rank_brokenness", "brokenness_score")]


def _rank_fields(row):
    """The CSV texts of a scored row's columns after "file", as ``topoeval rank --csv``
    writes them (also the batch's ``results.csv``)."""
    return [format_number(row[c]) if c in _FIGURES else row[c] for c in RANK_CSV_COLUMNS[1:]]


def rank_positions(values, valid, decimals=3):
    """Ranks as ``topoeval rank`` gives them: "1" best, ties to ``decimals`` decimals share
    ("2-3"), invalid entries ""."""
    return _core.rank_positions([float(v) for v in values], [bool(x) for x in valid], decimals)


def add_ranks(rows):
    """Sets the rank columns of row dicts that hold ``scores`` (or None when the map failed)."""
    valid = [r.get("scores") is not None for r in rows]
    for column, figure in _RANKED:
        values = [r["scores"][figure] if ok else 0.0 for r, ok in zip(rows, valid)]
        for r, pos in zip(rows, rank_positions(values, valid)):
            r[column] = pos
    return rows


def format_number(v, decimals=4):
    """A number as ``topoeval rank --csv`` writes it: fixed decimals, trailing zeros removed,
    "" for None or not finite."""
    if v is None or not np.isfinite(v):
        return ""
    if isinstance(v, (int, np.integer)) and not isinstance(v, bool):
        return str(int(v))
    s = f"{v:.{decimals}f}"
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return "0" if s == "-0" else s


class Ranking(list):
    """``rank()``'s result: one dict per map, in the order given, with the columns of
    ``topoeval rank --csv`` (numbers as floats, None where the CSV is empty; ranks as text),
    ``error`` (None, or the message the command prints for that map) and ``report`` (a
    :class:`Report`, None on error). ``to_csv()`` is the command's CSV."""

    def to_csv(self):
        lines = [",".join(RANK_CSV_COLUMNS)]
        for r in self:
            f = [_csv_field(r["file"])]
            if r["error"] is None:
                f += _rank_fields(r)
            else:
                f += [""] * (len(RANK_CSV_COLUMNS) - 1)
            lines.append(",".join(f))
        return "\n".join(lines) + "\n"


def _csv_field(s):
    if not any(c in s for c in ',"\r\n'):
        return s
    return '"' + s.replace('"', '""') + '"'


def _score_row(file, scores):
    row = {"file": file, "error": None, "scores": scores}
    for c in _FIGURES:
        row[c] = scores[c]
    return row


def rank(gt, maps, config=None, threads=0):
    """Scores every map against one ground truth and ranks them, as ``topoeval rank GT MAP...``
    does: the ground truth's graph is built once, up to ``threads`` maps (0 = all cores) are
    scored at once, and a map that cannot be read is a row with its error. Raises InputError
    only for the ground truth and the configuration."""
    p = _params(config)
    gt_map = _as_map(gt, config)
    gt_graph = _core.build_graph(gt_map._m, p)  # once, shared read-only by every thread

    def one(m):
        name = m.file if isinstance(m, Map) else os.fspath(m)
        try:
            c = _core.score(gt_graph, gt_map._m, _as_map(m, config)._m, p)
        except InputError as e:
            return {"file": name, "error": str(e), "scores": None, "report": None}
        row = _score_row(name, dict(c.scores))
        row["report"] = Report(c)
        return row

    maps = list(maps)
    workers = max(1, min(threads or os.cpu_count() or 1, len(maps) or 1))
    with ThreadPoolExecutor(workers) as pool:
        rows = list(pool.map(one, maps))
    add_ranks(rows)
    for r in rows:
        if r["error"] is not None:
            for c in RANK_CSV_COLUMNS[1:]:
                r[c] = None
    return Ranking(rows)


def is_map_file(path):
    """Whether the command reads ``path`` as a map, by its name (how a folder's maps are
    picked)."""
    return _core.is_map_file(os.fspath(path))

