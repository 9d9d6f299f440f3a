"""Every file of the bad-input corpus (tests/data/bad_inputs, the corpus cli_test drives through
`topoeval graph`) raises InputError, a ValueError, with the message the command prints."""
import os

import pytest

import mrpt_topoeval as te
from conftest import TESTS, cli_error, run_topoeval

CORPUS = os.path.join(TESTS, "data", "bad_inputs")
FILES = sorted(f for f in os.listdir(CORPUS)
               if os.path.isfile(os.path.join(CORPUS, f)) and not f.startswith("README"))


def test_the_corpus_is_there():
    assert len(FILES) > 20


@pytest.mark.parametrize("name", FILES)
def test_bad_input_raises_the_cli_message(name):
    path = os.path.join(CORPUS, name)
    code, _, err = run_topoeval("graph", path)
    assert code == 2, err
    with pytest.raises(te.InputError) as e:
        te.build_graph(te.load_map(path))  # what `topoeval graph` does
    assert isinstance(e.value, ValueError)
    assert str(e.value) == cli_error(err)
    # compare() and rank() refuse or report it the same way.
    with pytest.raises(te.InputError) as e2:
        te.compare(path, path)
    assert str(e2.value) == str(e.value)
