"""``assistantx report``: the usage report from the data directory's journal.

Writes ``usage.json``, ``usage.md`` and ``usage-{outcomes,survey,walking}.png`` into ``--out``
(default: ``report/`` inside the data directory, never the current working tree) and prints
the Markdown summary; with ``--json`` the last line of stdout is the report as one JSON
object. ``--from``/``--to`` take YYYY-MM-DD (``--to`` includes that day), an ISO date-time
(UTC unless a zone is given) or epoch seconds. People are shown by name.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from assistantx.core.errors import JournalError, OfficeError
from assistantx.core.office import load_office
from assistantx.core.settings import Settings
from assistantx.feedback.report import load_report, parse_time, render_markdown, write_report
from assistantx.feedback.store import FeedbackStore

JOURNAL_FILE = "journal.sqlite3"  # the service's journal (assistantx.service.runtime)


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = sub.add_parser("report", help="the usage report: instructions, survey, walking saved")
    p.add_argument("--from", dest="start", default=None, help="start (inclusive)")
    p.add_argument("--to", dest="end", default=None, help="end (exclusive; a date includes it)")
    p.add_argument("--person", default=None, help="only this person's instructions")
    p.add_argument("--data-dir", default=None, help="default: ASSISTANTX_DATA_DIR or ./data")
    p.add_argument(
        "--out",
        default=None,
        help="folder for the JSON, Markdown and charts (default: DATA/report)",
    )
    p.add_argument("--json", action="store_true", help="end with the report as one JSON line")
    p.set_defaults(func=_report)


def _report(args: argparse.Namespace) -> int:
    try:
        start = parse_time(args.start) if args.start else None
        end = parse_time(args.end, end=True) if args.end else None
    except ValueError as exc:
        print(f"error: {exc}")
        return 2
    settings = Settings()
    data_dir = Path(args.data_dir) if args.data_dir else settings.data_dir
    journal = data_dir / JOURNAL_FILE
    if not journal.is_file():
        print(f"error: no journal at {journal} (has 'assistantx serve' run with this data dir?)")
        return 2
    try:
        store = FeedbackStore.open(journal)
    except JournalError as exc:
        print(f"error: {exc}")
        return 2
    try:
        names = {p.id: p.name for p in load_office(settings.office).people}
        report = load_report(store, start, end, time.time(), requester=args.person, names=names)
    except (ValueError, OfficeError) as exc:
        print(f"error: {exc}")
        return 2
    finally:
        store.close()
    paths = write_report(report, Path(args.out) if args.out else data_dir / "report")
    print(render_markdown(report))
    for path in paths:
        print(f"wrote {path}")
    if args.json:
        print(json.dumps(report.model_dump(mode="json")))
    return 0
