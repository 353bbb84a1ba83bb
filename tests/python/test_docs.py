"""Every code block of docs/python.md and of the README's "From Python" section runs as
written, each in a fresh interpreter of its own."""

import os
import subprocess
import sys

import pytest

from conftest import doc_code_blocks

BLOCKS = doc_code_blocks() if os.environ.get("CONVEXLOC_SOURCE_DIR") else []


def test_the_blocks_are_found():
    if not BLOCKS:
        pytest.skip("CONVEXLOC_SOURCE_DIR is not set (run the tests through ctest)")
    labels = [label for label, _ in BLOCKS]
    assert sum(label.startswith("docs/python.md") for label in labels) >= 4
    assert sum(label.startswith("README.md") for label in labels) == 1


@pytest.mark.parametrize("label, code", BLOCKS, ids=[label for label, _ in BLOCKS])
def test_block_runs_as_written(label, code, tmp_path):
    run = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=dict(os.environ),
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, f"{label} failed:\n{code}\n{run.stderr}"
