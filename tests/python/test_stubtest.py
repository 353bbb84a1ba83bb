"""stubtest finds the stubs equal to the module, apart from the commented allowlist of what it
cannot match (stubtest_allowlist.txt)."""

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import pytest

import convexloc

pytestmark = pytest.mark.skipif(importlib.util.find_spec("mypy") is None,
                                reason="mypy is not installed (Debian: python3-mypy); the stubs "
                                       "were not checked")

HERE = Path(__file__).parent
PACKAGE_ROOT = Path(convexloc.__file__).parent.parent


def test_stubtest():
    env = dict(os.environ)
    run = subprocess.run([sys.executable, "-m", "mypy.stubtest", "--allowlist",
                          str(HERE / "stubtest_allowlist.txt"), "convexloc"],
                         capture_output=True, text=True, cwd=PACKAGE_ROOT, env=env, timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
