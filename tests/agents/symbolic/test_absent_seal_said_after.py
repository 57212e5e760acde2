"""A colleague's seal asked for to stamp with, their absence said in a piece after the request
(fix61d, class 3): "take Wang's seal and stamp my form yourself, she's at lunch" fetched Wang's
seal and stamped, where "... while she's at lunch" is declined (test_absent_seal.py): the seal
used behind its owner's back. The absence is read in a piece of its own too, by a pronoun
("she's at lunch", "he's off today") or by the owner's name ("Wang is on holiday"), and "use
Wang's seal on my contract" puts the seal to use as words of stamping do. A seal given back to
its owner, the speaker's own absence, another's absence and a plain transfer keep their
readings."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "take Wang's seal and stamp my form yourself, she's at lunch",
        "use Wang's seal on my contract, she's on holiday",
        "take Wang's seal and stamp my form. she's out today",
        "use Wang's seal on my contract, Wang is on holiday",
        "grab Mao's seal and seal my invoice with it, he's off today",
    ],
)
def test_an_absent_colleagues_seal_for_own_stamping_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "seal" in frame.decline and "I did nothing" in frame.decline


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # no absence: Wang stamps it herself, or her seal is asked of her for Lee to use
        ("use Wang's seal on my contract", [("seal", "document", "lee", "wang")]),
        (
            "take Wang's seal and stamp my form yourself",
            [("transfer", "seal", "wang", None), ("seal", "document", "lee", None)],
        ),
        # another colleague away: not the seal's owner
        (
            "use Wang's seal on my contract, Zhang is on holiday",
            [("seal", "document", "lee", "wang")],
        ),
        # the speaker away, or nobody's thing
        ("bring me Zhang's stapler, I'm at lunch", [("transfer", "stapler", "zhang", None)]),
        ("Wang's at lunch, can you bring me a stapler", [("transfer", "stapler", None, None)]),
        # a plain transfer while its owner is out asks the owner, as "... while he's out" does
        ("grab Zhang's stapler, he's off today", [("transfer", "stapler", "zhang", None)]),
    ],
)
def test_the_rest_keep_their_readings(
    text: str, tasks: list[tuple[str, str, str | None, str | None]]
) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.actor) for t in frame.tasks] == tasks, frame


def test_a_seal_given_back_to_its_absent_owner_is_not_declined() -> None:
    frame = _frame("take Wang's seal to her, she's at lunch")
    assert frame.decline is None, frame
