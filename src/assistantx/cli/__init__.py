"""The ``assistantx`` command line.

Each sub-command lives in its own module that exposes ``register(subparsers)``; the module
adds its parser and sets ``func`` (a callable taking the parsed namespace and returning the
exit code). Listing the command's name and module in ``COMMANDS`` is all it takes to add one.

Commands are lazy: when the command line names a command, only that command's module is
imported, so ``assistantx office show`` never pays for FastAPI, SciPy or Matplotlib, which
``serve`` and ``map`` need. The full parser (every module) is built only for ``--help``, for
a mistyped command, or when no command is given, so those still list every command.
"""

from __future__ import annotations

import argparse
import importlib
import logging
import os
import sys
from collections.abc import Sequence

# Command name on the command line -> the module that registers it (a module may register
# several commands, as lock_cmd does). Listed in the order ``--help`` shows them.
COMMANDS: dict[str, str] = {
    "office": "assistantx.cli.office_cmd",
    "sim": "assistantx.cli.sim_cmd",
    "run": "assistantx.cli.run_cmd",
    "lock-sim": "assistantx.cli.lock_cmd",
    "lock-keys": "assistantx.cli.lock_cmd",
    "map": "assistantx.cli.map_cmd",
    "llm": "assistantx.cli.llm_cmd",
    "serve": "assistantx.cli.serve_cmd",
    "dataset": "assistantx.cli.dataset_cmd",
    "eval": "assistantx.cli.eval_cmd",
    "report": "assistantx.cli.report_cmd",
    "matrix": "assistantx.cli.matrix_cmd",
}


def _named_command(argv: Sequence[str]) -> str | None:
    """The command ``argv`` names (its first word that is not an option), if it is known.
    The top-level parser's only option (``-v``) takes no value, so the first non-option word
    is the command."""
    for word in argv:
        if not word.startswith("-"):
            return word if word in COMMANDS else None
    return None


def build_parser(argv: Sequence[str] | None = None) -> argparse.ArgumentParser:
    """The parser for ``argv``: only the named command's module when it names one, else all."""
    parser = argparse.ArgumentParser(
        prog="assistantx", description="AssistantX, a proactive office assistant."
    )
    parser.add_argument("-v", "--verbose", action="count", default=0, help="more logging")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    named = _named_command(argv) if argv is not None else None
    modules = [COMMANDS[named]] if named is not None else list(dict.fromkeys(COMMANDS.values()))
    for name in modules:
        importlib.import_module(name).register(sub)
    return parser


# pydantic looks for plugins among every installed package's entry points when it builds its
# first model: about a tenth of `office show`. AssistantX uses none; a user who does can set
# the variable (an empty value enables them all again).
_NO_PYDANTIC_PLUGINS = ("PYDANTIC_DISABLE_PLUGINS", "__all__")


def main(argv: Sequence[str] | None = None) -> int:
    os.environ.setdefault(*_NO_PYDANTIC_PLUGINS)
    words = list(sys.argv[1:] if argv is None else argv)
    parser = build_parser(words)
    args = parser.parse_args(words)
    level = logging.WARNING - 10 * min(args.verbose, 2)
    logging.basicConfig(level=level, format="%(asctime)s %(levelname)s %(name)s: %(message)s")
    try:
        code: int = args.func(args)
    except KeyboardInterrupt:
        return 130
    return code


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
