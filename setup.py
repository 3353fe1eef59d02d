"""Builds the Python package `mmvlab` with CMake (pyproject.toml says how to install it).

The native module (_mmvlab*.so) and the plugins it loads at run time (the SUNDIALS
steppers, the .mat reader: sim/core/plugins.hpp looks for them beside the module) are
built by the project's CMake in MMVLAB_CMAKE_BUILD_DIR (default: build/pip in the
checkout, so a second install rebuilds nothing), for the interpreter running this file,
and copied into the package. The version is CMakeLists.txt's project(VERSION).
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
VERSION = re.search(r"project\(mmvlab VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)
PLUGINS = ["libmmvlab_mat.so", "libmmvlab_sundials.so"]


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = pathlib.Path(os.environ.get("MMVLAB_CMAKE_BUILD_DIR", ROOT / "build" / "pip")).resolve()
        jobs = os.environ.get("MMVLAB_BUILD_JOBS", str(os.cpu_count() or 1))
        if not (build / "CMakeCache.txt").exists():
            subprocess.check_call(["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                                   f"-DPython_EXECUTABLE={sys.executable}", "-DMMVLAB_BUILD_BENCH=OFF"])
        subprocess.check_call(["cmake", "--build", str(build), "-j", jobs, "--target", "mmvlab_python",
                               "mmvlab_mat", "mmvlab_sundials"])
        module = pathlib.Path(self.get_ext_fullpath(ext.name))
        module.parent.mkdir(parents=True, exist_ok=True)
        built = sorted((build / "python" / "mmvlab").glob("_mmvlab*.so"))
        if len(built) != 1:
            raise RuntimeError(f"{build}/python/mmvlab: expected one _mmvlab*.so, found {[p.name for p in built]}")
        shutil.copyfile(built[0], module)
        for plugin in PLUGINS:
            shutil.copyfile(build / plugin, module.parent / plugin)


setup(
    version=VERSION,
    packages=["mmvlab"],
    package_dir={"mmvlab": "python/mmvlab"},
    package_data={"mmvlab": ["py.typed", "*.pyi"]},
    ext_modules=[Extension("mmvlab._mmvlab", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
