"""An owner's leave for a colleague to keep their thing ("Wang can keep my stapler for now",
"..., Wang can hang on to it") asks for nothing: answered in words, nothing done, no question.
It asked "Who should get your stapler?" or what to do. Asking for the thing back is still a
request, and "Wang can have my stapler" (which may ask for a hand-over) is left as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "zhang")
_harbour = frame_reader(harbour_office, "mark")


@pytest.mark.parametrize(
    ("office", "text"),
    [
        ("default", "I don't need my stapler back till Monday, Wang can hang on to it"),
        ("default", "Wang can keep my stapler for now"),
        ("default", "Hu is welcome to hold on to it till Friday"),
        ("harbour", "Grace can keep my ruler for now"),
        ("harbour", "I don't need my calculator back till Friday, Will can hang on to it"),
    ],
)
def test_an_owners_leave_is_words(office: str, text: str) -> None:
    frame = (_default if office == "default" else _harbour)(text)
    assert frame.tasks == [] and frame.question is None and frame.decline is not None, frame


@pytest.mark.parametrize(
    ("office", "text", "item"),
    [
        ("default", "I need my stapler back from Wang", "stapler"),
        ("harbour", "I need my ruler back from Grace", "ruler"),
    ],
)
def test_asking_for_it_back_is_a_request(office: str, text: str, item: str) -> None:
    frame = (_default if office == "default" else _harbour)(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", item)], frame


def test_a_leave_to_have_it_is_not_read_as_told() -> None:
    frame = _default("Wang can have my stapler")
    assert frame.decline is None or "can keep it" not in frame.decline, frame
