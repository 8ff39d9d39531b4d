"""Shared helpers of the kreisel Python tests: the repository's paths, the
sequences and the CLI (the exact rotations are in mp_reference.py)."""

import subprocess
from pathlib import Path

import pytest

import kreisel_cli_runner

REPO = Path(__file__).resolve().parents[3]
DATA = REPO / "tests" / "data"

TAIT_BRYAN = ["XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"]
PROPER = ["XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"]
SEQUENCES = TAIT_BRYAN + PROPER + [s.lower() for s in TAIT_BRYAN + PROPER]


@pytest.fixture(scope="session")
def cli():
    """Runs the CLI of this checkout (kreisel_cli_runner.binary: $KREISEL_BIN,
    else built now); returns (exit status, stdout, stderr)."""
    binary = kreisel_cli_runner.binary()

    def run(*args, stdin=None):
        done = subprocess.run([binary, *args], input=stdin, capture_output=True, text=True)
        return done.returncode, done.stdout, done.stderr

    return run
