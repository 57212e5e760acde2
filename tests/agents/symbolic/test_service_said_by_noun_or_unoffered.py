"""Services said by nouns, through a pronoun, or not offered at all (fixer 189b).

- Class 2: an operation's verb said as a noun after "go for" / "book in for" asks for the
  operation on the thing, also where the thing is "it", said before ("the strings on my racket
  are shot, can it go for a restring?": before, asked what "a restring" meant;
  ``reading.due_service``).
- Class 3: a verb no service of the office does, on a particular thing said with "the", also
  "for me" after it and also a thing the office does not list ("please lacquer the Amati copy
  for me"): declined (nothing here does that work), never a question or a fetch; "the
  <Capitalised name> copy" is a thing, not the copy operation's product
  (``screen.unknown_work``)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.glaze_works import glaze_works
from helpers.reading import frame_reader

_works = frame_reader(glaze_works, "lee")
_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "item", "operation"),
    [
        ("the strings on my racket are shot, can it go for a restring?", "racket", "restring"),
        ("the handle on my knife is loose, can it go for a sharpen", "knife", "sharpen"),
        ("book my racket in for a restring", "racket", "restring"),
        ("can you book my racket in for a restring", "racket", "restring"),
        # must not change
        ("can my racket go for a restring", "racket", "restring"),
        ("my racket is due a restring", "racket", "restring"),
        ("my knife needs a sharpen", "knife", "sharpen"),
    ],
)
def test_the_operation_said_as_a_noun_runs_on_the_thing(
    text: str, item: str, operation: str
) -> None:
    frame = _works(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        ("heat", item, "lee", "lee", operation)
    ], frame
    assert frame.question is None, frame


def test_a_pronoun_going_for_no_service_is_left_as_said() -> None:
    frame = _works("my racket is shot, can it go for a walk")
    assert not frame.tasks, frame


@pytest.mark.parametrize(
    "text",
    [
        "please lacquer the violin for me",
        "please lacquer the Amati copy for me",
        "please varnish the Amati copy",
        "please tune the violin",
    ],
)
def test_work_nothing_here_does_on_a_thing_is_declined(text: str) -> None:
    frame = _works(text)
    assert not frame.tasks, frame
    assert frame.question is None, frame
    assert frame.decline is not None and "nothing in this office does that" in frame.decline


@pytest.mark.parametrize(
    "text",
    ["please lacquer the Amati copy for me", "please varnish the desk for me"],
)
def test_work_nothing_here_does_is_declined_in_the_default_office(text: str) -> None:
    frame = _default(text)
    assert not frame.tasks, frame
    assert frame.decline is not None and "nothing in this office does that" in frame.decline


@pytest.mark.parametrize(
    ("text", "kind", "operation"),
    [
        # must not change: a fetch said with a particle, the office's own work on a thing
        ("could you track down a stapler for me", "transfer", None),
        ("please copy the report for me", "copy", None),
    ],
)
def test_errands_and_offered_work_are_read_as_before(
    text: str, kind: str, operation: str | None
) -> None:
    frame = _default(text)
    assert [(t.kind, t.operation) for t in frame.tasks] == [(kind, operation)], frame
