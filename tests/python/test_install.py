"""`cmake --install` puts the package where the interpreter imports it from."""

import os
import subprocess
import sys

from conftest import env_path


def test_install_dir_is_on_the_interpreters_path():
    """For /usr/local (CMake's default prefix) and /usr, the directory install_dir.py names
    is one the interpreter searches (Debian: dist-packages)."""
    script = env_path("CONVEXLOC_INSTALL_DIR_SCRIPT")
    for prefix in ("/usr/local", "/usr"):
        relative = subprocess.run([sys.executable, str(script), prefix], capture_output=True,
                                  text=True, check=True).stdout.strip()
        if sys.prefix != "/usr" and prefix == "/usr":
            continue  # not Debian's interpreter: /usr is not its prefix
        assert os.path.join(prefix, relative) in sys.path, (prefix, relative, sys.path)


def test_installed_package_imports(tmp_path):
    build = env_path("CONVEXLOC_BUILD_DIR")
    relative = os.environ["CONVEXLOC_PYTHON_INSTALL_DIR"]
    cmake = os.environ.get("CMAKE_COMMAND", "cmake")
    subprocess.run([cmake, "--install", str(build), "--component", "python", "--prefix",
                    str(tmp_path)], check=True, capture_output=True)
    site = tmp_path / relative
    installed = sorted(p.name for p in (site / "convexloc").iterdir())
    assert "__init__.py" in installed and "__init__.pyi" in installed and "py.typed" in installed
    assert any(name.startswith("_core") and name.endswith(".so") for name in installed)
    check = ("import convexloc, numpy; "
             "print(convexloc.__file__); "
             "print(convexloc.contains([[0, 0], [1, 0], [0, 1]], [[0.2, 0.2]])[0])")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    run = subprocess.run([sys.executable, "-c", check], capture_output=True, text=True,
                         env=env, cwd=tmp_path, check=True)
    where, answer = run.stdout.split()
    assert where.startswith(str(site)) and answer == "True"
