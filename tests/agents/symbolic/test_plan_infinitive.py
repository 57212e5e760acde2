"""After a request, "need to <verb> ..." with its "to" said is the speaker's own doing (the
reason), even where the verb's word also names a thing of the office ("book", "file",
"tape") or a service nothing here offers ("book a room"): the word after "to" is a verb
(screen/own_doing.py ``infinitive``). Read as the thing, the reason fetched a book, asked
whose document, or declined the whole request. The office's own errands and services after
"need to" are still asked, and a need for a thing said without "to" is a second request."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office
from helpers.dataset_offices import default_office


@pytest.fixture(scope="module")
def default_parser() -> InstructionParser:
    return InstructionParser(default_office())


def _asked(parser: InstructionParser, text: str, who: str) -> list[tuple[str, str | None]]:
    frame = parser.parse(text, who)
    assert frame.question is None and frame.decline is None, (text, frame)
    return [(t.item, t.owner) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "can u grab Wang's stapler for me? need to book in the delivery",  # fetched a book
        "can u grab Wang's stapler for me? need to book a room",  # declined: "I can't book"
        "could you bring me Wang's stapler? need to file the invoices",  # asked whose document
        "bring me Wang's stapler, need it to staple my report",  # neighbour: one request
    ],
)
def test_the_reason_after_a_request_is_no_task(
    default_parser: InstructionParser, text: str
) -> None:
    assert _asked(default_parser, text, "lee") == [("stapler", "wang")], text


@pytest.mark.parametrize(
    ("text", "items"),
    [
        ("grab me a stapler, and I need a book too", ["stapler", "book"]),  # two requests
        ("could you get me some paper? need to print my report", ["paper", "file"]),
    ],
)
def test_a_second_thing_or_service_is_still_asked(
    default_parser: InstructionParser, text: str, items: list[str]
) -> None:
    assert [item for item, _ in _asked(default_parser, text, "lee")] == items, text


@pytest.mark.parametrize(
    ("text", "items"),
    [
        ("could you bring me a ruler? need to tape up the boxes", ["ruler"]),  # fetched tape
        ("could you bring me a ruler? need to file the invoices", ["ruler"]),  # did nothing
        ("bring me a ruler, and I need some tape too", ["ruler", "tape"]),
    ],
)
def test_in_harbour(harbour: Office, text: str, items: list[str]) -> None:
    assert [item for item, _ in _asked(InstructionParser(harbour), text, "may")] == items
