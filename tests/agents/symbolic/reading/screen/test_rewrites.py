"""The rewrites of what is left: a thing by its purpose, "another one" after a condition, a
pronoun the facts pin to one person, a dangling possessive."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.rewrites import purposes, rewrite, stem
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core.task_schema import Hint
from reading.screen._judge import Read


def test_a_thing_named_by_its_purpose_becomes_the_declared_item(terms: Terms) -> None:
    text, evidence = purposes(terms, "bring me something to cut this with")
    assert text == "bring me a scissors"
    assert [e.meaning for e in evidence] == ["a scissors (to cut)"]


def test_a_purpose_no_item_declares_is_left(terms: Terms) -> None:
    assert purposes(terms, "bring me something to juggle with") == (
        "bring me something to juggle with",
        [],
    )


def test_another_one_after_a_condition_is_that_item(terms: Terms, message: Read) -> None:
    hint = Hint(kind="condition", person="zhang", value="broken", item_type="stapler", said="")
    msg = message("bring me another one")
    text, evidence = rewrite(terms, msg, "bring me another one", [hint], [])
    assert text == "bring me a stapler"
    assert [e.meaning for e in evidence] == ["another stapler"]


def test_a_pronoun_the_facts_pin_to_one_person_gets_the_name(terms: Terms, message: Read) -> None:
    hint = Hint(kind="availability", person="zhang", value="here", said="")
    msg = message("bring him a pen")
    text, _ = rewrite(terms, msg, "bring him a pen", [hint], [])
    assert text == "bring Zhang Wei a pen"


def test_mine_after_an_item_is_my_item(terms: Terms, message: Read) -> None:
    msg = message("Wang needs a stapler, lend him mine")
    text, evidence = rewrite(terms, msg, "lend Wang mine", [], [])
    assert text == "lend Wang my stapler"
    assert [e.meaning for e in evidence] == ["my stapler"]


def test_stem_is_the_verbs_lemma() -> None:
    assert [stem(w) for w in ("cutting", "writes", "stapling", "zzq")] == [
        "cut",
        "write",
        "staple",
        "zzq",
    ]
