"""Smoke test of ``benchmarks/compare.py --quick``: it runs, prints the table, and agrees with
ballcollide on every clear (non-grazing) pair of the random and at-rest sets."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[2] / "benchmarks" / "compare.py"
ROW = re.compile(
    r"^\| (?P<method>[^|]+?) +\| +(?P<pairs>\d+) \| +(?P<ns>[\d.]+) \| +(?P<cpu>[\d.]+) \|"
    r" +[\d.]+ \| +\d+ \| +(?P<disagree>\d+|—) \| +(?P<clear>\d+|—) \|"
)


def run_quick() -> str:
    """The script's output on the quick settings (no pooltool)."""
    done = subprocess.run(
        [sys.executable, str(SCRIPT), "--quick", "--sets", "random,at_rest"],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    return done.stdout


def rows(out: str) -> dict[str, list[dict[str, str]]]:
    """Table rows per method name, in order of the sets."""
    found: dict[str, list[dict[str, str]]] = {}
    for line in out.splitlines():
        m = ROW.match(line)
        if m:
            found.setdefault(m["method"], []).append(m.groupdict())
    return found


def test_quick_run_prints_the_table_and_agrees_on_clear_pairs() -> None:
    out = run_quick()
    assert "## set: random" in out and "## set: at_rest" in out
    assert "skipped pooltool" in out
    table = rows(out)
    methods = ["ballcollide, 1 thread", "numpy.roots loop (all windows)", "numpy eigvals batched"]
    for method in methods:
        assert len(table.get(method, [])) == 2, (method, out)
        for row in table[method]:
            assert float(row["ns"]) > 0
    for method in methods[1:]:
        for row in table[method]:
            assert row["clear"] == "0", (method, out)
