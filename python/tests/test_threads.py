"""Calls from several threads give the results of one thread, and the GIL is released while the
C++ library computes."""
import threading
from concurrent.futures import ThreadPoolExecutor

import mrpt_topoeval as te
from conftest import GT, MAP_A, MAP_B  # noqa: F401


def test_threads_give_identical_results():
    gt, a, b = te.load_map(MAP_B), te.load_map(MAP_A), te.load_map(GT)
    cfg = te.Config()
    expected = {m: te.compare(gt, m, cfg).json_text.split('"timing_ms"')[0] for m in (a, b)}
    jobs = [a, b] * 4
    with ThreadPoolExecutor(4) as pool:  # the same Map and Config objects shared by all
        got = list(pool.map(lambda m: te.compare(gt, m, cfg).json_text.split('"timing_ms"')[0],
                            jobs))
    assert got == [expected[m] for m in jobs]
    graphs = set()
    with ThreadPoolExecutor(3) as pool:
        for g in pool.map(lambda _: te.build_graph(a, cfg).to_json(), range(6)):
            graphs.add(g)
    assert len(graphs) == 1
    assert te.rank(gt, [a, b, a], threads=3).to_csv() == te.rank(gt, [a, b, a], threads=1).to_csv()


def test_the_gil_is_released_while_computing():
    gt, a = te.load_map(MAP_B), te.load_map(MAP_A)
    t = threading.Thread(target=te.compare, args=(gt, a))
    ticks = 0
    t.start()
    while t.is_alive():  # runs only if compare() let go of the GIL
        ticks += 1
    t.join()
    assert ticks > 1000
