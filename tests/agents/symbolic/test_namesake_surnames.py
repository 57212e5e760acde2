"""Namesakes told apart by a word of one's name said later (fixer 82f, class 4): in an office
with two colleagues called Rosa (Rosa Álvarez, Rosa Lindqvist), "copy the consent form and drop
the copy with Rosa at reception - Álvarez, not Lindqvist" was asked about ("what do you mean by
'the copy'"), though the message says which Rosa. A part set off after the shared name that
says only the namesakes' other names ("- Álvarez", ", the Álvarez one", ", not Lindqvist")
picks the one (``reading/namesake_surnames.py``). The shared name said alone is asked about
("Who do you mean by 'Rosa'"), never the work around it, and an answer naming one settles it.

On copies of the default office and of Harbour with Sun Li and Lee Ming (default) or Rose
Adeyemi and Pat Nowak (Harbour) renamed Rosa Álvarez and Rosa Lindqvist (Harbour keeps its
Mark Lindqvist)."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE, default_office
from helpers.reading import answered_reader, frame_reader
from helpers.renamed_offices import renamed


@functools.cache
def _default_rosas() -> Office:
    rosas = (("sun", "Rosa Álvarez", ("Rosa",)), ("lee", "Rosa Lindqvist", ("Rosa",)))
    return renamed(DEFAULT_FILE, rosas, "default with two Rosas")


@functools.cache
def _harbour_rosas() -> Office:
    rosas = (("rose", "Rosa Álvarez", ("Rosa",)), ("pat", "Rosa Lindqvist", ("Rosa",)))
    return renamed(HARBOUR_FILE, rosas, "harbour with two Rosas")


_default = frame_reader(_default_rosas, "mao")
_default_answered = answered_reader(_default_rosas, "mao")
_harbour = frame_reader(_harbour_rosas, "may")
_harbour_answered = answered_reader(_harbour_rosas, "may")
_plain = frame_reader(default_office, "mao")


def _got(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(str(t.kind), t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "got"),
    [
        # the class's analogue
        (
            "copy the consent form and drop the copy with Rosa at reception - Álvarez, not "
            "Lindqvist",
            [("copy", "document", "sun")],
        ),
        # variants: one word of the name, "the ... one", "not" alone, other verbs and things
        ("give my contract to Rosa, the Álvarez one", [("transfer", "document", "sun")]),
        ("give my contract to Rosa, not Lindqvist.", [("transfer", "document", "sun")]),
        ("copy my report and give the copy to Rosa - Lindqvist", [("copy", "document", "lee")]),
        ("give Rosa my contract, not Álvarez, thanks", [("transfer", "document", "lee")]),
    ],
)
def test_a_surname_said_later_picks_the_namesake(
    text: str, got: list[tuple[str, str, str]]
) -> None:
    assert _got(_default(text)) == got


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("take my umbrella to Rosa - Álvarez, not Lindqvist", "rose"),
        ("take my umbrella to Rosa, not Álvarez", "pat"),
        ("bring my umbrella over to Rosa, the Lindqvist one please", "pat"),
    ],
)
def test_a_surname_said_later_picks_the_namesake_harbour(text: str, who: str) -> None:
    frame = _harbour(text)
    assert [t.recipient for t in frame.tasks] == [who], frame


@pytest.mark.parametrize(
    "text",
    [
        "copy my report and give the copy to Rosa",
        "copy the consent form and drop the copy with Rosa at reception",
        "drop my contract with Rosa",
        # neighbour: a part that names nobody among the Rosas does not pick one
        "give my contract to Rosa, not Wang",
    ],
)
def test_the_shared_name_alone_is_asked_about(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [], frame
    assert (frame.question or "").startswith("Who do you mean by 'Rosa'"), frame


@pytest.mark.parametrize(
    ("text", "answer", "who"),
    [
        ("copy my report and give the copy to Rosa", "Rosa Álvarez", "sun"),
        ("copy the consent form and drop the copy with Rosa at reception", "Rosa Lindqvist", "lee"),
        ("drop my contract with Rosa", "Álvarez", "sun"),
    ],
)
def test_an_answer_naming_one_settles_it(text: str, answer: str, who: str) -> None:
    frame = _default_answered(text, [answer])
    assert [t.recipient for t in frame.tasks] == [who], frame


def test_an_answer_naming_one_settles_it_harbour() -> None:
    frame = _harbour_answered("take my umbrella to Rosa", ["Rosa Lindqvist"])
    assert [t.recipient for t in frame.tasks] == ["pat"], frame


def test_namesakes_in_the_default_office_too() -> None:
    # Liu Yang and Yang Lei share "Yang": "not Liu" leaves Yang Lei
    assert _got(_plain("give my contract to Yang, not Liu")) == [("transfer", "document", "yang")]
