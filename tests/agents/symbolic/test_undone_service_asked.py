"""A machine's work said not done yet, then asked for with no machine named: "my badge hasn't
been laminated yet, can you get it done", "my form still isnt stamped, can you sort that".
The participle names the one operation whose verb or done word it is; "get it done" / "sort
it (out)" asks for it on the thing the first clause named (the speaker's own where they own
one), handed back to the speaker (round 59, class 1 of fixer fix59e). The first clause alone
stays a statement, "get it done" with nothing before it asks, two operations whose
participles match ask which, and carrying reads as before."""

from __future__ import annotations

from typing import Any

import pytest

from helpers import office_builder as ob
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader
from helpers.spectro_lab import spectro_lab


def _raw_stamp_room() -> dict[str, Any]:
    return ob.office_file(
        "stamp room",
        (
            ob.person("lee", "Lee Park", "banner", aliases=["Lee"]),
            ob.person("ana", "Ana Ruiz", aliases=["Ana"]),
        ),
        rooms=[
            ob.room("print_room", "Print room", 4.0, 20.0),
            ob.room("kitchen", "Kitchen", 20.0, 20.0),
        ],
        item_types=[
            ob.item("form", "form", "personal", synonyms=["document"]),
            ob.item("banner", "banner"),
        ],
        operations=[
            ob.operation("stamp", "stamp", name="date stamp", input="form"),
            # two operations whose participles match: "sealed" names either
            ob.operation("seal", "seal", name="seal", input="form"),
            ob.operation("laminate", "laminate", "seal", name="laminate", input="banner"),
        ],
        facilities=[
            ob.facility(
                "stamper",
                "date stamper",
                at="print_room",
                guards=["ana"],
                operations=["stamp", "seal"],
            ),
            ob.facility(
                "laminator", "laminator", at="print_room", guards=["ana"], operations=["laminate"]
            ),
        ],
        everyone_owns=["form"],
        home="kitchen",
    )


_stamp_room = frame_reader(ob.parsed(_raw_stamp_room), "lee")
_bill = frame_reader(harbour_office, "bill")
_lab = frame_reader(spectro_lab, "lee")


@pytest.mark.parametrize(
    ("read", "text", "item", "operation", "owner"),
    [
        (_bill, "my badge hasn't been laminated yet, can you get it done", "badge", None, "bill"),
        (_bill, "my badge still isnt laminated, can you sort that", "badge", None, "bill"),
        (_bill, "my badge hasnt been laminated, sort it out please", "badge", None, "bill"),
        (_lab, "the banner hasnt been laminated, get it done pls", "banner", "laminate", "lee"),
        (
            _lab,
            "my sample hasnt been spun down yet, could you get that done",
            "sample",
            "spin",
            "lee",
        ),
        (_stamp_room, "my form still isnt stamped, can you sort that", "form", "stamp", "lee"),
    ],
)
def test_the_participle_names_the_work_asked_by_get_it_done(
    read: Any, text: str, item: str, operation: str | None, owner: str
) -> None:
    frame = read(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.operation, t.owner, t.recipient) for t in frame.tasks] == [
        (item, operation, owner, owner)
    ], frame


def test_the_first_clause_alone_is_a_statement() -> None:
    frame = _bill("my badge hasn't been laminated yet")
    assert not frame.tasks and frame.question is None, frame


def test_get_it_done_with_nothing_before_it_asks() -> None:
    frame = _bill("can you get it done")
    assert not frame.tasks and frame.question is not None, frame


def test_two_operations_whose_participles_match_ask_which() -> None:
    frame = _stamp_room("my form hasnt been sealed yet, can you get it done")
    assert not frame.tasks and frame.question is not None, frame
    assert "laminate" in frame.question and "seal" in frame.question, frame


def test_carrying_reads_as_before() -> None:
    frame = _bill("my badge hasn't been laminated yet, can you take it to the laminator")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("heat", "badge", "bill", "bill")
    ], frame
