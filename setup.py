"""The build of the wheel (pyproject.toml): CMake configures and builds the extension module
gpsurf._gpsurf, which setuptools packages with python/gpsurf's files. The version is the CMake
project's."""
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = Path(__file__).resolve().parent
# setuptools' own build folders (and its egg-info), kept in one place under the ignored build/.
BUILD_BASE = SOURCE_DIR / "build" / "python-wheel"


def project_version():
    """The VERSION of CMakeLists.txt's project()."""
    text = (SOURCE_DIR / "CMakeLists.txt").read_text()
    return re.search(r"project\(\s*gpsurf\s+VERSION\s+([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    """Builds the module with CMake (a fresh core-and-Python build unless GPSURF_CMAKE_BUILD_DIR
    names a configured one) and copies it to where setuptools packages it."""

    def build_extension(self, ext):
        build_dir = os.environ.get("GPSURF_CMAKE_BUILD_DIR")
        if not build_dir:
            build_dir = str(Path(self.build_temp).resolve() / "cmake")
            if not (Path(build_dir) / "CMakeCache.txt").exists():
                subprocess.run(
                    ["cmake", "-S", str(SOURCE_DIR), "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                     f"-DPython_EXECUTABLE={sys.executable}", "-DGPSURF_BUILD_TESTS=OFF", "-DGPSURF_BUILD_BENCH=OFF",
                     *shlex.split(os.environ.get("GPSURF_CMAKE_ARGS", ""))],
                    check=True)
        subprocess.run(["cmake", "--build", build_dir, "--target", "gpsurf_python"], check=True)
        built = sorted((Path(build_dir) / "python" / "gpsurf").glob("_gpsurf*.so"))
        if not built:
            sys.exit(f"gpsurf: the CMake build in {build_dir} made no python/gpsurf/_gpsurf*.so")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)
        # OpenImageIO's formats (render/image/image_file_module.h), looked for beside the module.
        image_module = Path(build_dir) / "lib" / "gpsurf" / "libgpsurf_openimageio.so"
        if image_module.exists():
            shutil.copyfile(image_module, target.parent / image_module.name)


BUILD_BASE.mkdir(parents=True, exist_ok=True)
setup(
    version=project_version(),
    packages=["gpsurf"],
    package_dir={"gpsurf": "python/gpsurf"},
    package_data={"gpsurf": ["__init__.pyi", "py.typed"]},
    ext_modules=[Extension("gpsurf._gpsurf", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
    options={"build": {"build_base": str(BUILD_BASE)}, "egg_info": {"egg_base": str(BUILD_BASE)}},
)
