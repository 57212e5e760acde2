"""The frame parser's priority rule tables (issue 16): each rule, and the order between them.

``PERSON_RULES`` gives a named person their part in a clause and ``KIND_RULES`` the one task
a clause about a document asks for; the first rule that applies wins, so each case below
names the rule it must reach, through the real parser on the default office.
"""

from __future__ import annotations

from dataclasses import replace

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic.reading._kinds import KIND_RULES
from assistantx.agents.symbolic.reading._parties import PERSON_RULES, PersonSite, person_rule
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.core.office import Office
from assistantx.core.receiving_place import Ahead


def _site(
    prev: str = "", nxt: str = "", following: Mention | None = None, then: str = "", **kw: bool
) -> PersonSite:
    return PersonSite(
        prev,
        nxt,
        following,
        kw.get("possessive", False),
        kw.get("back", False),
        kw.get("subject", False),
        then,
        kw.get("obliged", False),
        kw.get("stood_in_for", False),
        kw.get("to_have", False),
        later_use=kw.get("later_use", False),
    )


_DESK = Mention("word", 3, 4, ("desk",))
_SIGN = Mention("cue", 3, 4, ("sign",))
_ITEM = Mention("item", 3, 4, ("stapler",))
_MEETING = Mention("word", 3, 4, ("meeting",))
_COPY = Mention("cue", 3, 4, ("copy",))
_MY = Mention("self", 2, 3, (), possessive=True)

PERSON_CASES = [
    (
        replace(_site("on", following=_DESK, possessive=True), ahead=Ahead(("the", "one"))),
        "the one on Wang's desk, the book that's on Wang's desk: where it lies, the source",
    ),
    (
        replace(_site("on", following=_DESK, possessive=True), ahead=Ahead(("leave", "one"))),
        "at Wang's desk: met there",
    ),
    (_site("at", following=_DESK, possessive=True), "at Wang's desk: met there"),
    (_site("from", following=_DESK, possessive=True), "from Wang's desk: the source"),
    (_site("", following=_DESK, possessive=True), "Wang's desk: named, no role yet"),
    (_site("get", following=_SIGN, possessive=True), "Wang's signature: Wang signs"),
    (
        replace(_site("for", following=_MEETING, possessive=True), occasion=True),
        "for Grace's meeting: whose occasion it is receives, unless another is named",
    ),
    (_site("for", following=_MEETING, possessive=True), "Wang's stapler: an owner of the item"),
    (_site("from", following=_ITEM, possessive=True), "Wang's stapler: an owner of the item"),
    (_site("because", nxt="needs"), "because Rich ...: the reason, not a party"),
    (
        _site("", nxt="wants", then="it", subject=True),
        "Rich wants it (on the board): a wish about what was asked, not a recipient",
    ),
    (
        _site("", nxt="needs", then="to", subject=True, obliged=True),
        "Zhang has to / must sign: the doer",
    ),
    (
        _site("could", nxt="have", subject=True, to_have=True),
        "could Min have / let Min borrow scissors: the one asked for receives",
    ),
    (
        _site("", nxt="wants", subject=True, later_use=True),
        "fetch me tape? Zhang wants to wrap a parcel: Zhang's use of it, not a recipient",
    ),
    (_site("", nxt="needs", subject=True), "Min needs / gets scissors: the one in need receives"),
    (_site("from"), "from Wang: the source"),
    (_site("off"), "off Wang: the source"),
    (_site("by"), "by Wang: the doer"),
    (_site("to", back=True), "back to Wang: the owner, given back"),
    (
        _site("for", stood_in_for=True),
        "covering for Fen, standing in for Fen: why the speaker asks, not a recipient",
    ),
    (_site("to"), "to / for / with Wang: the recipient"),
    (_site("get", nxt="to"), "Wang to sign, ask Wang: the doer"),
    (_site("ask"), "Wang to sign, ask Wang: the doer"),
    (
        _site("if", nxt="could", then="sign", subject=True),
        "if Wang could sign it, Wang would sign it: the doer of a person's work",
    ),
    (
        _site("if", nxt="signed", subject=True),
        "if Wang could sign it, Wang would sign it: the doer of a person's work",
    ),
    (_site("bring", following=_ITEM), "give Wang a stapler: the recipient"),
    (_site("bring", following=_SIGN), "otherwise: named, no role yet"),
    (
        replace(_site("make", nxt="a", following=_COPY), indirect=True),
        "make Zhang a copy, print Mark my file: whom the thing made is for",
    ),
    (
        replace(_site("print", nxt="my", following=_MY), indirect=True),
        "make Zhang a copy, print Mark my file: whom the thing made is for",
    ),
    (_site("make", nxt="copy", following=_COPY), "otherwise: named, no role yet"),
    (
        replace(_site("and", nxt="a", following=_COPY), gapped=True),
        "bring Wang a stapler and Sun a pen: Sun is whom the unsaid verb gives the pen",
    ),
    (
        _site("and", nxt="asked", subject=True),
        "Rich asked for it, Hal said so: the subject of a statement, not a party",
    ),
    (_site("and"), "otherwise: named, no role yet"),
]


@pytest.mark.parametrize(("site", "rule"), PERSON_CASES, ids=[r for _, r in PERSON_CASES])
def test_the_first_person_rule_that_applies_wins(site: PersonSite, rule: str) -> None:
    assert person_rule(site).name == rule


def test_every_person_rule_is_reached() -> None:
    assert {r.name for r in PERSON_RULES} == {rule for _, rule in PERSON_CASES}


KIND_CASES = [
    (
        "Get Zhang Wei to sign my contract and copy it.",
        "sign",
        "a person's work (a signature, a kind of the table), whatever else is said",
    ),
    ("Please stamp my contract with the seal.", "seal", "a seal on a document"),
    ("Please heat my lunch.", "heat", "heating, unless a product is asked for"),
    ("Print my report and photocopy my contract.", "print", "printing the requester's file"),
    ("Please photocopy my contract.", "copy", "copying a document (not a file)"),
]


@pytest.mark.parametrize(("text", "kind", "rule"), KIND_CASES, ids=[c[2] for c in KIND_CASES])
def test_a_clause_about_a_document_is_one_task_by_the_first_rule(
    office: Office, text: str, kind: str, rule: str
) -> None:
    frame = InstructionParser(office).parse(text, "lee")
    assert [t.kind for t in frame.tasks][:1] == [kind], (frame.question, frame.decline)
    assert any(r.name.startswith(rule) for r in KIND_RULES)
