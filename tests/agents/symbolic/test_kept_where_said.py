"""A place phrase after an unpossessed kind, read before asking which one (blind round 55's
classes; its office and sentences were never read).

Several people keep a lunch in the staff fridge and the requester is one of them: "lunch from
the fridge pls" is the requester's own (nobody asks for a colleague's lunch without naming
them); a requester who keeps none there is asked whose, as before.

A supply kept elsewhere, said "at" a place that keeps none ("need gloves at the nurses
station", gloves in the store cupboard): the place is where it goes, not where it is. At the
requester's own place it comes to them; elsewhere they are asked who there should get it, and
the answer names the recipient. A size or count said after it ("smalls if there are any",
"two if you can") is no new item. The question about a thing kept nowhere says its article as
English does ("any exam gloves", "a pair of scissors")."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.reading import answered_reader, frame_reader
from helpers.sample_lab import sample_lab


def _read(who: str, text: str) -> list[tuple[str, str | None, str | None, str]]:
    frame = frame_reader(sample_lab, who)(text)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize("who", ["rhea", "nell", "sami"])
@pytest.mark.parametrize(
    "text",
    [
        "lunch from the fridge to my desk pls, starving",
        "lunch from the fridge pls",
        "bring me the lunch from the staff fridge",
        "could you get the lunch in the fridge for me",
    ],
)
def test_a_kind_the_requester_keeps_there_is_their_own(who: str, text: str) -> None:
    assert _read(who, text) == [("transfer", "lunch", who, who)]


@pytest.mark.parametrize(
    "text", ["lunch from the fridge pls", "bring me the lunch from the staff fridge"]
)
def test_one_who_keeps_none_there_is_asked_whose(text: str) -> None:
    frame = frame_reader(sample_lab, "wren")(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert frame.question.startswith("Which lunch at the staff fridge do you mean"), frame


def test_a_colleagues_named_lunch_is_still_theirs() -> None:
    assert _read("rhea", "bring me Sami's lunch from the fridge") == [
        ("transfer", "lunch", "sami", "rhea")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "need gloves at the nurses station plz, smalls if there are any",
        "need gloves at the nurses station, two if you can",
        "gloves at the nurses station please",
        "can I get some gloves at the nurses station",
    ],
)
def test_a_supply_said_at_the_requesters_place_comes_to_them(text: str) -> None:
    assert _read("nell", text) == [("transfer", "gloves", None, "nell")]


def test_a_supply_said_at_another_place_asks_who_there() -> None:
    text = "need gloves at the nurses station plz, smalls if there are any"
    frame = frame_reader(sample_lab, "rhea")(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "who there should get them" in frame.question, frame
    assert "Nell Amadi is there" in frame.question, frame
    answered = answered_reader(sample_lab, "rhea")
    for answer, who in (("Nell", "nell"), ("Nell Amadi", "nell"), ("me", "rhea")):
        got = answered(text, [answer])
        assert [(t.item, t.recipient) for t in got.tasks] == [("gloves", who)], (answer, got)


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("bring me the scissors from the store room", "a pair of scissors"),
        ("bring me the thermometer at the staff room", "a thermometer"),
    ],
)
def test_a_thing_kept_nowhere_there_is_asked_about_in_english(text: str, said: str) -> None:
    frame = frame_reader(sample_lab, "nell")(text)
    assert frame.question is not None and f"I don't know of {said} kept at" in frame.question


def test_the_article_of_an_unknown_one() -> None:
    from assistantx.core.language import indefinite

    assert [indefinite(w) for w in ("exam gloves", "glue", "apron", "ruler")] == [
        "any",
        "any",
        "an",
        "a",
    ]


async def test_end_to_end_gloves_come_to_the_requesters_station() -> None:
    text = "need gloves at the nurses station plz, smalls if there are any"
    run = await run_instruction(sample_lab(), "nell", text)
    assert run.stm.trace.summary.startswith("Done"), run.stm.trace.summary


async def test_end_to_end_the_requesters_own_lunch() -> None:
    run = await run_instruction(sample_lab(), "rhea", "lunch from the fridge to my desk pls")
    assert run.stm.trace.summary.startswith("Done: you now have your lunch"), run.stm.trace.summary
