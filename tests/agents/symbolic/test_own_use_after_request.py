"""After a request, "need to <verb> it" is what the speaker will do with the thing (fixer 84k,
class 3: "grab my lunch from the fridge would you, need to eat it before 2" was declined
"Sorry, I won't eat anything"). A need or plan of the speaker's, subject said or not, to do
something with "it"/"them" after a request is its reason, context only; the request is done
(``reading/screen/own_use.py``). The office's own services ("need to heat it"), a thing named
anew ("eat my lunch") and a colleague's thing taken to be eaten read as before."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_default = frame_reader(default_office, "lee")  # Lee's lunch is in the fridge
_harbour = frame_reader(harbour_office, "will")  # so is Will's


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    assert frame.question is None and frame.decline is None
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        # the class's analogue, and with its subject said
        "grab my lunch from the fridge would you, need to eat it before 2",
        "grab my lunch from the fridge would you, I need to eat it before 2",
        # variants: other plans, other verbs
        "bring me my lunch please, have to finish it before the 1 o'clock",
        "could you fetch my lunch from the fridge? gotta eat it at my desk today",
        "bring my lunch over please, I want to eat it while it's hot",
    ],
)
def test_what_the_speaker_will_do_with_it_is_context_on_the_default_office(text: str) -> None:
    assert _tasks(_default(text)) == [("transfer", "lunch", "lee", "lee")]


@pytest.mark.parametrize(
    "text",
    [
        "could you fetch my lunch from the fridge, need to eat it before my 1 o'clock",
        "bring me my lunch pls, I've got to eat it before the site visit",
    ],
)
def test_what_the_speaker_will_do_with_it_is_context_on_harbour(text: str) -> None:
    assert _tasks(_harbour(text)) == [("transfer", "lunch", "will", "will")]


def test_the_offices_own_service_is_still_asked() -> None:
    # must not change: "need to heat it" asks the heating the office offers
    assert _tasks(_default("bring me my lunch please, need to heat it")) == [
        ("heat", "lunch", "lee", "lee")
    ]
    assert _tasks(_default("I need to heat my lunch")) == [("heat", "lunch", "lee", "lee")]


@pytest.mark.parametrize(
    ("read", "text"),
    [
        # must not change: the thing named anew, nothing asked before it
        (_default, "eat my lunch"),
        (_harbour, "eat my lunch"),
        # must not change: a colleague's lunch taken to be eaten
        (_default, "grab Zhang's lunch from the fridge, need to eat it"),
        (_harbour, "grab Grace's lunch from the fridge, need to eat it"),
    ],
)
def test_eating_asked_or_a_colleagues_lunch_is_still_declined(read: ReadFrame, text: str) -> None:
    frame = read(text)
    assert frame.tasks == [] and frame.decline is not None and "won't eat" in frame.decline
