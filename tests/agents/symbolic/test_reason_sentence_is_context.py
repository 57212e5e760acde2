"""A reason said in a sentence or clause after the request ("Could you laminate my safety
poster? Tea keeps getting spilled on it.") is context: its nouns never replace or join the
request's thing, and it never withdraws the request. Three gaps let a reason take over:

- a thing of the office said bare, then a present verb of what keeps happening ("tea keeps
  getting spilled on it") or the passive's "got" ("coffee got spilled on it") was not told
  (``speech._thing_happened`` took only a past verb, and "got" for the errand's "get"): the
  tea became the thing laminated ("Sorry, I can't laminate a tea here"), a coffee was made;
- "tea got spilled on mine" was read as the thing being had already, and the request was
  dropped (``speech.had_already``: the passive's "got" is no having);
- a thing named only in the reason hid that the request's own thing was guessed ("my safety
  poster", unknown, read as the laminator's badge): the badge was laminated unasked. The
  guess is now looked for in the request's own words too, and asked ("Shall I ...?")."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    ("office", "requester", "text", "got"),
    [
        # the class's analogue, with a thing the office knows
        ("harbour", "may", "could you bring me a ruler? tea got spilled on mine",
         [("transfer", "ruler", None, "may")]),
        ("default", "sun", "could you copy my contract? coffee got spilled on it",
         [("copy", "document", "sun", "sun")]),
        ("default", "sun", "could you bring me some wipes? coffee keeps dripping on my desk",
         [("transfer", "wipes", None, "sun")]),
        ("harbour", "may", "can you scan my letter? tea got spilled on it",
         [("copy", "document", "may", "may")]),
    ],
)  # fmt: skip
def test_the_reason_adds_and_withdraws_nothing(
    office: str, requester: str, text: str, got: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of(office, text, requester) == got


@pytest.mark.parametrize(
    "text",
    [
        # the class's analogue: the poster is no thing the office knows
        "could you laminate my safety poster? tea keeps getting spilled on it",
        "could you laminate my safety poster? keeps getting tea on it",
        "Could you laminate my safety poster? It keeps getting tea spilled on it.",
    ],
)
def test_a_guessed_thing_is_asked_whatever_the_reason_names(text: str) -> None:
    frame = parser("harbour").parse(text, "may")
    assert frame.tasks == [] and frame.decline is None, frame
    assert frame.question is not None and "laminate" in frame.question, frame
    assert "tea" not in frame.question


@pytest.mark.parametrize(
    ("office", "requester", "text", "got"),
    [
        # a second request after the reason still stands
        ("harbour", "may", "bring me a ruler? tea got spilled on mine. also bring me a calculator",
         [("transfer", "ruler", None, "may"), ("transfer", "calculator", None, "may")]),
        # the thing had already, said so: still withdrawn
        ("harbour", "may", "bring me a ruler. oh wait, I got one already", []),
        ("harbour", "may", "bring me a ruler, Mark got me one already", []),
        # a thing asked for with a verb of its own: still asked
        ("harbour", "may", "bring me a ruler. tea needs making too",
         [("transfer", "ruler", None, "may"), ("produce", "tea", None, "may")]),
    ],
)  # fmt: skip
def test_must_not_change(
    office: str, requester: str, text: str, got: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of(office, text, requester) == got
