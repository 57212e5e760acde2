"""A shared name said as an owner, then set off by a dash or comma with the full name of the one
meant and the other refused: "could you bring me Yang's book — Yang Lei, not Liu" (Yang is Yang
Lei's family name and Liu Yang's given name). The appositive names the owner: the shared word
said again beside one namesake's own word is that one's full name, the possessive "Yang's" is
the name said, and a "not" refuses the whole name after it ("not Yang Lei")
(``reading.namesake_surnames``). Before, the book was taken as Yang Lei's and the appositive
as a receiver ("Yang Lei already has their book; who should get it?")."""

from __future__ import annotations

import functools

import pytest
from _offices import parser as office_parser

from assistantx.agents.symbolic import InstructionParser
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.renamed_offices import renamed


@functools.cache
def _rosas(where: str) -> InstructionParser:
    # two colleagues called Rosa (Harbour keeps its Mark Lindqvist)
    if where == "default":
        rosas = (("sun", "Rosa Álvarez", ("Rosa",)), ("lee", "Rosa Lindqvist", ("Rosa",)))
        return InstructionParser(renamed(DEFAULT_FILE, rosas, "default with two Rosas"))
    rosas = (("rose", "Rosa Álvarez", ("Rosa",)), ("pat", "Rosa Lindqvist", ("Rosa",)))
    return InstructionParser(renamed(HARBOUR_FILE, rosas, "harbour with two Rosas"))


def _parser(office: str) -> InstructionParser:
    return office_parser("default") if office == "plain" else _rosas(office)


@pytest.mark.parametrize(
    ("office", "requester", "text", "task"),
    [
        # the class's analogue
        ("plain", "sun", "could you bring me Yang's book — Yang Lei, not Liu",
         ("transfer", "book", "yang", "sun")),
        # variants: the other namesake, lower case, no comma, other offices and things
        ("plain", "sun", "bring me Yang's cup — Liu Yang, not Lei",
         ("transfer", "cup", "liu", "sun")),
        ("plain", "mao", "could you bring me yang's book - yang lei not liu",
         ("transfer", "book", "yang", "mao")),
        ("default", "mao", "bring me Rosa's pen — Rosa Lindqvist, not Álvarez",
         ("transfer", "pen", "lee", "mao")),
        ("harbour", "may", "can I borrow Rosa's umbrella - Rosa Álvarez, not Lindqvist?",
         ("transfer", "umbrella", "rose", "may")),
        # a refusal of the whole full name leaves the other one
        ("plain", "sun", "take my report to Yang - Liu Yang, not Yang Lei",
         ("transfer", "document", "sun", "liu")),
    ],
)  # fmt: skip
def test_the_appositive_names_the_one_meant(
    office: str, requester: str, text: str, task: tuple[str, str, str, str]
) -> None:
    frame = _parser(office).parse(text, requester)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [task], frame


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("give my contract to Yang, not Liu", "yang"),  # one word refused, as before
        ("give my contract to Yang, not Yang Lei", "liu"),
    ],
)
def test_a_refusal_alone_still_leaves_the_other(text: str, recipient: str) -> None:
    frame = office_parser("default").parse(text, "sun")
    assert [t.recipient for t in frame.tasks] == [recipient], frame


def test_the_shared_name_with_no_appositive_is_still_asked() -> None:
    """Must not change: "Rosa's pen" alone says neither Rosa (both keep one)."""
    frame = _rosas("default").parse("bring me Rosa's pen", "mao")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Rosa Álvarez" in frame.question and "Rosa Lindqvist" in frame.question


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("take Yang my pen - no wait, Liu Yang, not Lei", "liu"),
        ("take Yang my pen - sorry, Yang Lei", "yang"),
        ("take Yang my pen - oh wait no, Liu Yang", "liu"),
    ],
)
def test_a_correction_opening_the_naming_part_goes_with_it(text: str, recipient: str) -> None:
    """ "- no wait, Liu Yang, not Lei": the naming part was cut and "no wait" left alone,
    which withdrew the whole request (blind round 130's case, broken by the appositive rule)."""
    frame = office_parser("default").parse(text, "hu")
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "pen", "hu", recipient)
    ], frame


def test_must_not_change_a_correction_to_another_request() -> None:
    frame = office_parser("default").parse("take Yang my pen - no wait, give it to Zhang", "hu")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", "zhang")], frame
