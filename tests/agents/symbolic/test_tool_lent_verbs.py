"""Fix115d, class 2 (analogues, not the measured sentences): a verb English derives from a
word of the seal's names asks for the seal's work ("get my affidavit notarised" where the seal
is a "notary stamp"; "certified" where it is a "certification stamp"), as "stamped" does
(reading/tool_verbs.py). The noun itself stays a noun: "the notary called" is told, "bring me
the notary stamp" fetches the stamp; a tool whose names derive no verb lends none."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.tool_verbs import LentVerbs, derived_verbs
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office
from helpers.law_firm import certifying_harbour, law_firm
from helpers.reading import frame_reader

_law = frame_reader(law_firm, "chen")
_harbour = frame_reader(certifying_harbour, "may")
_default = frame_reader(default_office, "chen")


def _seals(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    assert frame.question is None, frame.question
    return [(t.kind, t.item, t.actor) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "actor"),
    [
        ("Can you get my affidavit notarised pls", None),  # the class's analogue
        ("get my contract notarized", None),
        ("can you have my contract notarised by Mao", "mao"),
        ("could you notarise my affidavit", None),
        ("my affidavit needs notarising", None),
        ("Notarize my report please", None),
    ],
)
def test_a_verb_of_the_notary_stamp_asks_for_its_work(text: str, actor: str | None) -> None:
    assert _seals(_law(text)) == [("seal", "document", actor)]


@pytest.mark.parametrize(
    ("text", "actor"),
    [
        ("can you get my contract certified", None),
        ("please have my letter certified by Mark", "mark"),
    ],
)
def test_a_verb_of_the_certification_stamp_asks_for_its_work(text: str, actor: str | None) -> None:
    assert _seals(_harbour(text)) == [("seal", "document", actor)]


def test_derivations_the_dictionary_knows() -> None:
    assert derived_verbs(["notary stamp", "notarial seal"]) == {"notarize"}
    assert derived_verbs(["certification stamp"]) == {"certify"}
    assert derived_verbs(["embosser"]) == {"emboss"}
    # a word no suffix makes a known verb of lends nothing
    assert derived_verbs(["company seal", "official seal", "stamp", "chop"]) == frozenset()


def test_the_default_offices_seal_lends_no_verb() -> None:
    # "company seal", "official seal", "stamp", "chop": no derived verb, nothing re-read
    assert LentVerbs.from_office(default_office(), ()).forms == {}
    lent = LentVerbs.from_office(law_firm(), ())
    assert lent.read("Notarised? notarizing, notary") == "Sealed? sealing, notary"


# -- must not change ---------------------------------------------------------------------


def test_the_noun_is_told_never_a_task() -> None:
    frame = _law("the notary called")
    assert frame.tasks == []


def test_the_stamp_by_its_name_is_fetched() -> None:
    assert [(t.kind, t.item) for t in _law("bring me the notary stamp").tasks] == [
        ("transfer", "seal")
    ]


def test_work_told_as_done_asks_nothing() -> None:
    assert _law("my affidavit was notarised yesterday").tasks == []


def test_stamped_still_asks_for_the_seal() -> None:
    assert _seals(_default("can you get my contract stamped pls")) == [("seal", "document", None)]
