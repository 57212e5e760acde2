"""A correction that says again a later part of a request replaces only that part (blind
rounds 57-58's class: "print my slides and take them to Ivo - sorry, I meant take it to
Amber, Ivo is off today" was not understood: the correction opened with a request verb and
withdrew the whole request, print and all, leaving "take it to Amber" with nothing for "it").
The later part, after "and", "then" or a comma, that opens with the correction's own verb (or
another verb of handing a thing on: take / bring / pass) is what is replaced; what came before
it stands, and the reason after the correction is context. A correction that says a request
of another verb still withdraws the whole request it breaks off."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "wang")


@pytest.mark.parametrize(
    ("text", "kind", "recipient"),
    [
        (
            "print my slides and take them to Chen - sorry, I meant take it to Lee, Chen is "
            "off today",
            "print",
            "lee",
        ),
        ("print my report and bring it to Chen, no wait, bring it to Lee", "print", "lee"),
        ("print my report and take it to Chen - sorry, I mean bring it to Lee", "print", "lee"),
        (
            "print my slides and take them to Chen - actually, take them to Lee, Chen's away",
            "print",
            "lee",
        ),
        (
            "could you print my report and pass it to Chen? sorry, I meant pass it to Lee",
            "print",
            "lee",
        ),
        # fix129e: wang has no lunch in the fridge; Zhang's is there
        (
            "heat Zhang's lunch and then bring it to Chen - oops, I meant bring it to me",
            "heat",
            "wang",
        ),
    ],
)
def test_the_repeated_part_is_replaced_and_the_rest_stands(
    text: str, kind: str, recipient: str
) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.recipient) for t in frame.tasks] == [(kind, recipient)], frame


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        # a request of its own verb: the whole request broken off is withdrawn
        ("fetch Zhang's stapler... actually, no, just print my report", "print", "file"),
        ("bring me Zhang's stapler - sorry, I meant print my report", "print", "file"),
    ],
)
def test_a_correction_of_another_request_still_withdraws_it(
    text: str, kind: str, item: str
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [(kind, item, "wang")], frame
