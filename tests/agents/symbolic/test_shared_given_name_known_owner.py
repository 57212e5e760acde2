"""A possessive name several colleagues share ("Léa's scale rule" where two Léas work) means
one of them only when exactly one is KNOWN (by the assistant's own data) to own the thing
(round 143 class 3): a thing the office lists as a namesake's but the assistant does not know
of (``known: false``) never chooses between them, so which one is asked. Nor does one known
owner among colleagues all called by the name (round 160): the other may own one unknown to
the assistant. A unique family name reads as before."""

from __future__ import annotations

import pytest

from helpers.namesake_studio import namesake_studio
from helpers.reading import answered_reader, frame_reader

_read = frame_reader(namesake_studio, "noor")
_answered = answered_reader(namesake_studio, "noor")


@pytest.mark.parametrize(
    ("text", "names"),
    [
        # only Léa Kaczmarek owns one, unknown to the assistant
        ("bring me Léa's scale rule", ("Léa Fournier", "Léa Kaczmarek")),
        ("can you grab Lea's scale rule for me", ("Léa Fournier", "Léa Kaczmarek")),
        # only Sam Birch owns one, unknown to the assistant
        ("bring me Sam's stapler", ("Sam Birch", "Sam Ortiz")),
        # neither Sam owns one
        ("bring me Sam's scale rule", ("Sam Birch", "Sam Ortiz")),
        # only Sam Ortiz is known to own one, but both are called Sam and the other may keep
        # one the assistant does not know of (round 160: "Noor's controller",
        # test_namesakes_called_alike.py); this was read as Sam Ortiz's before
        ("bring me Sam's ruler", ("Sam Birch", "Sam Ortiz")),
        # a shared family name: Léa's is unknown, Ivo has none
        ("bring me Kaczmarek's scale rule", ("Ivo Kaczmarek", "Léa Kaczmarek")),
    ],
)
def test_no_known_owner_among_namesakes_is_asked(text: str, names: tuple[str, str]) -> None:
    frame = _read(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert all(n in frame.question for n in names), frame.question


def test_the_answer_settles_which_namesake() -> None:
    frame = _answered("bring me Léa's scale rule", ["Léa Kaczmarek"])
    assert [(t.item, t.owner) for t in frame.tasks] == [("scale_rule", "lea_k")], frame


# -- must not change ---------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("bring me Fournier's mug", "mug", "lea_f"),  # a unique family name
        ("bring me Birch's stapler", "stapler", "sam_b"),  # unique, though unknown to own it
    ],
)
def test_a_unique_name_is_read(text: str, item: str, owner: str) -> None:
    frame = _read(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner) for t in frame.tasks] == [(item, owner)]
