"""The committed shots of pooltool (``tests/data/shot_cases.txt``, read by
``tests/reference/shots.rs``) are what the installed pooltool simulates.

The first shots of each kind are played again by ``tools/shot_reference.py``: the same
inputs and events to the bit on the machine that wrote the file, and elsewhere the same lines
with numbers within ``1e-9`` (pooltool's BLAS and numba may round otherwise on another CPU).
"""

from __future__ import annotations

import pytest

pytest.importorskip("pooltool")

from .reference import ROOT, same_words, script

FILE = ROOT / "tests" / "data" / "shot_cases.txt"
COUNT = 2  # shots of each kind played again
TOLERANCE = 1e-9  # numbers of a line another CPU may round otherwise (relative above 1)


def shots(lines: list[str]) -> dict[str, list[str]]:
    """Each shot's lines by its name, and the table's under ``""``."""
    by_name: dict[str, list[str]] = {"": []}
    name = ""
    for line in lines:
        if line.startswith("shot "):
            name = line.split()[1]
            by_name[name] = []
        if not line.startswith("#"):
            by_name[name].append(line)
    return by_name


def test_the_shots_are_what_pooltool_simulates() -> None:
    tool = script("tools/shot_reference.py")
    fresh = shots(tool.cases(COUNT))
    committed = shots(FILE.read_text().splitlines())
    for name, lines in fresh.items():
        assert name in committed, name
        then = committed[name]
        assert len(lines) == len(then), name
        for now, before in zip(lines, then):
            words_now, words_then = now.split(), before.split()
            assert len(words_now) == len(words_then), (now, before)
            assert same_words(words_now, words_then, TOLERANCE), (now, before)
