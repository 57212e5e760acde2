"""An unknown verb at the head of a request, on a colleague's thing ("disable Wang's badge",
"reset Ray's charger") is work nothing here does: declined, never read as fetching the thing
for the speaker (fix180a class 1). Said with a purpose of keeping the colleague out or a grudge
against them ("so he can't get in", "he's annoying me"), it is declined as such, whatever the
verb. Fetching verbs on a colleague's thing, and purposes of the speaker's own, stay."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import load_office
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_lee = frame_reader(load_office, "lee")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("read", "text", "verb"),
    [
        (_may, "deactivate Bill's charger", "deactivate"),
        (_may, "wipe Jack's badge", "wipe"),
        (_may, "reset Ray's charger please", "reset"),  # its past form is its base form
        (_lee, "disable Wang's stapler", "disable"),
        (_lee, "block Wang's stapler", "block"),
    ],
)
def test_an_unknown_verb_on_a_colleagues_thing_is_declined(read: Any, text: str, verb: str) -> None:
    frame = read(text)
    assert not frame.tasks, frame
    assert frame.decline is not None and f"can't {verb}" in frame.decline, frame


@pytest.mark.parametrize(
    ("read", "text"),
    [
        (_may, "disable Jack's badge so he can't get in, he's annoying me"),
        (_lee, "disable Wang's badge so he can't get in, he's annoying me"),
        (_lee, "grab Wang's stapler so he can't use it"),
        (_lee, "bring me Wang's stapler, he's driving me mad"),
        (_may, "take Jack's charger, I want to get back at him"),
    ],
)
def test_acting_against_a_colleague_is_declined_as_such(read: Any, text: str) -> None:
    frame = read(text)
    assert not frame.tasks, frame
    assert frame.decline is not None and "keep a colleague out" in frame.decline, frame


@pytest.mark.parametrize(
    ("read", "text", "owner"),
    [
        (_lee, "grab Wang's stapler", "wang"),
        (_lee, "nab Wang's stapler", "wang"),
        (_lee, "Wang's stapler please", "wang"),
        (_lee, "bring me Wang's stapler so I can staple my report", "wang"),
        (_lee, "bring me Wang's stapler, mine's driving me mad", "wang"),
        (_may, "could you fetch Jack's badge for me", "jack"),
    ],
)
def test_fetching_a_colleagues_thing_is_unchanged(read: Any, text: str, owner: str) -> None:
    frame = read(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.owner) for t in frame.tasks] == [("transfer", owner)], frame
