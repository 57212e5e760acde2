""" "<a thing> would be great" asks for the thing, also where the thing's name is several words
whose first is also a verb ("some wet wipes would be great": "wet" had been read as the verb of
a plural subject, and the whole said as a statement, "Noted."). The speech act skips the
first word of a name of the office's things as it skips a one-word name."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_wang = frame_reader(default_office, "wang")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("some wet wipes would be great, spilled coffee all over the desk", "wipes"),
        ("some wet wipes would be lovely", "wipes"),
        ("a data cable would be great, mine is frayed", "data_cable"),
        ("some clean wipes would be great", "wipes"),  # must not change
    ],
)
def test_a_thing_that_would_be_great_is_brought(text: str, item: str) -> None:
    frame = _wang(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, "wang")], frame


def test_a_statement_about_a_thing_is_still_told() -> None:
    # must not change: how a thing is, told
    frame = _wang("the data cable works fine now")
    assert frame.tasks == [] and frame.question is None, frame
