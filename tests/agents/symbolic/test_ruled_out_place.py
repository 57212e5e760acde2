"""A place ruled out beside a where-question ("where's Wang's stapler? not on his desk") is
where the speaker already looked: the question is answered in words as it is alone, and
nothing moves (it was met with "I'm not sure what you need": blind round 86's class; the
sentences here are the tests' own)."""

from __future__ import annotations

from pathlib import Path

import pytest

from assistantx.core.office import Office, load_office
from helpers.reading import frame_reader

_HARBOUR = Path(__file__).parents[3] / "dataset" / "offices" / "harbour" / "office.yaml"


def _harbour() -> Office:
    return load_office(_HARBOUR)


_default = frame_reader(load_office, "mao")
_harbour_frame = frame_reader(_harbour, "mark")


@pytest.mark.parametrize(
    ("text", "answer"),
    [
        ("where's Wang's stapler? not on his desk", "Wang Fang has a stapler"),
        ("where is Wang's stapler? it's not in his drawer", "Wang Fang has a stapler"),
        ("where's Zhang's stapler, it isn't at his desk", "Zhang Wei has a stapler"),
        ("where is Wang's stapler? not by the printer either", "Wang Fang has a stapler"),
    ],
)
def test_the_question_is_answered_as_alone(text: str, answer: str) -> None:
    frame = _default(text)
    assert frame.tasks == [], frame
    said = frame.question or frame.decline or ""
    assert answer in said, frame


@pytest.mark.parametrize(
    "text", ["where's May's tape? not in her drawer", "where is May's tape? it's not on her desk"]
)
def test_harbour_answers_the_same_as_the_bare_question(text: str) -> None:
    frame = _harbour_frame(text)
    bare = _harbour_frame(text.split("?")[0] + "?")
    assert frame.tasks == [] and frame.question == bare.question, frame
    assert frame.question is not None or frame.decline is not None


def test_a_request_after_the_remark_is_still_done() -> None:
    frame = _default("where's Wang's stapler? not on his desk. bring me Zhang's stapler")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "zhang", "mao")
    ], frame


def test_a_request_after_a_where_question_about_a_person_is_done() -> None:
    frame = _default("where's Wang? bring him my stapler")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "wang")
    ], frame
