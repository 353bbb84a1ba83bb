"""mypy --strict accepts the examples, the documentation's code blocks and the package's own
Python modules, through the stubs (test_stubtest.py checks the stubs against the module)."""

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import pytest

import convexloc
from conftest import doc_code_blocks, env_path

pytestmark = pytest.mark.skipif(importlib.util.find_spec("mypy") is None,
                                reason="mypy is not installed (Debian: python3-mypy); the types "
                                       "were not checked")

HERE = Path(__file__).parent
PACKAGE_ROOT = Path(convexloc.__file__).parent.parent


def run_mypy(*args, cwd=None):
    # one cache in the build folder: numpy's stubs are analysed once, not by every run
    cache = env_path("CONVEXLOC_BUILD_DIR") / "mypy_cache"
    env = dict(os.environ, MYPYPATH=str(PACKAGE_ROOT))
    return subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(cache), *args],
                          capture_output=True, text=True, cwd=cwd, env=env, timeout=600)


def test_mypy_strict_on_the_examples_and_the_doc_blocks(tmp_path):
    files = sorted(str(p) for p in env_path("CONVEXLOC_EXAMPLES").glob("*.py"))
    for k, (label, code) in enumerate(doc_code_blocks()):
        block = tmp_path / f"block_{k}.py"
        block.write_text(f"# {label}\n{code}")
        files.append(str(block))
    run = run_mypy("--config-file", str(HERE / "mypy.ini"), *files)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "Success" in run.stdout


def test_mypy_strict_on_the_package():
    run = run_mypy("--strict", "-p", "convexloc", cwd=PACKAGE_ROOT)
    assert run.returncode == 0, run.stdout + run.stderr


def test_mypy_finds_a_wrong_call(tmp_path):
    # the check can fail: a call the stubs forbid is reported
    wrong = tmp_path / "wrong.py"
    wrong.write_text("import convexloc\n"
                     "convexloc.PolarLocator(convexloc.Polygon([[0, 0], [1, 0], [0, 1]]))"
                     ".locate([[0, 0]], threads='many')\n")
    run = run_mypy("--config-file", str(HERE / "mypy.ini"), str(wrong))
    assert run.returncode == 1 and 'incompatible type "str"' in run.stdout
