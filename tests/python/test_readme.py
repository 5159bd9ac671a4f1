"""Every ```python block of README.md runs as written (each in a fresh namespace).

Blocks that import an optional package (dask, pooltool) are skipped where it is not
installed, unless ``BALLCOLLIDE_REQUIRE_<PACKAGE>=1`` says it must be there
(``scripts/test-pooltool`` runs this file in its pooltool environment with
``BALLCOLLIDE_REQUIRE_POOLTOOL=1``, so every block runs somewhere). The first install
command of the README and the test command are checked to be the ones it starts with.
"""

from __future__ import annotations

import importlib.util
import os
import re
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[2] / "README.md"
OPTIONAL = ("dask", "pooltool")


def python_blocks() -> list[tuple[int, str]]:
    """The README's ```python blocks, with the line each starts on."""
    text = README.read_text(encoding="utf-8")
    blocks = []
    for m in re.finditer(r"^```python\n(.*?)^```$", text, flags=re.MULTILINE | re.DOTALL):
        blocks.append((text.count("\n", 0, m.start()) + 1, m.group(1)))
    return blocks


BLOCKS = python_blocks()


def test_the_readme_has_python_examples() -> None:
    assert len(BLOCKS) >= 6


def test_the_readme_starts_with_the_install_and_test_commands() -> None:
    text = README.read_text(encoding="utf-8")
    first = text[: text.index("\n## ")]
    assert (
        "python3 -m venv .venv && .venv/bin/pip install . && .venv/bin/python -m ballcollide demo"
        in first
    )
    assert "\n./scripts/test\n" in first


@pytest.mark.parametrize(("line", "code"), BLOCKS, ids=[f"line{n}" for n, _ in BLOCKS])
def test_readme_example_runs(line: int, code: str) -> None:
    for name in OPTIONAL:
        if re.search(rf"^\s*import {name}\b", code, flags=re.MULTILINE):
            if importlib.util.find_spec(name) is None:
                if os.environ.get(f"BALLCOLLIDE_REQUIRE_{name.upper()}") == "1":
                    pytest.fail(f"{name} is required here but not installed")
                pytest.skip(f"{name} is not installed")
    exec(compile(code, f"README.md:{line}", "exec"), {"__name__": "readme_example"})
