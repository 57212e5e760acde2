"""Round 175's classes of the reader (analogues of outside testers' sentences, none of them):
a colleague's content asked for with its form said in the next sentence; a service's -ing form
as a modifier of a noun; a room, facility or team said as who does a service; a problem said,
then a remedy asked for. Each with neighbours whose reading must stay."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, parse_office
from assistantx.core.task_schema import TaskFrame
from helpers.costume_shop import costume_shop, raw_costume_shop
from helpers.dataset_offices import default_office

Row = tuple[str, str | None, str | None, str | None]


@functools.cache
def _parser(name: str) -> InstructionParser:
    offices = {"default": default_office, "costume": costume_shop, "brushes": _with_brush}
    return InstructionParser(offices[name]())


@functools.cache
def _with_brush() -> Office:
    """The costume shop with a clothes brush declared for taking hair off too."""
    raw = raw_costume_shop()
    raw["item_types"].append(
        {"id": "clothes_brush", "name": "clothes brush", "purposes": ["remove hair"]}
    )
    raw["facilities"][0]["supplies"].append({"type": "clothes_brush"})
    return parse_office(raw, "costume shop with a brush")


def _parse(office: str, text: str) -> TaskFrame:
    return _parser(office).parse(text, "lee")


def _tasks(frame: TaskFrame) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


# -- class 1: "<content> from <colleague>? She keeps them in a spreadsheet" ------------------
@pytest.mark.parametrize(
    ("office", "text", "owner"),
    [
        (
            "default",
            "Can you get me this week's rota numbers from Wang? She keeps them in a spreadsheet.",
            "wang",
        ),
        ("costume", "could I have the quarterly figures from Tomás? They're in a pdf.", "tomas"),
        # a word of the content names a product of the office: still the colleague's file
        (
            "costume",
            "Can you get me the quarterly cake numbers from Wang? She keeps them in a spreadsheet.",
            "wang",
        ),
    ],
)
def test_content_whose_form_is_said_next_is_the_colleagues_file(
    office: str, text: str, owner: str
) -> None:
    assert _tasks(_parse(office, text)) == [("send_file", "file", owner, "lee")]


def test_content_kept_in_no_file_is_still_asked_about() -> None:
    frame = _parse(
        "costume", "Can you get me the rota numbers from Wang? She keeps them in a drawer."
    )
    assert not frame.tasks and frame.question is not None


def test_the_file_already_said_is_read_as_before() -> None:
    frame = _parse("default", "Can you get me the rota spreadsheet from Wang?")
    assert _tasks(frame) == [("send_file", "file", "wang", "lee")]


# -- class 2: "Tomás's shipping spreadsheet", "his printing budget" --------------------------
@pytest.mark.parametrize(
    ("office", "text", "owner"),
    [
        ("costume", "can you get Tomás's shipping spreadsheet for me", "tomas"),
        ("costume", "get Tomás to send me his printing budget", "tomas"),
        ("default", "get Wang to send me his printing budget", "wang"),
        ("default", "get Wang to send me her copying log", "wang"),
    ],
)
def test_a_services_ing_form_before_a_noun_only_describes_it(
    office: str, text: str, owner: str
) -> None:
    frame = _parse(office, text)
    assert frame.decline is None
    assert _tasks(frame) == [("send_file", "file", owner, "lee")]


def test_the_service_asked_of_a_described_file_is_still_run() -> None:
    frame = _parse("costume", "can you print Tomás's shipping spreadsheet for me")
    assert _tasks(frame) == [("print", "file", "tomas", "lee")]


def test_an_ing_form_with_no_noun_after_it_is_read_as_before() -> None:
    frame = _parse("costume", "my printing is urgent, print my spreadsheet")
    assert _tasks(frame) == [("print", "file", "lee", "lee")]


# -- class 3: "can laundry stitch it up?" --------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "tore the hem on my apron during service, can laundry stitch it up?",
        "can laundry stitch up my apron?",
        "can the laundry mend my whites?",  # the apron by the office's synonym
        "could the sewing bench mend my apron?",
    ],
)
def test_a_place_said_to_do_a_service_is_the_service_there(text: str) -> None:
    frame = _parse("costume", text)
    assert frame.decline is None
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("apron", "lee", "lee")]
    assert frame.tasks[0].actor is None


def test_a_colleague_said_to_do_it_is_still_asked() -> None:
    frame = _parse("costume", "can Nia stitch my apron?")
    assert [(t.item, t.actor) for t in frame.tasks] == [("apron", "nia")]


def test_a_place_said_to_do_a_service_the_office_lacks_is_no_service() -> None:
    frame = _parse("costume", "can laundry dye my apron?")
    assert not frame.tasks


# -- class 4: a problem, then "got anything to sort it out?" ---------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "my coat is covered in dog hair and I'm on in ten, got anything to sort it out?",
        "my coat is covered in lint. do you have anything to deal with it?",
    ],
)
def test_the_one_thing_declared_for_the_problem_is_offered(text: str) -> None:
    frame = _parse("costume", text)
    assert frame.question is not None and "lint roller" in frame.question
    assert "Shall I bring you" in frame.question


def test_several_things_that_fit_are_asked_about() -> None:
    text = "my coat is covered in dog hair, got anything to sort it out?"
    frame = _parse("brushes", text)
    assert not frame.tasks and frame.question is not None
    assert "lint roller" in frame.question and "clothes brush" in frame.question


def test_nothing_that_fits_is_asked_not_declined() -> None:
    frame = _parse("costume", "my coat is soaking wet, got anything to sort it out?")
    assert not frame.tasks and frame.decline is None and frame.question is not None


def test_a_remedy_asked_with_no_problem_said_is_read_as_before() -> None:
    frame = _parse("costume", "got anything to sort it out?")
    assert not frame.tasks and frame.question is None
