"""setuptools' half of pyproject.toml: the extension convexloc._core is built by CMake (core and
the bindings alone, for the interpreter running this), then copied where setuptools puts
extensions. The pure-Python modules and the stubs come from app/python/convexloc as they are.

Environment: CONVEXLOC_USE_GMP=ON/OFF overrides the GMP check (ON where pkg-config finds gmp);
CONVEXLOC_CMAKE_ARGS adds arguments to CMake's configure step (split as a shell would);
CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs (default: every core)."""

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_version() -> str:
    """The VERSION of project() in CMakeLists.txt: one version for C++ and Python."""
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    found = re.search(r"project\(\s*convexloc\s+VERSION\s+([0-9.]+)", text)
    if not found:
        raise RuntimeError("CMakeLists.txt: no 'project(convexloc VERSION x.y.z' found")
    return found.group(1)


def gmp_option() -> str:
    """ON where GMP is there for core's exact numbers (pkg-config gmp), else OFF: core then
    uses Boost's header-only cpp_int, with the same exact answers."""
    asked = os.environ.get("CONVEXLOC_USE_GMP")
    if asked:
        return asked
    pkg_config = shutil.which("pkg-config")
    if pkg_config and subprocess.run([pkg_config, "--exists", "gmp"]).returncode == 0:
        return "ON"
    return "OFF"


class CMakeBuild(build_ext):
    """Configures and builds the convexloc_python target, then copies _core*.so into place."""

    def build_extension(self, ext: Extension) -> None:
        build_dir = Path(self.build_temp).resolve() / "cmake"
        build_dir.mkdir(parents=True, exist_ok=True)
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython_EXECUTABLE={sys.executable}",
            "-DCONVEXLOC_BUILD_PYTHON=ON",
            "-DCONVEXLOC_BUILD_TESTS=OFF", "-DCONVEXLOC_BUILD_CLI=OFF",
            "-DCONVEXLOC_BUILD_VIEWER=OFF", "-DCONVEXLOC_BUILD_BENCH=OFF",
            f"-DCONVEXLOC_USE_GMP={gmp_option()}",
        ]
        if shutil.which("ninja") and not (build_dir / "Makefile").exists():
            configure += ["-G", "Ninja"]
        configure += shlex.split(os.environ.get("CONVEXLOC_CMAKE_ARGS", ""))
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "convexloc_python",
                        "--parallel", jobs], check=True)
        built = sorted((build_dir / "python" / "convexloc").glob("_core*.so"))
        if not built:
            raise RuntimeError(f"CMake built no convexloc/_core*.so under {build_dir} (its "
                               "configure step says why: pybind11-dev, python3-dev or numpy "
                               "missing?)")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    version=project_version(),
    ext_modules=[Extension("convexloc._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own build folder, apart from the CMake build/ the project's set-up makes
    options={"build": {"build_base": "build-python"}},
)
