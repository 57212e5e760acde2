"""One part not available never declines the whole message: "bring a coffee to Zhang and bring
for me a tea" (no tea in the office) had been declined whole. The part that asks for a thing
nothing here offers, a request of its own, is said not to be here, and the rest still offered
("Shall I still bring a coffee to Zhang?"; ``screen.service.doable_rest``); on a yes the rest
is done. A message that asks nothing else is declined as before."""

from __future__ import annotations

import pytest
from _offices import parser

_NO_TEA = (
    "Sorry, I can't get you any tea: nothing in this office offers that, and I won't swap it "
    "for something else. Shall I still "
)


@pytest.mark.parametrize(
    ("text", "rest"),
    [
        ("bring a coffee to Zhang and bring for me a tea", "bring a coffee to Zhang"),
        ("bring a coffee to Zhang. bring me a tea", "bring a coffee to Zhang"),
        ("could you bring me a tea and then bring Zhang a stapler", "bring Zhang a stapler"),
        ("bring me a tea and a stapler", "bring you a stapler"),
        # the rest said with no verb of its own is said back with one
        ("could I get a tea, a stapler please", "bring you a stapler please"),
    ],
)
def test_the_tea_is_told_and_the_rest_offered(text: str, rest: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.decline is None
    assert frame.question == f"{_NO_TEA}{rest}?"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("bring a coffee to Zhang and bring for me a tea", [("produce", "coffee", None, "zhang")]),
        ("bring me a tea and a stapler", [("transfer", "stapler", None, "lee")]),
    ],
)
def test_on_a_yes_the_rest_is_done(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    frame = parser("default").parse_with_answers(text, "lee", ["yes"])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == expected


def test_on_a_no_nothing_is_done() -> None:
    frame = parser("default").parse_with_answers(
        "bring a coffee to Zhang and bring for me a tea", "lee", ["no"]
    )
    assert frame.tasks == [] and frame.decline is not None


@pytest.mark.parametrize(
    "text", ["bring me a tea", "make me a tea", "bring me a tea and a unicorn"]
)
def test_neighbour_nothing_else_asked_is_declined(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.question is None
    assert (frame.decline or "").startswith("Sorry, I can't get you any tea")


def test_neighbour_an_unknown_thing_beside_a_known_one_is_asked() -> None:
    frame = parser("default").parse("bring me a stapler and a unicorn", "lee")
    assert frame.question == "Sorry, I'm not sure what you mean by “a unicorn”. Could you tell me?"


@pytest.mark.parametrize("text", ["could I get a tea, strong one please"])
def test_more_said_of_the_missing_thing_is_no_rest(text: str) -> None:
    # round 216 (read after its final measure): "could I get a coffee, strong one please" in
    # an office with no coffee had asked "Shall I still strong one please?"
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith(_NO_TEA[:30]), frame
