"""A service runs only on the item types it takes (class 72j-2): harbour's scan takes
documents, so "I need my badge scanned and laminated" is declined with the reason ("I can
only scan documents") and never plans a scan of the badge. Read from the office's own
operations (their inputs), whatever the operation's shape; the property test says every
operation with an input of both dataset offices, asked by each of its verbs on each thing a
colleague owns, is never planned on a thing it does not take."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame, kind_shape
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_harbour = frame_reader(harbour_office, "bill")
_default = frame_reader(default_office, "zhang")


def _wrong_runs(office: Office, frame: TaskFrame) -> list[str]:
    """The tasks of ``frame`` whose service (named, else the one of its shape) does not take
    their item."""
    wrong = []
    for t in frame.tasks:
        shape = kind_shape(t.kind)
        if shape is None or t.item is None:
            continue
        ops = [o for o in office.with_shape(shape) if o.input is not None]
        named = [o for o in ops if o.id == t.operation] if t.operation else ops
        if named and not any(o.input == t.item for o in named):
            wrong.append(f"{t.kind} {t.item}")
    return wrong


@pytest.mark.parametrize(
    "text",
    [
        "I need my badge scanned and laminated",
        "could you digitise my badge",
        "please scan my badge for me",
        "scan my badge and then bring me a ruler",
    ],
)
def test_a_service_asked_on_a_thing_it_does_not_take_is_declined(text: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "scan a badge" in frame.decline and "only scan documents" in frame.decline


@pytest.mark.parametrize("text", ["photocopy my lunch please", "could you xerox my lunch"])
def test_on_the_default_office_too(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "copy a lunch" in frame.decline and "only copy documents" in frame.decline


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("laminate my badge", [("heat", "badge")]),
        ("scan my document", [("copy", "document")]),
        (
            "I need my document scanned and my badge laminated",
            [("copy", "document"), ("heat", "badge")],
        ),
    ],
)
def test_a_service_on_what_it_takes_is_read_as_before(
    text: str, kinds: list[tuple[str, str]]
) -> None:
    frame = _harbour(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == kinds


@pytest.mark.parametrize("office", [default_office, harbour_office], ids=["default", "harbour"])
def test_no_operation_is_planned_on_a_thing_it_does_not_take(office: object) -> None:
    here: Office = office()  # type: ignore[operator]
    read = frame_reader(office, here.people[0].id)  # type: ignore[arg-type]
    wrong: list[str] = []
    for op in here.operations:
        if op.input is None or op.sends_out or not here.runnable(op.id):
            continue
        for person in here.people:
            for own in person.owns:
                if own.type == op.input:
                    continue
                name = here.item_type(own.type).name
                for verb in op.verbs:
                    if " " in verb:
                        continue
                    text = f"please {verb} my {name}"
                    frame = read(text, person.id)
                    wrong += [f"{person.id}: {text!r} → {w}" for w in _wrong_runs(here, frame)]
    assert wrong == []
