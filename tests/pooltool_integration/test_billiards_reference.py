"""The committed table of pooltool's answers (``tests/data/billiards_cases.txt``, read by
``tests/reference/billiards.rs``) is what the installed pooltool computes.

The first cases of each kind are drawn again by ``tools/billiards_reference.py`` and asked of
pooltool again, here: the same inputs to the bit, and the same outputs (to the bit, or within
``1e-12`` relative where pooltool's slide goes through BLAS, whose kernels may round
otherwise on another CPU).
"""

from __future__ import annotations

import pytest

pytest.importorskip("pooltool")

from .reference import ROOT, same_words, script

TABLE = ROOT / "tests" / "data" / "billiards_cases.txt"
COUNT = 200  # cases of each kind drawn again
TOLERANCE = 1e-12  # numbers of a line another CPU may round otherwise (relative above 1)


def committed() -> dict[str, list[str]]:
    """The table's lines by kind, in order."""
    kinds: dict[str, list[str]] = {}
    for line in TABLE.read_text().splitlines():
        if line and not line.startswith("#"):
            kinds.setdefault(line.split()[0], []).append(line)
    return kinds


def test_the_table_is_what_pooltool_computes() -> None:
    table = committed()
    fresh: dict[str, list[str]] = {}
    for line in script("tools/billiards_reference.py").cases(COUNT):
        fresh.setdefault(line.split()[0], []).append(line)
    assert sorted(fresh) == sorted(table)
    differing = 0
    for kind, lines in fresh.items():
        for ours, theirs in zip(lines, table[kind][:COUNT]):
            inputs_now, outputs_now = ours.split(" : ")
            inputs_then, outputs_then = theirs.split(" : ")
            assert inputs_now == inputs_then, "the same random inputs"
            words_now, words_then = outputs_now.split(), outputs_then.split()
            assert len(words_now) == len(words_then), (ours, theirs)
            assert same_words(words_now, words_then, TOLERANCE), (ours, theirs)
            differing += outputs_now != outputs_then
    # On the machine that wrote the table, every output is the same to the bit.
    print(f"{differing} of {sum(map(len, fresh.values()))} lines not equal to the bit")
