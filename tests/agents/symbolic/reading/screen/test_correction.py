"""A correction right after a name replaces it; the retracted one is never acted on."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.correction import corrected
from assistantx.agents.symbolic.reading.screen.terms import Terms


def test_a_person_corrected_is_replaced(terms: Terms) -> None:
    text, evidence = corrected(terms, "bring me Wang's stapler - sorry, I meant Zhang's")
    assert text == "bring me Zhang's stapler"
    assert [e.meaning for e in evidence] == ["means Zhang"]


def test_an_item_corrected_is_replaced(terms: Terms) -> None:
    text, _ = corrected(terms, "bring me a stapler, no wait, a pen")
    assert text == "bring me a pen"


def test_no_correction_leaves_the_text(terms: Terms) -> None:
    assert corrected(terms, "bring me a stapler") == ("bring me a stapler", [])


def test_what_is_refused_first_then_what_replaces_it(terms: Terms) -> None:
    """ "no wait not Wang's, Zhang's one" (blind round 26's class): the refusal comes first
    and the replacement after the comma; on main "not Wang's" was read as the correction."""
    text, evidence = corrected(terms, "bring me Wang's stapler? no wait not Wang's, Zhang's one")
    assert text == "bring me Zhang's stapler"
    assert [e.meaning for e in evidence] == ["means Zhang"]
