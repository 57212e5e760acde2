"""``assistantx matrix registration``: write the application-service registration file the
homeserver loads (``app_service_config_files`` in Synapse's homeserver.yaml).

The Matrix config comes from ``--config`` or ``ASSISTANTX_MATRIX_CONFIG``; the file is written
with mode 0600 because it holds both tokens. ``-o -`` prints it instead.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import yaml

from assistantx.core.errors import MessengerError
from assistantx.core.settings import Settings


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    matrix = sub.add_parser("matrix", help="Matrix homeserver set-up")
    actions = matrix.add_subparsers(dest="matrix_command", required=True, metavar="ACTION")
    reg = actions.add_parser(
        "registration", help="write the appservice registration file for the homeserver"
    )
    reg.add_argument("--config", type=Path, help="Matrix YAML; default ASSISTANTX_MATRIX_CONFIG")
    reg.add_argument(
        "-o",
        "--output",
        default="assistantx-registration.yaml",
        help="where to write it ('-' prints it); default %(default)s",
    )
    reg.set_defaults(func=run_registration)


def run_registration(args: argparse.Namespace) -> int:
    # Imported here: every command builds the parser, few need the Matrix adapter.
    from assistantx.adapters.messenger.matrix import (
        load_matrix_config,
        registration,
        write_registration,
    )

    path: Path | None = args.config or Settings().matrix_config
    if path is None:
        print("error: give --config or set ASSISTANTX_MATRIX_CONFIG", file=sys.stderr)
        return 2
    try:
        config = load_matrix_config(path)
        if args.output == "-":
            print(yaml.safe_dump(registration(config), sort_keys=False), end="")
            return 0
        written = write_registration(config, args.output)
    except (MessengerError, OSError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1
    print(
        f"wrote {written}; add it to app_service_config_files in the homeserver's config "
        "and restart the homeserver"
    )
    return 0
