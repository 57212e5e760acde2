"""Idioms of time are no things (blind round 17's class, on a school office no sentence was
written for, ``helpers.playschool``): "when you get a sec", "when you've a minute", "in a tick",
"whenever" say when, so their noun is never declined as a thing the office lacks ("there is no
sec in this office"); with no item before "it"/"that", the assistant asks which item. A request
that names its item is done as before, and a noun that goes on into a phrase ("in a second
drawer") or an office's own thing named like a while is no idiom."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.timing import without_time_idioms
from helpers import office_builder as ob
from helpers.playschool import playschool, raw_playschool
from helpers.reading import frame_reader

_frame = frame_reader(playschool, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "can u bring it down to me when you get a sec",
        "can u send that over to Penny when you get a sec",
        "can you bring it over when you've a minute",
        "bring it to me when you have a mo",
        "could you pass that to Rory in a tick",
        "bring it over whenever",
        "when you get a moment, can you take it to Miles",
        "drop it round to Thandi whenever you can please",
    ],
)
def test_an_idiom_of_time_with_no_item_asks_which_item(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame.decline
    assert frame.tasks == []
    assert frame.question is not None and "which item" in frame.question


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("bring Rory's stapler down to me when you get a sec", "ada"),
        ("can u take my stapler over to Penny when you've a minute", "penny"),
        ("when you get a chance, bring Rory my stapler", "rory"),
        ("pass my stapler to Thandi in a tick, thanks", "thandi"),
        ("bring my stapler to Jun whenever", "jun"),
    ],
)
def test_a_request_that_names_its_item_is_done(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", recipient)
    ]


def _terms(raw: dict[str, object]) -> Terms:
    office = ob.parsed(lambda: raw)()
    return Terms(office, Lexicon.from_office(office))


def test_a_noun_that_goes_on_into_a_phrase_is_no_idiom() -> None:
    terms = _terms(raw_playschool())
    for text in ("put my stapler in a second drawer", "bring me a minute book"):
        assert without_time_idioms(terms, text) == (text, [])


def test_the_idiom_is_set_aside_with_its_evidence() -> None:
    terms = _terms(raw_playschool())
    text, evidence = without_time_idioms(terms, "can u bring it down to me when you get a sec")
    assert text == "can u bring it down to me"
    assert [e.words for e in evidence] == ["when you get a sec"]


def test_an_office_thing_named_like_a_while_is_kept() -> None:
    raw = raw_playschool()
    raw["item_types"].append(ob.item("tick", "tick"))  # a tick sheet, say
    terms = _terms(raw)
    assert without_time_idioms(terms, "bring me it in a tick") == ("bring me it in a tick", [])


@pytest.mark.parametrize(
    "text",
    [
        "bring me Rory's stapler when he's back from lunch",
        "bring me Rory's stapler once he is back from his lunch",
        "can you get Rory's stapler for me as soon as he gets in",
        "bring me Rory's stapler when Rory is free",
        "when she's back from lunch, bring me Rory's stapler",
    ],
)
def test_waiting_for_someone_says_when_and_fetches_no_lunch(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "rory", "ada")
    ]


def test_a_wait_for_oneself_or_a_named_antecedent_is_kept() -> None:
    terms = _terms(raw_playschool())
    for text in (
        "once you're back, bring me Rory's lunch",
        "once Miles is free, take my stapler to him",
        "bring me Rory's lunch",
    ):
        assert without_time_idioms(terms, text) == (text, [])
    text, evidence = without_time_idioms(terms, "bring me Rory's stapler when he's back from lunch")
    assert text == "bring me Rory's stapler"
    assert [e.words for e in evidence] == ["when he's back from lunch"]
