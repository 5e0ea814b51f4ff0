"""Builds the module trebuchet._trebuchet with the project's CMake (pyproject.toml has the rest).

The version is the project's, from CMakeLists.txt. TREBUCHET_BUILD_DIR names a build folder
configured with -DTREBUCHET_PYTHON=ON to reuse (CI's install test), so that the library is not
compiled twice; without it the build goes to setuptools' own temporary folder, a unity build as
every build of the project is by default (CMakeLists.txt: the sources of a target compiled a few
at a time in one unit, which halves a first install's compile on two cores, docs/benchmarks.md).
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build import build
from setuptools.command.build_ext import build_ext

SOURCE = pathlib.Path(__file__).parent.resolve()
VERSION = re.search(r"project\(trebuchet VERSION (\S+)", (SOURCE / "CMakeLists.txt").read_text()).group(1)


class Build(build):
    # setuptools' own build folder, out of the way of the project's build/ (CMake's).
    def initialize_options(self):
        super().initialize_options()
        self.build_base = "build-python"


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        reused = os.environ.get("TREBUCHET_BUILD_DIR")
        build = pathlib.Path(reused).resolve() if reused else pathlib.Path(self.build_temp).resolve() / "cmake"
        if not (build / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release", "-DTREBUCHET_PYTHON=ON",
                            "-DTREBUCHET_BUILD_TESTS=OFF", "-DTREBUCHET_BUILD_PROGRAMS=OFF", f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "_trebuchet", "-j", str(os.cpu_count() or 2)], check=True)
        built = sorted((build / "python" / "trebuchet").glob("_trebuchet*.so"))
        if not built:
            raise RuntimeError(f"the build in {build} made no module _trebuchet")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[0], target)


setup(version=VERSION, ext_modules=[Extension("trebuchet._trebuchet", sources=[])], cmdclass={"build": Build, "build_ext": CMakeBuild})
