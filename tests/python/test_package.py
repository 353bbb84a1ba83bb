"""The pip route on a copy of the repository, in a fresh venv made with --system-site-packages:
`pip install --no-build-isolation` builds and installs the package (the one compile),
importlib.metadata knows it, `python3 -m build --wheel --no-isolation` makes a wheel from the
same CMake build, `pip uninstall -y` removes it (label install: the sanitized run skips it)."""

import os
import re
import shutil
import subprocess
import sys
import zipfile

from conftest import env_path

# what the copy leaves out: build folders, the git store, earlier packaging output
SKIPPED = shutil.ignore_patterns(".git", "build", "build-*", "dist", "*.egg-info", "__pycache__",
                                 ".cache", "out")


def project_version(root):
    text = (root / "CMakeLists.txt").read_text()
    return re.search(r"project\(\s*convexloc\s+VERSION\s+([0-9.]+)", text).group(1)


def run(args, cwd, env):
    done = subprocess.run([str(a) for a in args], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=1200)
    assert done.returncode == 0, f"{args} failed:\n{done.stdout[-4000:]}\n{done.stderr[-4000:]}"
    return done.stdout


def test_pip_install_wheel_and_uninstall():
    source = env_path("CONVEXLOC_SOURCE_DIR")
    # a fixed place in the build tree, so that a compiler cache finds the same paths each run
    work = env_path("CONVEXLOC_BUILD_DIR") / "tests" / "python" / "package"
    shutil.rmtree(work, ignore_errors=True)
    copy, venv, dist, elsewhere = work / "convexloc", work / "venv", work / "dist", work / "cwd"
    shutil.copytree(source, copy, ignore=SKIPPED)
    elsewhere.mkdir()
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    # what is tested is the packaging, not the optimiser: the link-time optimisation and -O2 that
    # pip users get would make this the suite's longest compile, so the test builds at -O0
    env["CONVEXLOC_CMAKE_ARGS"] = ("-DCMAKE_INTERPROCEDURAL_OPTIMIZATION=OFF "
                                   "-DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0")
    run(["/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable,
         "-m", "venv", "--system-site-packages", venv], work, env)
    python = venv / "bin" / "python"

    run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index", "--no-deps", copy],
        elsewhere, env)
    check = ("import importlib.metadata, convexloc\n"
             "print(importlib.metadata.version('convexloc'))\nprint(convexloc.__file__)\n"
             "print(convexloc.covers({'type': 'Polygon', 'coordinates': "
             "[[[0, 0], [1, 0], [0, 1], [0, 0]]]}, [[0.5, 0.5], [0.6, 0.6]]).tolist())")
    version, where, answer = run([python, "-c", check], elsewhere, env).split("\n")[:3]
    assert version == project_version(source)
    assert where.startswith(str(venv)) and "site-packages" in where
    assert answer == "[True, False]"  # (0.5, 0.5) is on the hypotenuse
    installed = os.path.dirname(where)
    assert {"__init__.pyi", "py.typed"} <= set(os.listdir(installed))

    # the wheel, from the same CMake build folder: nothing is compiled again
    run([python, "-m", "build", "--wheel", "--no-isolation", "--outdir", dist, copy], elsewhere,
        env)
    wheels = list(dist.glob("convexloc-*.whl"))
    assert len(wheels) == 1 and wheels[0].name.startswith(f"convexloc-{version}-")
    names = zipfile.ZipFile(wheels[0]).namelist()
    assert any(re.fullmatch(r"convexloc/_core\..*\.so", n) for n in names), names
    assert "convexloc/__init__.pyi" in names and "convexloc/py.typed" in names
    assert not any(n.startswith(("core/", "tests/", "app/")) for n in names)

    run([python, "-m", "pip", "uninstall", "-y", "convexloc"], elsewhere, env)
    # a system-wide install (cmake --install) may still be importable: not from the venv
    after = ("import importlib.metadata, importlib.util\n"
             "spec = importlib.util.find_spec('convexloc')\n"
             "print(spec.origin if spec else None)\n"
             "try:\n    print(importlib.metadata.version('convexloc'))\n"
             "except importlib.metadata.PackageNotFoundError:\n    print('no metadata')\n")
    origin, metadata = run([python, "-c", after], elsewhere, env).split("\n")[:2]
    assert not origin.startswith(str(venv)) and metadata == "no metadata"
    assert not os.path.exists(installed)
    shutil.rmtree(work, ignore_errors=True)
