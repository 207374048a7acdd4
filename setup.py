"""Builds the cavity extension module with CMake, for pip (configuration: pyproject.toml).

The version is the one in CMakeLists.txt's project() line, the project's single version; the
module reports the same one as cavity.__version__ (core/version/version.h.in).
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


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(cavity VERSION ([0-9][0-9.]*)", text)
    if match is None:
        sys.exit("setup.py: no 'project(cavity VERSION ...)' in CMakeLists.txt")
    return match.group(1)


class CMakeBuild(build_ext):
    """Configures the project for the module alone and builds the target cavity_python, for the
    interpreter running the build (CAVITY_PYTHON_EXECUTABLE)."""

    def build_extension(self, ext):
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        configure = ["cmake", "-S", str(ROOT), "-B", str(build),
                     "-DCMAKE_BUILD_TYPE=Release",
                     "-DCAVITY_BUILD_PYTHON=ON",
                     "-DCAVITY_BUILD_PROGRAMS=OFF",
                     "-DCAVITY_BUILD_TESTS=OFF",
                     "-DCAVITY_BUILD_BENCHMARKS=OFF",
                     f"-DCAVITY_PYTHON_EXECUTABLE={sys.executable}"]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "cavity_python",
                        "--parallel", jobs], check=True)
        built = sorted((build / "python" / "cavity").glob("_cavity*" + target.suffix))
        if len(built) != 1:
            sys.exit(f"setup.py: expected one built extension in {build / 'python' / 'cavity'}, "
                     f"found {built}")
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[0], target)


setup(version=project_version(),
      packages=["cavity"],
      package_dir={"cavity": "python/cavity"},
      package_data={"cavity": ["py.typed", "*.pyi"]},
      ext_modules=[Extension("cavity._cavity", sources=[])],
      cmdclass={"build_ext": CMakeBuild})
