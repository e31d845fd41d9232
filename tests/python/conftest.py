"""The pytest suite of the Python module (ctest test `python`, tests/CMakeLists.txt): the package is
imported from the build tree (PYTHONPATH=build/python) and compared with the executable
ROUGHGAS_BINARY (build/roughgas) on the same cases and seeds."""
import os
import subprocess

import pytest

SOURCE_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def cli_binary():
    path = os.environ.get("ROUGHGAS_BINARY", os.path.join(SOURCE_DIR, "build", "roughgas"))
    if not os.path.exists(path):
        pytest.fail(f"{path}: no roughgas executable (set ROUGHGAS_BINARY)")
    return path


@pytest.fixture
def cli():
    """Runs `roughgas ARGS...`, returning the CompletedProcess (text)."""
    binary = cli_binary()

    def run(*args, check=True):
        done = subprocess.run([binary, *map(str, args)], capture_output=True, text=True)
        if check and done.returncode != 0:
            raise AssertionError(f"roughgas {' '.join(map(str, args))}: exit {done.returncode}\n{done.stderr}")
        return done

    return run


@pytest.fixture
def case_path():
    return lambda name: os.path.join(SOURCE_DIR, "cases", name + ".toml")
