"""Runs pytest for ctest: exit 77 (ctest's SKIP_RETURN_CODE) when a package the tests need is
missing, else pytest's exit code. Usage: run_pytest.py --needs numpy pytest -- TEST.py ..."""
import importlib
import sys


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

    sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", "-rs"] + argv[split + 1:]))


# Guarded: Dask's LocalCluster starts its workers with multiprocessing "spawn", which imports
# this script again in each worker; unguarded, every worker would run the tests anew.
if __name__ == "__main__":
    main()
