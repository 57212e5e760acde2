"""Issue #23, fixer fix97h class 3: "Wang wants a book, can you take him my spare one": "my
<spare/other/old/second> one" after a thing is the requester's own thing of that kind
(``screen.own_one``), as "mine" is; it was read as "a book", anyone's, and a colleague's was
taken. "a spare one" (no "my") stays anyone's."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.parser import shared_parser
from assistantx.agents.symbolic.reading.screen.own_one import own_ones
from assistantx.core.office import Office
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office, harbour_office


def _office(name: str) -> Office:
    return harbour_office() if name == "harbour" else default_office()


@pytest.mark.parametrize(
    ("office", "who", "text", "item", "receiver"),
    [
        # the class's analogue (lee owns a book)
        ("default", "lee", "Wang wants a book, can you take him my spare one", "book", "wang"),
        # variants of our own: other describing words, things, offices
        ("default", "lee", "Wang wants a book, can you take him my one", "book", "wang"),
        ("default", "lee", "Wang needs a pen, bring him my other one", "pen", "wang"),
        ("harbour", "rose", "mark needs a calculator, can you take him my old one", "calculator",
         "mark"),
        ("harbour", "rose", "june wants a ruler, bring her my second one", "ruler", "june"),
    ],
)  # fmt: skip
def test_my_spare_one_is_the_requesters_own(
    office: str, who: str, text: str, item: str, receiver: str
) -> None:
    here = _office(office)
    frame = shared_parser(here).parse_with_answers(text, who, [])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, who, receiver)
    ]
    assert named_recipients(here, memory(who, text)) == {receiver}


@pytest.mark.parametrize(
    ("office", "who", "text", "item", "receiver"),
    [
        # neighbours: no "my", so anyone's
        ("default", "lee", "Wang wants a book, take him a spare one", "book", "wang"),
        ("harbour", "rose", "june wants a ruler, bring her a spare one", "ruler", "june"),
        # "my one" as the subject of news, then another asked for: not an object handed over
        ("default", "lee", "my one is broken, bring me a pen", "pen", "lee"),
    ],
)
def test_a_spare_one_without_my_stays_anyones(
    office: str, who: str, text: str, item: str, receiver: str
) -> None:
    frame = shared_parser(_office(office)).parse_with_answers(text, who, [])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, None, receiver)
    ]


def test_a_word_that_names_a_thing_is_no_describing_word() -> None:
    # "my paper one": paper is a thing of its own, so it is left as it was
    text, evidence = own_ones("take him my paper one", {"paper"}, lambda _: "cup")
    assert (text, evidence) == ("take him my paper one", [])
    text, _ = own_ones("take him my spare one", {"paper"}, lambda _: "cup")
    assert text == "take him my cup"
    # nothing named before it: left as it was
    assert own_ones("take him my spare one", set(), lambda _: None)[0] == "take him my spare one"
