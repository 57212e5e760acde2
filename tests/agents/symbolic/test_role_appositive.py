"""A colleague named in apposition to their role ("get the duty manager, Frank, to sign my
report", "could the night porter, Li, bring me a coffee") is the one named: the role only
describes them, so it is neither asked about ("what do you mean by 'the duty'?") nor read as
someone else the office calls by that role word. A role said with no name is read as before
(asked where nobody holds it), and a thing named before a comma is no role."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import load_office
from helpers.courier_room import courier_room
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_lee = frame_reader(load_office, "lee")
_will = frame_reader(harbour_office, "will")
_kit = frame_reader(courier_room, "kit")


@pytest.mark.parametrize(
    ("read", "text", "kind", "actor"),
    [
        # "manager" is Mao's title in the default office: the name after it decides
        (_lee, "Get the duty manager, Wang, to sign my incident report.", "sign", "wang"),
        (_lee, "ask the head chef, Wang, to sign my form", "sign", "wang"),
        (_lee, "get our office manager, Zhang, to stamp my letter", "seal", "zhang"),
        (_lee, "Please ask our head of finance, Dr. Zhang, to sign my document", "sign", "zhang"),
        (_will, "Get the duty manager, Mark, to sign my incident report.", "sign", "mark"),
        (_will, "could you ask the night porter, Rose, to sign my timesheet", "sign", "rose"),
        (_kit, "get the duty manager, Ana, to sign my form.", "sign", "ana"),
    ],
)
def test_the_name_after_a_role_is_who_does_it(read: Any, text: str, kind: str, actor: str) -> None:
    frame = read(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.actor) for t in frame.tasks] == [(kind, actor)], frame


def test_a_role_named_before_a_receiver_is_the_receiver() -> None:
    frame = _lee("take my document to our new intern, Wang, and bring me a coffee")
    assert frame.question is None, frame
    assert [t.recipient for t in frame.tasks][:1] == ["wang"], frame


def test_a_doer_named_after_a_role_reads_as_the_name_alone() -> None:
    # whatever "could Lee bring me a coffee" makes of Lee, the porter's role changes nothing
    plain = _lee("could Wang bring me a coffee")
    described = _lee("could the night porter, Wang, bring me a coffee")
    assert described.question == plain.question and described.decline == plain.decline
    assert [(t.kind, t.actor, t.recipient) for t in described.tasks] == [
        (t.kind, t.actor, t.recipient) for t in plain.tasks
    ]


def test_a_role_with_no_name_where_nobody_holds_it_is_asked() -> None:
    frame = _kit("get the manager to sign my form")
    assert not frame.tasks and frame.question is not None, frame


def test_a_thing_before_the_comma_is_no_role() -> None:
    # "the stapler, Wang, ...": a thing and whom the speaker addresses, never "Wang" alone
    frame = _lee("give the stapler, Wang, to Zhang")
    assert not any(t.recipient == "wang" for t in frame.tasks), frame
