"""A thing taken from one colleague to another who lacks it (class 72j-5): "Mark has no
calculator, can you take Dawn's calculator to him" asked "Dawn Sato already has their
calculator" ("him" read as Dawn); "Rose wants her umbrella back, can you take it from Pat to
her" asked "Rose Adeyemi already has their umbrella". The one a thing is taken from (its owner
said right before it, or after "from") is its source, never whom "him"/"her" means; the
person named in the first clause is the recipient. Rose's own umbrella taken from Pat, who
the office lists no umbrella of, is taken from Pat as whoever has it now."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_harbour = frame_reader(harbour_office, "will")
_default = frame_reader(default_office, "zhang")


@pytest.mark.parametrize(
    ("text", "task"),
    [
        (
            "Mark has no calculator, can you take Dawn's calculator to him",
            ("calculator", "dawn", "mark"),
        ),
        ("Mark says he needs tape, can you take some from Jack to him", ("tape", "jack", "mark")),
        ("Mark has no ruler, can you take Grace's ruler to him", ("ruler", "grace", "mark")),
        ("Mark has no calculator, can you take Dawn's to him", ("calculator", "dawn", "mark")),
        ("Mark has no ruler, could you bring Grace's to him", ("ruler", "grace", "mark")),
    ],
)
def test_the_source_is_not_whom_the_pronoun_means(text: str, task: tuple[str, str, str]) -> None:
    frame = _harbour(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [("transfer", *task)]


@pytest.mark.parametrize(
    ("text", "source"),
    [
        ("Rose wants her umbrella back, can you take it from Pat to her", "pat"),
        ("Rose needs her umbrella back, take it from Grace", "grace"),
    ],
)
def test_an_own_thing_back_from_one_who_has_it_now(text: str, source: str) -> None:
    frame = _harbour(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient, t.source) for t in frame.tasks] == [
        ("transfer", "umbrella", "rose", "rose", source)
    ]


@pytest.mark.parametrize(
    ("text", "to"),
    [
        ("Lee has no stapler, can you take Wang's stapler to him", "lee"),
        ("Lee has no stapler, can you take Wang's to him", "lee"),
        # a colleague named, not a pronoun: that colleague
        ("Lee has no stapler, can you take Wang's to Chen", "chen"),
    ],
)
def test_on_the_default_office_too(text: str, to: str) -> None:
    frame = _default(text)
    assert frame.question is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "wang", to)]


def test_a_return_with_nobody_it_is_taken_from_is_still_asked() -> None:
    # nothing says who has it: the office says Rose does
    frame = _harbour("Rose wants her umbrella back, can you bring it to her")
    assert frame.tasks == [] and frame.question is not None, frame


def test_two_colleagues_named_as_recipients_still_ask() -> None:
    frame = _harbour("Mark and Rose have no ruler, can you take Grace's ruler to him")
    assert frame.tasks == [] and frame.question is not None, frame
