"""A colleague's thing said to need one of the office's services goes back to its owner
(fix103h, class 4's analogue; ``reading.owners_need``): "Olek's 4-gas is due a bump test"
said by Ines tested Olek's monitor and handed it to Ines. The need is the owner's; the
speaker who wants the result says so ("for me", "bring it to me"), and a request's own verb
("copy Zhang's contract", as the default office's tests assert) is the speaker's want. One
rule for every operation; the owner is asked before their thing is taken."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from helpers.reading import frame_reader
from helpers.seed_lab import seed_lab

_lab = frame_reader(seed_lab, "ines")


def _lab_tasks(text: str) -> list[tuple[str | None, str | None, str]]:
    return [(t.item, t.owner, t.recipient) for t in _lab(text).tasks]


@pytest.mark.parametrize(
    "text",
    ["Olek's 4-gas is due a bump test", "Olek's gas monitor needs a bump test"],
)
def test_a_colleagues_monitor_due_its_test_goes_back_to_them(text: str) -> None:
    assert _lab_tasks(text) == [("gas_monitor", "olek", "olek")]


@pytest.mark.parametrize(
    ("office", "text", "requester", "task"),
    [
        (
            "default",
            "Zhang's contract needs copying",
            "lee",
            ("copy", "document", "zhang", "zhang"),
        ),
        ("default", "Wang's report needs a copy", "lee", ("copy", "document", "wang", "wang")),
        ("harbour", "Mark's document needs a scan", "will", ("copy", "document", "mark", "mark")),
        ("harbour", "Mark's document needs printing", "will", ("print", "file", "mark", "mark")),
    ],
)
def test_a_colleagues_paper_needing_work_goes_back_to_them(
    office: str, text: str, requester: str, task: tuple[str, str, str, str]
) -> None:
    assert tasks_of(office, text, requester) == [task]


# -- must not change: the speaker's want said, or a request's own verb ----------------------
@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("Olek's 4-gas is due a bump test, bring it to me after", "ines"),
        ("bump test Olek's 4-gas", "ines"),
    ],
)
def test_the_speakers_want_keeps_the_speaker(text: str, recipient: str) -> None:
    assert _lab_tasks(text) == [("gas_monitor", "olek", recipient)]


@pytest.mark.parametrize(
    "text",
    [
        "copy Zhang's contract",
        "Zhang's contract needs copying for me",
        "can you copy Zhang's contract",
    ],
)
def test_a_request_for_the_work_is_the_speakers(text: str) -> None:
    assert tasks_of("default", text, "lee") == [("copy", "document", "zhang", "lee")]


def test_a_request_about_it_after_the_need_keeps_the_speaker() -> None:
    # the speaker goes on to ask for "it": as the answered owner's lunch in
    # test_mine_answers_whose ("lunch needs heating, sort it pls" + "Lee's")
    assert tasks_of("harbour", "Mark's document needs a scan, can you take it over", "will") == [
        ("copy", "document", "mark", "will")
    ]
