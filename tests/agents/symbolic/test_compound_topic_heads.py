"""A noun used as a modifier of another noun does not name that thing: the head does (issue
#23). In "the coffee rota", "the laminator budget one", "the book list" the last noun is the
head; an item's or a facility's name before it only says which paper or file is meant, and a
paper's or file's everyday noun heads the phrase even where the dictionary lacks it ("rota") or
knows only its verb ("log"). The pro-form "one" after such a name stands for the thing named
before ("Lee's spreadsheet? the coffee one"). A paper named by its topic after "the" is the
requester's, of the type the work asked takes ("copy the book list": the office's paper).
On the default office and harbour; no coffee is made and nothing laminated for a file."""

from __future__ import annotations

import functools
from collections.abc import Sequence
from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.core.office import Office, parse_office
from assistantx.core.task_schema import Task
from helpers.dataset_offices import DEFAULT_FILE, default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader
from helpers.yaml_files import raw_yaml

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "may")

Row = tuple[str, str | None, str | None, str]


def _rows(tasks: Sequence[Task]) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in tasks]


@pytest.mark.parametrize(
    "text",
    [
        "can I have Lee's spreadsheet? the coffee rota one",
        "send me Lee's spreadsheet, the coffee rota one please",
        "can I have Lee's spreadsheet? the coffee one",
        "send me Lee's file, the printer one",
        "could I get Lee's file - the water budget one",
    ],
)
def test_a_topic_pick_after_a_named_file_is_that_file(text: str) -> None:
    """The item or facility before "one" describes the file: only the file is passed."""
    assert _rows(_default(text).tasks) == [("send_file", "file", "lee", "lin")]


@pytest.mark.parametrize(
    "text",
    [
        "can I have Mark's deck? the tea rota one",
        "can I have Mark's spreadsheet? the scanner schedule one",
        "can you get me Mark's spreadsheet - the printer log one",
    ],
)
def test_a_topic_pick_in_harbour_is_marks_file(text: str) -> None:
    assert _rows(_harbour(text).tasks) == [("send_file", "file", "mark", "may")]


def test_a_facility_before_a_papers_noun_names_no_work() -> None:
    """ "the laminator budget one": a budget, no laminating (main declined "I can't laminate
    an electronic file")."""
    frame = _harbour("could you send me Rose's file, the laminator budget one")
    assert frame.decline is None
    assert _rows(frame.tasks) == [("send_file", "file", "rose", "may")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("copy the book list and give the copy to Wang", [("copy", "document", "lin", "wang")]),
        ("copy the coffee rota", [("copy", "document", "lin", "lin")]),
        ("print the coffee rota for Wang", [("print", "file", "lin", "wang")]),
    ],
)
def test_a_paper_named_by_its_topic_is_the_requesters(text: str, expected: list[Row]) -> None:
    assert _rows(_default(text).tasks) == expected


def test_a_paper_named_by_its_topic_in_harbour() -> None:
    frame = _harbour("scan the umbrella list and send the scan to Mark")
    assert _rows(frame.tasks) == [("copy", "document", "may", "mark")]


@pytest.mark.parametrize(
    ("reader", "text"),
    [(_default, "send me the coffee rota"), (_harbour, "send me the tea rota")],
)
def test_a_topic_compound_with_no_such_thing_makes_no_drink(reader: ReadFrame, text: str) -> None:
    """ "the coffee rota" with a verb that takes no paper: a rota the office lacks, asked;
    main made a coffee."""
    frame = reader(text)
    assert frame.tasks == []
    assert frame.question is not None or frame.decline is not None


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("print the book list", [("print", "file", "lin", "lin")]),
        ("bring me a coffee cup", [("transfer", "cup", None, "lin")]),
        ("bring me a coffee", [("produce", "coffee", None, "lin")]),
        ("bring me a coffee, the large one", [("produce", "coffee", None, "lin")]),
        ("I want the coffee one more time", [("produce", "coffee", None, "lin")]),
        ("can I have a cup? the coffee one", [("transfer", "cup", None, "lin")]),
        (
            "bring me a coffee and Wang's book",
            [("produce", "coffee", None, "lin"), ("transfer", "book", "wang", "lin")],
        ),
    ],
)
def test_must_not_change_on_the_default_office(text: str, expected: list[Row]) -> None:
    """Neighbours: the head still names the thing; two things joined by "and" stay two."""
    assert _rows(_default(text).tasks) == expected


def test_an_unknown_topic_stays_unknown() -> None:
    """ "the fire drill plan" names nothing of the office's: no paper is guessed."""
    frame = _default("copy the fire drill plan and give the copy to Wang")
    assert frame.tasks == []
    assert frame.question is not None


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("take my badge to the laminator", [("heat", "badge", "may", "may")]),
        ("print the umbrella list", [("print", "file", "may", "may")]),
    ],
)
def test_must_not_change_in_harbour(text: str, expected: list[Row]) -> None:
    assert _rows(_harbour(text).tasks) == expected


def test_work_that_takes_no_paper_guesses_none() -> None:
    """ "laminate the tea rota": laminating takes badges; a rota is none, so which is asked."""
    frame = _harbour("laminate the tea rota")
    assert frame.tasks == []
    assert frame.question is not None


async def test_no_coffee_is_made_for_the_coffee_rota_spreadsheet() -> None:
    run = await run_instruction(
        default_office(), "lin", "can I have Lee's spreadsheet? the coffee rota one"
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert "forward_file" in run.actions, run.actions
    assert not {"send_qr", "move"} & set(run.actions), run.actions


@pytest.mark.parametrize(
    "text",
    [
        "can I get Rose's deck? the kettle tea rota one",
        "can I get Rose's deck? the umbrella stand one",
    ],
)
def test_every_noun_before_one_describes_it(text: str) -> None:
    """Several nouns between "the" and "one" (a facility's, a product's, one the office lacks)
    all say which of Rose's files: nothing boiled, no tea, no umbrella."""
    assert _rows(_harbour(text).tasks) == [("send_file", "file", "rose", "may")]


@functools.cache
def _lab() -> Office:
    """The default office as a lab's would be: samples, the paper also called a "log", and
    the cup also called a "coffee cup"."""
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE)
    for t in raw["item_types"]:
        if t["id"] == "document":
            t["synonyms"] = [*t.get("synonyms", []), "log"]
        if t["id"] == "cup":
            t["synonyms"] = [*t.get("synonyms", []), "coffee cup"]
    raw["item_types"].append({"id": "sample", "name": "sample", "synonyms": ["specimen"]})
    return parse_office(raw, "default with samples")


_lab_frame = frame_reader(_lab, "lin")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # "one" after Lee's file: the sample log describes it (main asked "whose document?")
        ("can I have Lee's file? the sample log one", [("send_file", "file", "lee", "lin")]),
        ("can I have Wang's sample log", [("transfer", "document", "wang", "lin")]),
        ("copy the sample log for Wang", [("copy", "document", "lin", "wang")]),
        # must not change: the office's longer name wins; the sample said alone is one
        ("bring me a coffee cup", [("transfer", "cup", None, "lin")]),
        ("bring me Wang's sample", [("transfer", "sample", "wang", "lin")]),
    ],
)
def test_a_sample_log_is_a_paper(text: str, expected: list[Row]) -> None:
    assert _rows(_lab_frame(text).tasks) == expected
