"""A correction of whose thing, with why the first owner will not do said in between (fix213b
class 1): "bring me Wang's stapler, no wait she's using it on the filing. Zhang's then" had the
whole request dropped ("OK, I've dropped that request": "no wait" and the reason were read as a
withdrawal). The reason ("she's using it") rules Wang's out; the choice after it ("Zhang's
then", "try Zhang's", "Zhang's instead") names the new owner of the same thing
(``screen.correction._choice_after_reason``; in one sentence,
``possessive_corrections._reason_start``). A "no wait" with no choice after it still withdraws."""

from __future__ import annotations

import pytest
from _offices import tasks_of

_ZHANGS = [("transfer", "stapler", "zhang", "lee")]


@pytest.mark.parametrize(
    "text",
    [
        "can you bring me Wang's stapler, no wait she's using it on the filing. Zhang's then",
        "bring me Wang's stapler, no wait she's using it on the filing, Zhang's then",
        "bring me Wang's stapler, no wait she's using it. try Zhang's",
        "bring me Wang's stapler, no wait she's using it. Zhang's instead",
        "bring me Wang's stapler, oh wait he needs it today. Zhang's then",
        # where the one said is busy is no thing asked for (blind round 213, after its fixes:
        # "... no wait he's using it on the vault shelves. Hunter's then" was dropped)
        "can you bring me Wang's stapler, no wait she's using it in the meeting room. Zhang's then",
        "bring me Wang's stapler, no wait she's busy at the print room. Zhang's then",
    ],
)
def test_the_choice_after_the_reason_is_the_owner(text: str) -> None:
    assert tasks_of("default", text, "lee") == _ZHANGS


def test_a_new_thing_after_the_reason_replaces_it() -> None:
    text = "bring me Wang's stapler, no wait it's broken. a pen instead"
    assert tasks_of("default", text, "lee") == [("transfer", "pen", None, "lee")]


@pytest.mark.parametrize(
    "text",
    [
        "bring me Wang's stapler no Zhang's",
        "bring me Wang's stapler, no wait, Zhang's",
        "bring me Wang's stapler, no wait. Zhang's then",
        "bring me Wang's stapler, the blue one, Zhang's",
    ],
)
def test_neighbour_plain_corrections_stay(text: str) -> None:
    assert tasks_of("default", text, "lee") == _ZHANGS


def test_neighbour_hu_then_gao_stays() -> None:
    assert tasks_of("default", "bring me Hu's stapler, Gao's", "lee") == [
        ("transfer", "stapler", "gao", "lee")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "bring me Wang's stapler, no wait, never mind",
        "bring me Wang's stapler, no wait she's using it",
    ],
)
def test_neighbour_no_choice_still_withdraws(text: str) -> None:
    from _offices import parser

    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and (frame.decline or "").startswith("OK, I've dropped")
