"""A service on "the X" said by someone who has no X ("Could you weigh the parcel?" from a
colleague with no parcel) asks whose it is (blind round 38's class: the requester's own was
tried, and there was none). The requester's own, or "my X", or a named owner's is read as
before; the answer to the question names the owner."""

from __future__ import annotations

import pytest

from helpers.parcel_desk import parcel_desk
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(parcel_desk, "petra")


@pytest.mark.parametrize(
    "text",
    [
        "Could you weigh the parcel?",
        "Please weigh the package for me",
        "weigh the parcel please",
    ],
)
def test_a_service_on_a_thing_the_requester_has_none_of_asks_whose(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question == "Whose parcel do you mean?", frame


@pytest.mark.parametrize(
    ("text", "who", "owner"),
    [
        ("Could you weigh the parcel?", "olive", "olive"),
        ("Please weigh the package for me", "nadia", "nadia"),
        ("Could you weigh Olive's parcel?", "petra", "olive"),
        ("Could you weigh my parcel?", "petra", "petra"),
    ],
)
def test_an_owner_known_or_said_keeps_its_reading(text: str, who: str, owner: str) -> None:
    frame = _frame(text, who)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("heat", "parcel", owner)]


@pytest.mark.parametrize(("answer", "owner"), [("Olive's", "olive"), ("It's Nadia's", "nadia")])
def test_the_answer_names_the_owner(answer: str, owner: str) -> None:
    frame = answered_reader(parcel_desk, "petra")("Could you weigh the parcel?", [answer])
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("heat", "parcel", owner, "petra")
    ]
