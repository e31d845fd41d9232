"""setuptools drives the CMake build of the extension roughgas._roughgas, as pybind11's CMake example
does. The build directory is $ROUGHGAS_BUILD_DIR, else build/ (scripts/setup.sh's): one already
configured is reused, and only the module's target is built there, so an install after set-up
compiles nothing again. An unconfigured one is configured as scripts/setup.sh configures it."""
import os
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
BUILD = os.path.abspath(os.environ.get("ROUGHGAS_BUILD_DIR", os.path.join(ROOT, "build")))


def version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        return re.search(r"project\(roughgas VERSION ([0-9.]+)", f.read()).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if not os.path.exists(os.path.join(BUILD, "CMakeCache.txt")):
            subprocess.run(["cmake", "-G", "Ninja", "-S", ROOT, "-B", BUILD, "-DCMAKE_BUILD_TYPE=Release",
                            f"-DPYTHON_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", BUILD, "--target", "_roughgas", "--parallel", str(os.cpu_count() or 1)],
                       check=True)
        built = os.path.join(BUILD, "python", "roughgas", "_roughgas" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not os.path.exists(built):
            raise RuntimeError(f"{built}: not built; the build in {BUILD} is for another Python than "
                               f"{sys.executable} (set ROUGHGAS_BUILD_DIR to a new directory)")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built, target)


setup(
    version=version(),
    packages=["roughgas"],
    package_dir={"roughgas": "src/python/roughgas"},
    ext_modules=[Extension("roughgas._roughgas", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own build files beside CMake's, not in the source tree.
    options={"build": {"build_base": os.path.join(BUILD, "setuptools")},
             "egg_info": {"egg_base": BUILD}},
    zip_safe=False,
)
