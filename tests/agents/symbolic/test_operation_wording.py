"""Lock codes and plans are worded with the office's own operation (issue 16).

The lock's purposes "copy" and "heat" are the shapes of operation (a product made from the
item; the item worked on and given back), not what the office calls them: in the harbour
office they are a scan and a lamination, and the person must read "scan", "laminate".
"""

from __future__ import annotations

from pathlib import Path

from assistantx.agents.symbolic.planning import describe
from assistantx.core.office import load_office
from assistantx.core.task_schema import Task
from assistantx.core.wording import purpose_text

ROOT = Path(__file__).resolve().parents[3] / "dataset"
HARBOUR = load_office(ROOT / "offices" / "harbour" / "office.yaml")
DEFAULT = load_office(ROOT / "office.yaml")


def _someone_with(office_items: str) -> str:
    return next(p.id for p in HARBOUR.people if any(o.type == office_items for o in p.owns))


def test_a_scan_code_says_scan_not_copy() -> None:
    who = _someone_with("document")
    text = purpose_text(HARBOUR, "copy", f"document:{who}", you=who)
    assert text == "take your document out, scan it and put the original and the scan back"


def test_a_lamination_code_says_laminate_not_heat() -> None:
    who = _someone_with("badge")
    text = purpose_text(HARBOUR, "heat", f"badge:{who}", you=who)
    assert text == "take your badge out, laminate it and put it back"


def test_the_default_office_keeps_its_words() -> None:
    who = next(p.id for p in DEFAULT.people if any(o.type == "document" for o in p.owns))
    text = purpose_text(DEFAULT, "copy", f"document:{who}", you=who)
    assert text == "take your document out, copy it and put the original and the copy back"
    assert purpose_text(DEFAULT, "deposit", f"document:{who}", you=who) == (
        "put your document into the locker"
    )


def test_a_plan_line_names_the_office_operation() -> None:
    who = _someone_with("badge")
    task = Task(kind="heat", item="badge", owner=who, recipient=who, operation="laminate")
    assert describe(task, HARBOUR, you=who) == "laminate your badge for you"
    scan = Task(kind="copy", item="document", owner=who, recipient=who)
    assert describe(scan, HARBOUR, you=who).startswith("scan your document")
