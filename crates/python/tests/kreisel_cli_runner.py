"""The `kreisel` binary of this checkout, for tests that compare the Python
package with the CLI bit for bit.

The binary is `$KREISEL_BIN` if set (CI sets it to the
release build of this checkout), else it is built now (`cargo build -p
kreisel-cli`, honouring CARGO_TARGET_DIR) from the same workspace the
package was built from, so both hold the same code (an existing binary
could be older than the source).
"""

import functools
import json
import os
import pathlib
import subprocess

REPO = pathlib.Path(__file__).resolve().parents[3]


@functools.lru_cache(maxsize=None)
def binary() -> str:
    """Path of the `kreisel` executable."""
    given = os.environ.get("KREISEL_BIN")
    if given:
        return given
    subprocess.run(
        ["cargo", "build", "--quiet", "-p", "kreisel-cli", "--bin", "kreisel"],
        cwd=REPO,
        check=True,
    )
    meta = subprocess.run(
        ["cargo", "metadata", "--format-version", "1", "--no-deps"],
        cwd=REPO,
        check=True,
        capture_output=True,
        text=True,
    )
    target = pathlib.Path(json.loads(meta.stdout)["target_directory"])
    return str(target / "debug" / "kreisel")


def run(*args, cwd=REPO) -> subprocess.CompletedProcess:
    """Runs `kreisel ARGS` (text output, not checked)."""
    return subprocess.run(
        [binary(), *map(str, args)], cwd=cwd, capture_output=True, text=True
    )


def error_line(*args, cwd=REPO) -> str:
    """The message of the error `kreisel ARGS` prints (after `kreisel: error: `)."""
    done = run(*args, cwd=cwd)
    assert done.returncode != 0, done.stdout
    line = done.stderr.strip().splitlines()[-1]
    prefix = "kreisel: error: "
    assert line.startswith(prefix), done.stderr
    return line[len(prefix) :]
