"""The README's Python examples, run as they are written: every ```python
block of README.md, each in a fresh namespace, from the repository root
(so that relative paths such as assets/t_handle.obj resolve)."""

import re
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[3]
BLOCKS = re.findall(r"```python\n(.*?)```", (REPO / "README.md").read_text(), re.S)


def test_the_readme_has_python_examples():
    assert BLOCKS, "README.md has no ```python block"


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_readme_python_block(index, monkeypatch):
    monkeypatch.chdir(REPO)
    exec(compile(BLOCKS[index], f"README.md python block {index + 1}", "exec"), {})
