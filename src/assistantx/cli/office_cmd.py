"""``assistantx office show``: the office, and what the assistant knows of it at start;
``assistantx office migrate FILE``: an office file of the previous format, rewritten."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from assistantx.core.errors import OfficeError
from assistantx.core.office import Office, load_office
from assistantx.core.office_upgrade import migrate_file
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.render import render_long_term


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    office = sub.add_parser("office", help="inspect the office")
    office_sub = office.add_subparsers(dest="office_command", required=True, metavar="ACTION")
    show = office_sub.add_parser("show", help="print the office and what the assistant knows")
    show.add_argument("--office", default=None, help="office YAML (default: the default office)")
    show.add_argument("--json", action="store_true", help="print the office as JSON")
    show.set_defaults(func=_show)
    migrate = office_sub.add_parser(
        "migrate", help="rewrite an office file of the previous format in the current one"
    )
    migrate.add_argument("file", type=Path, help="the office YAML to update (in place)")
    migrate.add_argument("--out", type=Path, default=None, help="write here instead")
    migrate.set_defaults(func=_migrate)


def _migrate(args: argparse.Namespace) -> int:
    """Fill in what the previous format left out, say what changed, and check the result."""
    try:
        notes = migrate_file(args.file, args.out)
        load_office(args.out or args.file)
    except OfficeError as exc:
        print(f"error: {exc}")
        return 2
    except OSError as exc:
        print(f"error: {args.file}: {exc.strerror or exc}")
        return 2
    for note in notes:
        print(f"  {note}")
    where = args.out or args.file
    print(f"{where}: {'updated' if notes else 'already in the current format'}")
    return 0


def _show(args: argparse.Namespace) -> int:
    try:
        office = load_office(args.office)
    except OfficeError as exc:
        print(f"error: {exc}")
        return 2
    if args.json:
        print(json.dumps(office.model_dump(mode="json"), indent=2))
        return 0
    print(describe(office))
    return 0


def describe(office: Office) -> str:
    ws, public = office.workstations(), office.public_places()
    lines = [
        office.name,
        f"{len(office.locations)} locations: {len(ws)} workstations, {len(public)} facilities",
        "",
        "Workstations: " + ", ".join(f"{w.id} ({w.name})" for w in ws),
        "Facilities and rooms: " + ", ".join(f"{p.id} ({p.name})" for p in public),
        "",
        f"{len(office.people)} people (owned items; * = unknown to the assistant at start):",
    ]
    for p in office.people:
        owns = ", ".join(o.type + ("" if o.known else "*") for o in p.owns)
        aliases = f" aka {', '.join(p.aliases)}" if p.aliases else ""
        lines.append(f"  {p.id:8} {p.name}{aliases} @ {p.location}: {owns}")
    kept = [f for f in office.facilities if f.supplies]
    if kept:
        lines += ["", "Supplies owned by nobody (count, if the office gives one):"]
        for f in kept:
            stock = ", ".join(
                s.type + ("" if s.count is None else f" ({s.count})") for s in f.supplies
            )
            lines.append(f"  {f.name} @ {f.location}: {stock}")
    lines += ["", "What the assistant knows at start:", render_long_term(LongTermMemory(office))]
    return "\n".join(lines)
