"""The ``assistantx`` command line.

Each sub-command lives in its own module that exposes ``register(subparsers)``; the module
adds its parser and sets ``func`` (a callable taking the parsed namespace and returning the
exit code). Listing a module in ``COMMAND_MODULES`` is all it takes to add a command.
"""

from __future__ import annotations

import argparse
import importlib
import logging
import sys
from collections.abc import Sequence

COMMAND_MODULES = [
    "assistantx.cli.office_cmd",
    "assistantx.cli.sim_cmd",
    "assistantx.cli.run_cmd",
    "assistantx.cli.lock_cmd",
    "assistantx.cli.map_cmd",
    "assistantx.cli.llm_cmd",
    "assistantx.cli.serve_cmd",
    "assistantx.cli.dataset_cmd",
    "assistantx.cli.eval_cmd",
    "assistantx.cli.report_cmd",
    "assistantx.cli.matrix_cmd",
]


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="assistantx", description="AssistantX, a proactive office assistant."
    )
    parser.add_argument("-v", "--verbose", action="count", default=0, help="more logging")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name in COMMAND_MODULES:
        importlib.import_module(name).register(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    level = logging.WARNING - 10 * min(args.verbose, 2)
    logging.basicConfig(level=level, format="%(asctime)s %(levelname)s %(name)s: %(message)s")
    try:
        code: int = args.func(args)
    except KeyboardInterrupt:
        return 130
    return code


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
