"""A thing at hand sent through a facility: "can this go thru the scanner", "put it through
the scanner please", "pls feed this through the copier", "run it through the laminator". The
facility's service is asked on the requester's own item of the type that service works on
("this"/"it" naming nothing said before: reading/at_hand.py); a verb of handing it over that
is no service here ("feed") is not declined when the thing goes through one of the office's
facilities (screen/passed_through.py); where one machine offers two services, the name said
for it ("copier" of "copy") picks its service (reading/doer_nouns.py). Before: "I'm not sure
what you need" or "I can't feed", and the run failed. A question about a thing that went
through a machine, or walking through a room, stays words."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic.reading.doer_nouns import is_doer_noun
from assistantx.core.office import Office
from helpers.dataset_offices import default_office, harbour_office


def _parse(office: Office, text: str, who: str) -> list[tuple[str, str | None, str | None]]:
    frame = InstructionParser(office).parse(text, who)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "can this go thru the scanner",
        "put it through the scanner please",
        "pls feed this through the scanner",
        "could you send this through the scanner for me",
        "can you scan this",
    ],
)
def test_harbour_scans_the_requesters_own_paper(text: str) -> None:
    assert _parse(harbour_office(), text, "may") == [("copy", "document", "may")]


@pytest.mark.parametrize(
    "text",
    [
        "run it through the laminator",
        "feed this thru the laminator please",
        "put this in the laminator",
    ],
)
def test_harbour_laminates_the_requesters_own_badge(text: str) -> None:
    assert _parse(harbour_office(), text, "bill") == [("heat", "badge", "bill")]


@pytest.mark.parametrize(
    "text",
    [
        "put this through the copier",
        "run it through the photocopier please",
        "pls feed this through the copier",
        "can my document go through the copier",
        "copy this please",
    ],
)
def test_default_office_copies_the_requesters_own_paper(text: str) -> None:
    assert _parse(default_office(), text, "mao") == [("copy", "document", "mao")]


@pytest.mark.parametrize(
    ("office", "text"),
    [
        (harbour_office(), "has my document gone through the scanner yet?"),
        (harbour_office(), "has this gone through the scanner yet?"),
        (harbour_office(), "can you walk through the copy room"),
        (default_office(), "can you walk through the print room"),
    ],
)
def test_a_question_or_a_walk_through_a_room_moves_nothing(office: Office, text: str) -> None:
    frame = InstructionParser(office).parse(text, "may" if office is harbour_office() else "mao")
    assert frame.tasks == [] and frame.decline is not None, frame


@pytest.mark.parametrize(
    ("office", "text", "who"),
    [
        (default_office(), "heat this up", "lee"),  # a lunch? a tea? (a treat takes any)
        (default_office(), "could you sign it?", "lee"),  # nobody named to sign
        (harbour_office(), "run it through the laminator", "may"),  # has no badge of hers
    ],
)
def test_with_no_one_type_or_none_of_the_requesters_it_is_still_asked(
    office: Office, text: str, who: str
) -> None:
    frame = InstructionParser(office).parse(text, who)
    assert frame.tasks == [] and frame.question is not None, frame


def test_a_machine_of_two_services_named_by_neither_is_asked_about() -> None:
    # the printer prints files and copies papers: "this" through "the printer" is either
    frame = InstructionParser(default_office()).parse("put this through the printer", "mao")
    assert frame.tasks == [] and frame.question is not None, frame


def test_a_file_run_through_the_printer_is_still_printed() -> None:
    assert _parse(default_office(), "run my file through the printer", "mao") == [
        ("print", "file", "mao")
    ]


def test_doer_nouns_follow_english_morphology() -> None:
    pairs = [
        ("copier", "copy"),
        ("scanner", "scan"),
        ("laminator", "laminate"),
        ("printer", "print"),
    ]
    assert all(is_doer_noun(n, v) for n, v in pairs)
    assert not is_doer_noun("printer", "copy") and not is_doer_noun("copier", "print")


async def test_a_thing_at_hand_through_the_scanner_is_scanned_and_handed_back() -> None:
    run = await run_instruction(harbour_office(), "may", "can this go thru the scanner")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
