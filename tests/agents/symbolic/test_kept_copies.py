"""A copy of a thing the office keeps for anyone is one of those things (fix62b class 3: "could
I get a copy of thursdays catalogue" was declined, "nothing here makes copies", where the
front counter keeps forty catalogues): ``reading/kept_copies``. One, or that many, is fetched
with a copier in the office or without one; a paper of someone's ("a copy of my contract",
"a copy of Wang's document") and "copy my contract for Wang" are read as before."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from assistantx.agents.symbolic.reading.kept_copies import kept_copies
from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.reading import ReadFrame, frame_reader


def _staffroom(copier: bool) -> ob.Row:
    facilities = [
        ob.facility(
            "cupboard",
            "stationery cupboard",
            at="store",
            guards=["max"],
            supplies=[{"type": "handbook", "count": 10}, {"type": "timetable", "count": 10}],
        )
    ]
    items = [
        ob.item("handbook", "staff handbook", synonyms=["handbook"]),
        ob.item("timetable", "timetable"),
        ob.item("document", "document", "personal", signable=True, synonyms=["contract"]),
    ]
    operations: list[ob.Row] = []
    if copier:
        facilities.append(ob.facility("copier", "photocopier", at="store", guards=["max"]))
        facilities[-1]["operations"] = ["copy"]
        items.append(ob.item("copy", "photocopy", "product", synonyms=["copy", "copies"]))
        operations.append(
            ob.operation("copy", "copy", "photocopy", input="document", product="copy")
        )
    return ob.office_file(
        "Staff room",
        [
            ob.person("lee", "Lee Hart", "document", aliases=["Lee"]),
            ob.person("wang", "Wang Li", "document", aliases=["Wang"]),
            ob.person("max", "Max Doyle", aliases=["Max"]),
        ],
        rooms=[ob.room("store", "Store room", 20.0, 6.0)],
        item_types=items,
        operations=operations,
        facilities=facilities,
        home="store",
    )


_with_copier: Callable[[], Office] = ob.parsed(lambda: _staffroom(True))
_without_copier: Callable[[], Office] = ob.parsed(lambda: _staffroom(False))
_copying = frame_reader(_with_copier, "lee")
_plain = frame_reader(_without_copier, "lee")


@pytest.mark.parametrize("read", [_copying, _plain])
@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("can I grab a copy of the staff handbook", "handbook"),
        ("2 copies of the timetable pls", "timetable"),
        ("could I get a copy of today's handbook", "handbook"),
        ("could I get a copy of thursdays timetable", "timetable"),
        ("can u get me two copies of this week's timetable", "timetable"),
    ],
)
def test_a_copy_of_a_kept_thing_is_one_of_them(read: ReadFrame, text: str, item: str) -> None:
    frame = read(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, None, "lee")
    ], frame


def test_a_copy_of_the_speakers_paper_is_still_a_copy_job() -> None:
    frame = _copying("a copy of my contract")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("copy", "document", "lee")]


def test_a_copy_of_a_colleagues_paper_is_still_a_copy_job() -> None:
    frame = _copying("a copy of Wang's document")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("copy", "document", "wang")]


def test_copying_a_paper_for_someone_is_still_a_copy_job() -> None:
    frame = _copying("copy my contract for Wang")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("copy", "wang")], frame


def test_copying_without_a_copier_is_still_declined() -> None:
    frame = _plain("copy my contract for Wang")
    assert frame.tasks == [] and frame.decline is not None and "copy" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("a copy of the staff handbook pls", "a staff handbook pls"),
        ("2 copies of thursday's timetable", "2 timetables"),
        ("another copy of the timetable, thanks", "another timetable, thanks"),
    ],
)
def test_the_copy_is_said_as_the_thing(text: str, said: str) -> None:
    names = {"staff handbook": 2, "timetable": 1}
    kept = lambda p: next((n for k, n in names.items() if p.startswith(k)), 0)  # noqa: E731
    assert kept_copies(text, kept) == said


@pytest.mark.parametrize(
    "text",
    ["a copy of my contract", "a copy of Wang's timetable", "make a copy of the document"],
)
def test_a_copy_of_what_is_kept_for_nobody_stays(text: str) -> None:
    assert kept_copies(text, lambda p: 1 if p.startswith("timetable") else 0) == text
