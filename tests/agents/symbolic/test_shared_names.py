"""A name one person goes by that is another person's name word too ("Yang": Yang Lei, and
Liu Yang's given name) means either, until the words around it say which: the item it is
said to own, when only one of them owns one and is called so (their first name, or a name the
office declares), else one question naming both (issue 23). The one who only has the word as
a later name ("Ada Hal", "Liu Yang") is never taken for it without asking (blind rounds
20-22: "cliff's running order" is Cliff Adebayo's, or asked, never Marcus Cliff's)."""

from __future__ import annotations

import functools

import pytest
from _offices import parser as office_parser

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.clinic import raw_clinic


@functools.cache
def clinic_with_a_second_hal() -> InstructionParser:
    """The clinic, with Ada Hal: her family name is Hal Brooks's given name."""
    raw = raw_clinic()
    raw["people"].append(
        {
            "id": "ada",
            "name": "Ada Hal",
            "location": "desk_7",
            "handle": "@ada",
            "owns": [{"type": "clipboard"}, {"type": "document"}],
        }
    )
    return InstructionParser(parse_office(raw, "clinic with a second Hal"))


def _tasks(p: InstructionParser, text: str, who: str) -> list[tuple[str, str | None, str]]:
    return [(t.kind, t.owner, t.recipient) for t in p.parse(text, who).tasks]


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("bring me Hal's thermometer", "hal"),  # only Hal Brooks has one
        ("bring me hal's thermometer", "hal"),
    ],
)
def test_the_item_only_one_of_them_owns_says_whom(text: str, owner: str) -> None:
    assert _tasks(clinic_with_a_second_hal(), text, "dawn") == [("transfer", owner, "dawn")]


@pytest.mark.parametrize(
    "text",
    [
        "bring me Hal's clipboard",  # only Ada Hal has one, but she is called Ada
        "could you bring me hal's clipboard",
    ],
)
def test_the_family_name_alone_is_asked_about_even_when_the_item_says(text: str) -> None:
    p = clinic_with_a_second_hal()
    frame = p.parse(text, "dawn")
    assert frame.tasks == [] and frame.question is not None
    assert "Hal Brooks" in frame.question and "Ada Hal" in frame.question
    settled = p.parse_with_answers(text, "dawn", ["Ada Hal"])
    assert [(t.kind, t.owner, t.recipient) for t in settled.tasks] == [("transfer", "ada", "dawn")]


@pytest.mark.parametrize(
    "text",
    ["take my form to Hal", "bring me Hal's form"],  # both have a form
)
def test_otherwise_one_question_names_both_and_the_answer_settles_it(text: str) -> None:
    p = clinic_with_a_second_hal()
    frame = p.parse(text, "dawn")
    assert frame.tasks == [] and frame.question is not None
    assert "Hal Brooks" in frame.question and "Ada Hal" in frame.question
    settled = p.parse_with_answers(text, "dawn", ["Ada Hal"])
    assert "ada" in {settled.tasks[0].owner, settled.tasks[0].recipient}


def test_on_the_default_office_yang_is_asked_unless_the_item_says() -> None:
    p = office_parser("default")
    assert [t.owner for t in p.parse("bring me Yang's book", "lee").tasks] == ["yang"]
    # only Liu Yang has a cup, but "Yang" is how Yang Lei is called: asked, never taken
    cup = p.parse("bring me Yang's cup", "lee")
    assert cup.tasks == [] and cup.question is not None and "Liu Yang" in cup.question
    question = p.parse("take this stapler to Yang", "lee").question
    assert question is not None and "Liu Yang" in question and "Yang Lei" in question


def test_a_statement_about_the_family_name_settles_no_owner() -> None:
    """ "Hal said I could borrow her clipboard": Hal stays unsettled (Ada Hal is called Ada),
    so the clipboard is anyone's, its owner asked as for any other; never Ada's unasked."""
    frame = clinic_with_a_second_hal().parse(
        "Hal said I could borrow her clipboard, can you get it for me", "dawn"
    )
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("transfer", None, "dawn")]
