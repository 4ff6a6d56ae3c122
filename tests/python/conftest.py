"""Fixtures of the Python module's tests: the gpsurf command line (GPSURF_BINARY, set by ctest) and a
temporary folder."""
import os
import subprocess

import pytest


@pytest.fixture
def cli(tmp_path):
    """Runs `gpsurf ARGS...` in tmp_path; fails the test on a non-zero exit."""
    binary = os.environ.get("GPSURF_BINARY")
    if not binary:
        pytest.fail("GPSURF_BINARY is not set (ctest sets it)")

    def run(*args):
        result = subprocess.run([binary, *map(str, args)], cwd=tmp_path, capture_output=True, text=True)
        assert result.returncode == 0, result.stderr
        return result.stdout

    return run
