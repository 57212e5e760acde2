"""A view of what a thing needs, hedged by the speaker ("I think", "I reckon", "imo", "to be
frank") and asking nothing, is told and answered in words (reading/screen/opinion.py): never
a thing fetched, nor one declined as missing. "to be frank i think the book needs a full
support, not just stitching" was declined as "there is no full support in this office" in a
bindery where Frank is a colleague; "to be frank" is the adjective there. A request anywhere
in the message, a person's need, the speaker's own need and an unhedged need are read as
before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.office_builder import facility, item, office_file, operation, parsed, person, room
from helpers.reading import frame_reader

_NOTED = "Noted. I did nothing."


def _bindery_raw() -> dict[str, object]:
    return office_file(
        "Bindery",
        [
            person("lee", "Lee Ming", "book"),
            person("frank", "Frank Hale", "book", "stapler"),
            person("ana", "Ana Ruiz", "stapler"),
        ],
        rooms=[room("sewing", "Sewing room", 20.0, 10.0), room("dock", "Dock", 1.0, 1.0)],
        item_types=[item("book", "book"), item("stapler", "stapler"), item("thread", "thread")],
        operations=[operation("stitch", "stitch", name="stitching", input="book")],
        facilities=[
            facility(
                "bench",
                "sewing bench",
                at="sewing",
                guards=["ana"],
                operations=["stitch"],
                supplies=["thread"],
            )
        ],
        home="dock",
    )


_bindery = frame_reader(parsed(_bindery_raw), "lee")
_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")


@pytest.mark.parametrize(
    "text",
    [
        "to be frank i think the book needs a full support, not just stitching",
        "To be frank, I think the book needs a full support, not just stitching",
        "honestly i reckon the book needs a new spine tbh",
        "imo the sewing room could do with a bigger table",
    ],
)
def test_a_view_of_a_thing_s_need_in_the_bindery_is_told(text: str) -> None:
    frame = _bindery(text)
    assert frame.tasks == [] and frame.question is None and frame.decline == _NOTED, frame


@pytest.mark.parametrize(
    "text",
    [
        "honestly i reckon the quarterly report needs a full rewrite, not just a proofread",
        "I think the printer needs a new drum tbh",
        "imo the meeting room could do with a bigger table",
        "to be fair I feel the contract needs another look before Friday",
        "in my view, the kitchen could use a new kettle",
        "the stapler needs a proper overhaul, tbh",
    ],
)
def test_a_view_of_a_thing_s_need_in_the_default_office_is_told(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question is None and frame.decline == _NOTED, frame


def test_a_view_of_a_thing_s_need_in_harbour_is_told() -> None:
    frame = _harbour("personally I think the charger could do with a longer cable")
    assert frame.tasks == [] and frame.question is None and frame.decline == _NOTED, frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # a request beside the view: read as before
        ("I think I need a stapler, can you bring me one", [("transfer", "stapler", None, "lee")]),
        (
            "i reckon the printer needs paper, can you top it up",
            [("transfer", "paper", None, "lee")],
        ),
        (
            "I think Zhang needs my stapler, take it to him",
            [("transfer", "stapler", "lee", "zhang")],
        ),
        # unhedged, and the office's own work: read as before
        ("the report needs printing", [("print", "file", "lee", "lee")]),
        ("I think the report needs printing", [("print", "file", "lee", "lee")]),
    ],
)
def test_what_asks_is_read_as_before(
    text: str, tasks: list[tuple[str, str, str | None, str]]
) -> None:
    frame = _default(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == tasks, frame


def test_a_colleague_s_need_is_read_as_before() -> None:
    asked = _bindery("Frank needs a stapler")
    assert asked.tasks == [] and asked.question == "Shall I bring a stapler to Frank Hale?", asked
    hedged = _bindery("i think frank needs a stapler")
    assert [(t.kind, t.item, t.recipient) for t in hedged.tasks] == [
        ("transfer", "stapler", "frank")
    ], hedged
