"""The compiled half of `pip install .` (pyproject.toml): configures and builds the C++ project
with CMake, then places its products in the package —
  tendril/_tendril*.so     the extension module
  tendril/_version.py      the version (from VERSION, through CMake)
  tendril/bin/tendril      the command-line program (the `tendril` command runs it)
  tendril/bin/libtendril_dynamics_plugin.so   its learned-model part (LibTorch), loaded by the
                           program when a command needs it (docs/architecture.md)
  tendril/dashboard/       the page `tendril serve` serves
The CMake build directory is TENDRIL_CMAKE_BUILD_DIR when set, else build-pip/ beside the
sources; it is kept between builds, so a rebuild compiles only what changed. With ccache
(scripts/setup), a build directory at the same depth below the sources as build/ (as build-pip/
is) gets every object `scripts/build` compiled from the compiler cache, since ccache sees the
same relative paths. TENDRIL_CMAKE_ARGS adds options to the configuration (e.g.
"-DTENDRIL_NATIVE=OFF" for a wheel meant for other machines); CMAKE_BUILD_PARALLEL_LEVEL sets
the build's jobs (default 2)."""
import glob
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
# setuptools' own build and egg-info directories, kept out of the source tree's top level.
os.makedirs(os.path.join(ROOT, "build", "python-package"), exist_ok=True)


class CMakeExtension(Extension):
    def __init__(self):
        super().__init__("tendril._tendril", sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.environ.get("TENDRIL_CMAKE_BUILD_DIR") or os.path.join(ROOT, "build-pip")
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        configure = ["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                     "-DTENDRIL_BUILD_TESTS=OFF", "-DTENDRIL_BUILD_BENCH=OFF",
                     f"-DTENDRIL_PYTHON_EXECUTABLE={sys.executable}",
                     *os.environ.get("TENDRIL_CMAKE_ARGS", "").split()]
        if shutil.which("ninja") and not os.path.exists(os.path.join(build, "CMakeCache.txt")):
            configure += ["-G", "Ninja"]
        subprocess.run(configure, check=True)
        targets = ["_tendril", "tendril", "python_package"]
        page = os.path.join(ROOT, "web", "node_modules", "esbuild", "package.json")
        if os.path.exists(page):
            targets.append("dashboard_page")
        subprocess.run(["cmake", "--build", build, "-j", jobs, "--target", *targets], check=True)

        package = os.path.dirname(self.get_ext_fullpath(ext.name))
        os.makedirs(package, exist_ok=True)
        built = glob.glob(os.path.join(build, "python", "tendril", "_tendril*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one extension module in {build}/python/tendril, "
                               f"found {built}")
        shutil.copyfile(built[0], self.get_ext_fullpath(ext.name))
        shutil.copyfile(os.path.join(build, "python", "tendril", "_version.py"),
                        os.path.join(package, "_version.py"))
        os.makedirs(os.path.join(package, "bin"), exist_ok=True)
        program = os.path.join(package, "bin", "tendril")
        shutil.copyfile(os.path.join(build, "apps", "tendril"), program)
        os.chmod(program, 0o755)
        # Building the program built its plugin; the program looks for it in its own directory.
        plugin = "libtendril_dynamics_plugin.so"
        built_plugin = os.path.join(build, "apps", plugin)
        if os.path.exists(built_plugin):
            shutil.copyfile(built_plugin, os.path.join(package, "bin", plugin))
        pages = os.path.join(build, "web", "dashboard")
        if os.path.isdir(pages):
            shutil.copytree(pages, os.path.join(package, "dashboard"), dirs_exist_ok=True)


setup(ext_modules=[CMakeExtension()], cmdclass={"build_ext": CMakeBuild})
