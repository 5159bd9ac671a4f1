"""``python -m ballcollide``: command-line tools (``demo``; more subcommands may follow)."""

from __future__ import annotations

import argparse
import sys

from . import __version__, demo


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m ballcollide",
        description="ballcollide: collision times of balls slowing under friction.",
    )
    parser.add_argument("--version", action="version", version=f"ballcollide {__version__}")
    subparsers = parser.add_subparsers(title="commands", dest="command", required=True)
    demo.add_parser(subparsers)
    args = parser.parse_args(argv)
    return int(args.func(args))


if __name__ == "__main__":
    sys.exit(main())
