"""The wheel: pip builds it offline from the source tree with --no-build-isolation (setuptools from
Debian driving CMake, here reusing this build's CMake folder), installs it into a fresh virtual
environment, and the package's tests pass there against the installed copy."""
import os
import subprocess
import sys

import pytest

SOURCE_DIR = os.path.abspath(os.environ.get("GPSURF_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")))
BUILD_DIR = os.environ.get("GPSURF_BUILD_DIR")
# The slow ones (threads, Ctrl-C, the fuzz) ran against the build already; this one would recurse.
LEFT_OUT = "not wheel and not ctrl_c and not other_threads and not fuzz"


@pytest.mark.skipif(not BUILD_DIR, reason="GPSURF_BUILD_DIR (set by ctest) names the CMake build to reuse")
def test_wheel_installs_into_a_fresh_venv_and_its_tests_pass(tmp_path):
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env.update(GPSURF_CMAKE_BUILD_DIR=BUILD_DIR, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")

    def run(*command, cwd=tmp_path):
        result = subprocess.run(command, cwd=cwd, env=env, capture_output=True, text=True, timeout=600)
        assert result.returncode == 0, f"{command}:\n{result.stdout[-3000:]}\n{result.stderr[-3000:]}"
        return result.stdout

    run(sys.executable, "-m", "pip", "wheel", "--no-build-isolation", "--no-deps", "-w", str(tmp_path / "dist"),
        SOURCE_DIR)
    wheels = list((tmp_path / "dist").glob("gpsurf-*.whl"))
    assert len(wheels) == 1
    venv = tmp_path / "venv"
    run(sys.executable, "-m", "venv", "--system-site-packages", str(venv))  # Debian's numpy and pytest
    python = str(venv / "bin" / "python")
    run(python, "-m", "pip", "install", "--no-deps", str(wheels[0]))
    where = run(python, "-c", "import gpsurf, os; print(os.path.dirname(gpsurf.__file__)); print(gpsurf.__version__)")
    package_dir, version = where.split()
    assert package_dir.startswith(str(venv))
    assert wheels[0].name.startswith(f"gpsurf-{version}-")
    assert {"__init__.pyi", "py.typed"} <= set(os.listdir(package_dir))
    assert f"Version: {version}" in run(python, "-m", "pip", "show", "gpsurf")
    run(python, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-k", LEFT_OUT, os.path.join(SOURCE_DIR, "tests", "python"))
