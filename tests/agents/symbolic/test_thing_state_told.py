"""A thing's state said bare ("stapler's working fine now", "calculator is fine again"): the
"'s" before an adverb of how it works is "is", and a bare thing, "be" and a state is told,
never the thing asked for. With a thank-you it is answered in words; nothing moves. Before,
"thanks robot, stapler's working fine now" borrowed a colleague's stapler."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_mao = frame_reader(default_office, "mao")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    "text",
    [
        "thanks robot, stapler's working fine now 👍",
        "thanks, stapler's working perfectly now",
        "cheers, stapler is ok now",
        "stapler's working fine now",
    ],
)
def test_default_a_thing_said_to_work_again_moves_nothing(text: str) -> None:
    frame = _mao(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None


@pytest.mark.parametrize(
    "text",
    [
        "thanks, ruler's working fine now",
        "cheers, calculator's fine now",
        "thanks, label maker's working again",
        "ta, umbrella's alright now",
        "laptop charger is working fine",
    ],
)
def test_harbour_a_thing_said_to_work_again_moves_nothing(text: str) -> None:
    frame = _may(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None


def test_the_thanks_is_answered() -> None:
    frame = _mao("thanks robot, stapler's working fine now 👍")
    assert frame.decline is not None and frame.decline.startswith("You're welcome")


@pytest.mark.parametrize(
    ("read", "text", "item", "who"),
    [
        (_mao, "thanks! can I have Wang's stapler now?", "stapler", "mao"),
        (_mao, "Wang's stapler please", "stapler", "mao"),
        (_mao, "stapler is urgent", "stapler", "mao"),
        (_may, "thanks! label maker please", "label_maker", "may"),
        (
            _may,
            "thanks, calculator's working perfectly now, can I borrow Mark's ruler?",
            "ruler",
            "may",
        ),
    ],
)
def test_a_request_beside_or_instead_still_fetches(
    read: ReadFrame, text: str, item: str, who: str
) -> None:
    frame = read(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, who)], frame
