"""Runs pytest for ctest: exit 77 (ctest's SKIP_RETURN_CODE) when a package the tests need is
missing, else pytest's exit code. Usage: run_pytest.py --needs numpy pytest -- TEST.py ..."""
import importlib
import os
import sys
import tempfile


def main():
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    needs = [a for a in argv[:split] if a != "--needs"]
    missing = []
    for name in needs:
        try:
            importlib.import_module(name)
        except ImportError:
            missing.append(name)
    if missing:
        print(f"skipped: {sys.executable} lacks {', '.join(missing)} "
              "(Debian: scripts/install-deps installs python3-numpy python3-pytest "
              "python3-distributed)")
        sys.exit(77)

    import pytest

    # A temporary folder of this run's own: concurrent pytest runs (ctest -j2 runs python_api
    # and python_batch side by side) otherwise share /tmp/pytest-of-USER, and each one's
    # clean-up of old runs can delete the other's folders while it works in them.
    tests = argv[split + 1:]
    name = os.path.splitext(os.path.basename(tests[0]))[0] if tests else "pytest"
    work = os.environ.get("TOPOEVAL_WORK_DIR", tempfile.gettempdir())
    os.makedirs(work, exist_ok=True)
    base = os.path.join(work, "pytest-" + name)
    sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", "-rs", "--basetemp", base] + tests))


# Guarded: Dask's LocalCluster starts its workers with multiprocessing "spawn", which imports
# this script again in each worker; unguarded, every worker would run the tests anew.
if __name__ == "__main__":
    main()
