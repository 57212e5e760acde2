"""British "sort" as a giving verb: "sort Wang a coffee", "sort Wang out with a coffee" get
the coffee for Wang, the first object being who receives it, as after "get" or "make"
(``english.yaml`` dative_verbs). On main the coffee went to the speaker. Neighbours: "sort
me a coffee" is still the speaker's, "sort a coffee for Zhang" Zhang's, and a statement of
the speaker's own ("I'll sort Wang a coffee myself") still asks nothing of the robot."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("sort Wang a coffee", "wang"),
        ("could you sort Zhang a coffee please", "zhang"),
        ("sort Wang out with a coffee", "wang"),
        ("can you sort me a coffee", "lin"),  # neighbour: the speaker, as before
        ("sort a coffee for Zhang", "zhang"),  # neighbour: "for" names them, as before
    ],
)
def test_default_sort_gives_to_its_first_object(text: str, recipient: str) -> None:
    assert [(t.item, t.recipient) for t in _default(text).tasks] == [("coffee", recipient)]


@pytest.mark.parametrize(
    "text", ["can you sort Bill a ruler", "sort Bill out with a ruler", "pls sort Rose a ruler"]
)
def test_harbour_sort_gives_a_thing_to_its_first_object(text: str) -> None:
    who = "bill" if "Bill" in text else "rose"
    tasks = _harbour(text).tasks
    assert [(t.item, t.recipient) for t in tasks] == [("ruler", who)], tasks


def test_the_speakers_own_plan_asks_nothing() -> None:
    assert _default("I'll sort Wang a coffee myself").tasks == []
