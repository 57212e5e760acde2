"""A correction of whose thing it is, with a reason after it ("Could you ask Olive to lend me
her calculator? Sorry, I meant Anne-Marie's, Olive took hers home"): the new owner's thing is
asked for, and the owner's pronoun said before the correction is the new owner's too (blind
round 38's class: the old owner's thing was fetched, the reason naming them again). A given
name written with a hyphen is one name ("Anne-Marie"). Near-misses keep their reading."""

from __future__ import annotations

import pytest

from helpers.parcel_desk import parcel_desk
from helpers.reading import frame_reader

_frame = frame_reader(parcel_desk, "nadia")


def _tasks(text: str) -> list[tuple[str, str | None, str | None, str | None]]:
    frame = _frame(text)
    assert frame.question is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        (
            "Could you ask Olive to lend me her calculator? Sorry, I meant Petra's, "
            "Olive took hers home.",
            "petra",
        ),
        (
            "Could you ask Olive to lend me her calculator? Sorry, I meant Petra's. "
            "Olive took hers home.",
            "petra",
        ),
        (
            "Could you ask Olive to give her calculator to me? No wait, Petra's - "
            "Olive took hers home",
            "petra",
        ),
        (
            "Could you ask Olive to lend me her calculator? Sorry, I meant Anne-Marie's, "
            "Olive took hers home.",
            "annemarie",
        ),
        ("Could you bring me Olive's calculator? Sorry, I meant Anne-Marie's.", "annemarie"),
    ],
)
def test_a_corrected_owner_with_a_reason_after_is_the_owner(text: str, owner: str) -> None:
    assert _tasks(text) == [("transfer", "calculator", owner, "nadia")]


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("Could you ask Olive to lend me her calculator?", "olive"),
        ("Could you ask Olive to lend me her calculator? Sorry, I meant Petra's.", "petra"),
        ("Bring me Anne-Marie's calculator", "annemarie"),
        ("Ask Anne-Marie for her dev kit", "annemarie"),
        ("Bring me Miles's calculator", "miles"),
    ],
)
def test_near_misses_keep_their_reading(text: str, owner: str) -> None:
    item = "dev_kit" if "dev kit" in text else "calculator"
    assert _tasks(text) == [("transfer", item, owner, "nadia")]


def test_a_hyphened_given_name_alone_is_not_half_of_it() -> None:
    frame = _frame("Bring me Anne's calculator")
    assert frame.tasks == [] and frame.question is not None, frame
