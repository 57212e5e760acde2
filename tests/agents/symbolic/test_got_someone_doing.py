""" "we've got a little one going for bloods", "we've got someone coming in at two": a having
whose "one"/"someone" is doing something (a present participle after it) tells what is
happening, the reason for the request beside it; it is not the thing asked for had already
(``speech.had_already``), which withdrew the request."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "lin")
_HARBOUR = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("read", "text", "task"),
    [
        (_DEFAULT, "scissors pls, we've got a little one doing crafts", ("transfer", "scissors")),
        (
            _DEFAULT,
            "a stapler please, we've got someone coming in to staple the reports",
            ("transfer", "stapler"),
        ),
        (
            _HARBOUR,
            "May's tape pls, we've got one kid starting in the mailroom",
            ("transfer", "tape"),
        ),
        (_HARBOUR, "a ruler please, I've got one intern measuring the hall", ("transfer", "ruler")),
    ],
)
def test_the_request_stands(read: object, text: str, task: tuple[str, str]) -> None:
    frame = read(text)  # type: ignore[operator]
    assert frame.question is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == [task], frame


@pytest.mark.parametrize(
    "text",
    [
        "a stapler please. oh wait, got one already",
        "bring me a stapler. actually Wang just brought me one",
        "scissors pls. never mind, we've got one now",
        # the thing itself on its way: had, as before
        "a stapler please. actually I've got one coming from Wang",
    ],
)
def test_a_thing_had_already_still_withdraws(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.tasks == [], frame
