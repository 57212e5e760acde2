"""Blind rounds 20 to 22, class 4 (its name variants): "one of the temp passes" is one of the
office's temporary passes, a plural of a name ending in -ss ("passes") and a compound name with
its first word clipped ("temp pass"). On sentences of our own against a kitchen no sentence
was written for; only what is named moves, and only to whom it is asked for."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.clipped_phrases import clipped_phrases
from assistantx.core import language
from helpers.airside_kitchen import airside_kitchen
from helpers.reading import frame_reader

_frame = frame_reader(airside_kitchen, "odile")

_PASS_TO_TOBIN = [("transfer", "airside_pass", None, "tobin")]


def _tasks(text: str) -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _frame(text).tasks]


@pytest.mark.parametrize(
    "text",
    [
        "Can you bring Tobin one of the temp passes? he's taking the contractor airside",
        "Can you bring Tobin one of the temporary passes?",
        "bring Tobin two visitor passes",
        "bring Tobin a temp pass please",
        "could Tobin have one of the visitor passes",
    ],
)
def test_a_pass_named_by_a_variant_goes_to_tobin(text: str) -> None:
    assert _tasks(text) == _PASS_TO_TOBIN


@pytest.mark.parametrize(
    "text",
    [
        "bring me a temp",  # the clipped word alone names nothing
        "thanks for the temp pass",
        "has Tobin got one of the temp passes?",
        "don't bring Tobin a temp pass",
    ],
)
def test_a_variant_asks_nothing_of_its_own(text: str) -> None:
    assert _tasks(text) == []


@pytest.mark.parametrize(
    ("noun", "plural"),
    [
        ("temporary pass", "temporary passes"),
        ("glass", "glasses"),
        ("gloves", "gloves"),
        ("scissors", "scissors"),
        ("tape dispenser", "tape dispensers"),
    ],
)
def test_plural_of_a_name_ending_in_ss_adds_es(noun: str, plural: str) -> None:
    assert language.plural(noun) == plural


@pytest.mark.parametrize(
    ("names", "expected"),
    [
        (  # three letters clip too ("ref CD" of a "reference CD", round 60)
            [("temporary pass", "p")],
            {"tem pass", "temp pass", "tempo pass", "tempor pass", "tempora pass"},
        ),
        ([("vacuum bag", "v")], {"vac bag", "vacu bag"}),
        ([("thermal cup", "c")], {"ther cup", "therm cup"}),  # never "the cup"
        (  # "temp pass" clips both: neither gets it
            [("temporary pass", "p"), ("tempered pass", "q")],
            # ("temper" of "tempered" is that word's own verb, no clip)
            {"tempo pass", "tempor pass", "tempora pass", "tempe pass"},
        ),
        ([("pass", "p")], set()),  # one word: ``clipped_names``' business
        ([("iced tea", "t")], set()),  # too short to clip
    ],
)
def test_clipped_phrases_keep_the_head_and_one_item(
    names: list[tuple[str, str]], expected: set[str]
) -> None:
    assert set(clipped_phrases(names, taken=set())) == expected


def test_a_clipped_form_the_office_uses_is_never_replaced() -> None:
    assert "temp pass" not in clipped_phrases([("temporary pass", "p")], taken={"temp pass"})


def test_the_first_words_own_verb_is_no_clip() -> None:
    # "weigh" of "weighing scales" is the verb: round 22's "Could you bring me Olive's scales
    # please? Need to weigh the salt for the levain." read "weigh" as the scales' name and
    # asked whose levain was meant
    assert "weigh scales" not in clipped_phrases([("weighing scales", "s")], taken=set())
    assert "weighi scales" in clipped_phrases([("weighing scales", "s")], taken=set())
