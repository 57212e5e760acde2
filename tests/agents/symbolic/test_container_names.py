"""A colleague called by a word for a waste container ("Skip Larsen", called Skip; "Dang Bin",
called Bin): after "to" the name written with a capital is the colleague the thing goes to,
never the container declined ("Sorry, I won't put things in the skip"); in lower case with no
article ("give my report to skip") it is asked ("Do you mean Skip Larsen, or the skip?") and
the answer settles it; after an article ("in the skip") it is the container, declined as
before. The name before a finite verb ("Skip needs a ruler", "Bin needs a stapler") is its
subject, never the screen's verb ("skip ...": don't; "bin ...": dispose of). Office-agnostic:
harbour with a Skip, the default office (family name first) with a Bin, and the offices as
they are, where "skip" and "bin" are only words."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, ReadFrame, answered_reader, frame_reader
from helpers.renamed_offices import default_with_bin, harbour_with_skip

_skip = frame_reader(harbour_with_skip, "may")
_skip_answered = answered_reader(harbour_with_skip, "may")
_bin = frame_reader(default_with_bin, "lee")
_bin_answered = answered_reader(default_with_bin, "lee")


def _to(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.owner, t.recipient) for t in frame.tasks]


def _declined_as_disposal(frame: TaskFrame, container: str) -> None:
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and f"in the {container}" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("Send my file to Skip, he's updating the website.", "send_file"),  # the class
        ("give my report to Skip", "transfer"),
        ("could you take my document over to Skip please", "transfer"),
        ("pass my file to Skip, thanks", "send_file"),
    ],
)
def test_a_capitalised_container_name_after_to_is_the_colleague(text: str, kind: str) -> None:
    assert _to(_skip(text)) == [(kind, "may", "bill")]


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("send my file to Bin, he needs it for the meeting", "send_file"),
        ("please bring my document to Bin", "transfer"),
    ],
)
def test_default_office_a_colleague_called_bin(text: str, kind: str) -> None:
    assert _to(_bin(text)) == [(kind, "lee", "dang")]


@pytest.mark.parametrize(
    ("text", "asked"),
    [
        ("give my report to skip", "Do you mean Skip Larsen, or the skip?"),
        ("take my file to skip", "Do you mean Skip Larsen, or the skip?"),
    ],
)
def test_lower_case_after_to_is_asked(text: str, asked: str) -> None:
    frame = _skip(text)
    assert frame.tasks == [] and frame.decline is None and frame.question == asked, frame
    assert "bill" not in frame.question  # no internal id


def test_default_office_lower_case_bin_is_asked() -> None:
    frame = _bin("take my document to bin")
    assert frame.tasks == [] and frame.question == "Do you mean Dang Bin, or the bin?", frame


@pytest.mark.parametrize("answer", ["Skip Larsen", "Larsen", "skip larsen, my colleague"])
def test_the_answer_naming_the_colleague_delivers_to_them(answer: str) -> None:
    frame = _skip_answered("give my report to skip", [answer])
    assert _to(frame) == [("transfer", "may", "bill")]


def test_the_answer_naming_the_container_is_declined() -> None:
    _declined_as_disposal(_skip_answered("give my report to skip", ["the skip"]), "skip")
    _declined_as_disposal(_bin_answered("take my document to bin", ["the bin"]), "bin")


def test_default_office_the_answer_naming_bin_delivers() -> None:
    frame = _bin_answered("take my document to bin", ["Dang Bin"])
    assert _to(frame) == [("transfer", "lee", "dang")]


@pytest.mark.parametrize(
    ("reader", "text", "container"),
    [
        (_skip, "chuck my old drafts in the skip", "skip"),  # must not change
        (_skip, "stick my document into the skip", "skip"),
        (_bin, "put my cup in the bin", "bin"),
        (_bin, "chuck Wang's book in the bin", "bin"),
    ],
)
def test_the_container_after_an_article_is_declined_as_before(
    reader: ReadFrame, text: str, container: str
) -> None:
    _declined_as_disposal(reader(text), container)


@pytest.mark.parametrize(
    ("office", "who", "text", "container"),
    [
        (harbour_office, "may", "give my report to skip", "skip"),
        (default_office, "lee", "take my document to bin", "bin"),
    ],
)
def test_where_nobody_is_so_called_the_word_is_the_container(
    office: OfficeOf, who: str, text: str, container: str
) -> None:
    _declined_as_disposal(frame_reader(office, who)(text), container)


def test_the_name_before_a_dative_object_is_the_recipient() -> None:
    assert _to(_skip("send Skip my file")) == [("send_file", "may", "bill")]  # must not change
    assert _to(_bin("give Bin my book")) == [("transfer", "lee", "dang")]


@pytest.mark.parametrize(
    ("reader", "text", "offer"),
    [
        (_skip, "Skip needs a ruler", "Shall I bring a ruler to Skip Larsen?"),
        (_bin, "Bin needs a stapler", "Shall I bring a stapler to Dang Bin?"),
    ],
)
def test_the_name_as_subject_is_no_verb(reader: ReadFrame, text: str, offer: str) -> None:
    frame = reader(text)
    assert frame.tasks == [] and frame.decline is None and frame.question == offer, frame


@pytest.mark.parametrize(
    ("reader", "text", "said"),
    [
        (_skip, "skip printing it", "OK, I won't"),  # the verb, called off
        (_bin, "bin my old notes", "won't bin"),  # the verb, declined
    ],
)
def test_the_verb_in_lower_case_first_is_still_the_verb(
    reader: ReadFrame, text: str, said: str
) -> None:
    frame = reader(text)
    assert frame.tasks == [] and frame.decline is not None and said in frame.decline, frame
