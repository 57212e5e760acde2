"""A size or format word selects the facility that offers it (round 143 class 4): an A3 printer
prints and a plotter makes large-format plots; "printed big, A1 if poss" fits only the
plotter, whose own words say a large format and A0. Where the verb is the other facility's
("print" is only the printer's), the two conflict and which is asked, never the A3 printer at
A1; where the verb is shared by both, the size chooses the plotter. The answer to the
question runs the one service it names, never both. No size word, or one both fit, reads as
before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.plan_room import plan_room, shared_verb_plan_room
from helpers.reading import OfficeOf, answered_reader, frame_reader

_studio = frame_reader(plan_room, "tove")
_shared = frame_reader(shared_verb_plan_room, "tove")
_answered = answered_reader(plan_room, "tove")

_WHICH = "Which do you mean: print or large-format plot?"

_SIZED = [
    "get my plans printed big for the crit, A1 if poss",
    "print my poster big, A0 if you can",
    "get my drawings printed large format",
    "can you print my elevations poster size",
]


@pytest.mark.parametrize("text", _SIZED)
def test_a_size_only_the_other_facility_does_is_asked(text: str) -> None:
    frame = _studio(text)
    assert frame.tasks == [] and frame.question == _WHICH, frame


@pytest.mark.parametrize("text", _SIZED)
def test_a_size_chooses_among_services_of_one_verb(text: str) -> None:
    frame = _shared(text)
    assert frame.question is None, frame
    assert [(t.item, t.operation) for t in frame.tasks] == [("drawing", "plot")]


@pytest.mark.parametrize(
    ("answer", "operation"),
    [
        ("large-format plot", "plot"),
        ("the plotter", "plot"),
        ("plot it please", "plot"),
        ("print", "print"),
    ],
)
def test_the_answer_runs_the_one_service_named(answer: str, operation: str) -> None:
    frame = _answered(_SIZED[0], [answer])
    assert [(t.item, t.operation) for t in frame.tasks] == [("drawing", operation)], frame


# -- must not change ---------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("print my drawings", "print"),
        ("print my plans A4", "print"),  # both do A4: the verb's own
        ("plot my drawings", "plot"),
        ("plot my plans A1", "plot"),
    ],
)
def test_no_size_or_one_the_verbs_facility_does_reads_as_before(text: str, operation: str) -> None:
    frame = _studio(text)
    assert frame.question is None, frame
    assert [(t.item, t.operation) for t in frame.tasks] == [("drawing", operation)]


def test_a_facility_named_settles_a_shared_verb() -> None:
    frame = _shared("print my drawings on the printer")
    assert [(t.item, t.operation) for t in frame.tasks] == [("drawing", "print")]


def test_a_shared_verb_alone_is_asked_never_both() -> None:
    frame = _shared("print my drawings")
    assert frame.tasks == [] and frame.question == _WHICH, frame


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        (default_office, "chen", "print my document big please"),
        (harbour_office, "may", "print my file big please"),
    ],
)
def test_a_size_no_facility_says_chooses_nothing(office: OfficeOf, who: str, text: str) -> None:
    frame = frame_reader(office, who)(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == [("print", "file")]
