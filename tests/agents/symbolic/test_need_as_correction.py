"""A correction said as someone's need of the thing (class 86m-1): "take my document to wang,
no wait, zhang needs it first" was read as a withdrawal ("I did nothing"); who needs "it" after
"no wait"/"sorry" is who the thing goes to instead, one task. The rule is about English (a
need verb with the pronoun of the thing just asked for, core.needed_instead), read alike by
the reader and the consent guard; a withdrawal ("no wait, forget it") still withdraws, and a
need of another thing or other news ("has it") corrects nobody."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from assistantx.runtime.recipients import _in_roles
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "may")


def _deliveries(frame: TaskFrame) -> list[tuple[str, str | None, str]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "can you take my document to wang, no wait, zhang needs it first",
        "take my document to wang. no wait, zhang needs it first",
        "take my document to wang, sorry, zhang wants it",
        "take my document to wang, no wait, give it to zhang",
        "take my document to wang. no wait, zhang",
        "take my document to wang, no wait, make that zhang",
    ],
)
def test_default_the_needer_is_the_new_recipient(text: str) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert _deliveries(frame) == [("transfer", "document", "zhang")], frame


@pytest.mark.parametrize(
    ("text", "to"),
    [
        ("could you take my calculator to mark, no wait, grace needs it first", "grace"),
        ("take my ruler to ray, sorry, hope needs it", "hope"),
        ("take my ruler to ray, no wait, dawn wants it today", "dawn"),
        # a name-word that is also a modal verb, lower-case
        ("take my ruler to ray, no wait, will needs it", "will"),
    ],
)
def test_harbour_the_needer_is_the_new_recipient(text: str, to: str) -> None:
    frame = _harbour(text)
    assert frame.question is None and frame.decline is None, frame
    assert _deliveries(frame) == [("transfer", frame.tasks[0].item, to)], frame


@pytest.mark.parametrize(
    ("text", "who", "to"),
    [
        ("can you take my document to wang, no wait, zhang needs it first", "mao", "zhang"),
        ("take my ruler to ray, no wait, will needs it", "may", "will"),
    ],
)
def test_the_consent_guard_reads_the_same_recipient(text: str, who: str, to: str) -> None:
    office = default_office() if who == "mao" else harbour_office()
    assert _in_roles(office, text, who) == {to}


@pytest.mark.parametrize(
    "text",
    [
        "take my document to wang, no wait, forget it",
        "take my document to wang, no wait, never mind",
    ],
)
def test_a_withdrawal_still_withdraws(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [], frame


def test_other_news_after_sorry_corrects_nobody() -> None:
    # "has it" is news about Joy, not whom the ruler goes to
    frame = _harbour("take my ruler to ray, sorry, joy has it")
    assert [t.recipient for t in frame.tasks] != ["joy"], frame
    assert _in_roles(harbour_office(), "take my ruler to ray, sorry, joy has it", "may") == {"ray"}
