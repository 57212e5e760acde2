"""A name from outside the office after "from" in a need, and a "for him" pointing back to a
described outsider (``reading.described_outsider``): "I need a coffee for a visitor from
Shenzhen" asked whom 'Shenzhen' means, and "we've got a client visiting from Dublin, could
you get me a coffee for him?" whom 'him' means. The capitalised word after an outsider's
"from" is where they come from; "for him" with no colleague named is that outsider, and the
requester, who asked for it, receives it to pass on."""

from __future__ import annotations

import pytest

from assistantx.evaluation import metrics
from helpers.dataset_offices import default_office, harbour_office
from helpers.one_episode import ppdr_episode
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "lin")
_HARBOUR = frame_reader(harbour_office, "will")

Read = tuple[str, str | None, str]  # kind, item, recipient


def _tasks(frame: object) -> list[Read]:
    return [(t.kind, t.item, t.recipient) for t in getattr(frame, "tasks", [])]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I need a coffee for a visitor from Shenzhen", "coffee"),
        ("I need a snack for a visiting instructor from Verbier", "snack"),
        ("I need a coffee for a guest from Lagos", "coffee"),
        ("we've got a client visiting from Dublin, could you get me a coffee for him?", "coffee"),
        (
            "We've got an instructor visiting from Shenzhen tomorrow. Could you get me a snack "
            "for him?",
            "snack",
        ),
        ("a supplier is coming over from Leeds today, can you get me a coffee for her?", "coffee"),
        ("our auditor is visiting from Leeds, bring me a coffee for them", "coffee"),
        ("we have a visitor, I need a coffee for him", "coffee"),
    ],
)
def test_default_the_requester_receives(text: str, item: str) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [("produce", item, "lin")], frame


@pytest.mark.parametrize(
    "text",
    [
        "I need a tea for a visitor from Oslo",
        "we've got a guest coming over from Cork, could you get me a tea for her?",
    ],
)
def test_harbour_the_requester_receives(text: str) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [("produce", "tea", "will")], frame


@pytest.mark.parametrize(
    ("text", "asked"),
    [
        # a capitalised word after "from" beside no described outsider: still someone to find
        ("get me the stapler from Bob", "I don't know anyone called 'Bob'"),
        ("I need a coffee for Bob from Leeds", "I don't know anyone called 'Bob'"),
        # "for him" with nobody described, or no one said to take it: whom is asked
        ("could you get me a coffee for him?", "Who do you mean by 'him'?"),
        ("a client is visiting, could you bring a coffee for him?", "Who do you mean by 'him'?"),
        ("a client is here, take him a coffee", "Who do you mean by 'him'?"),
        # the outsider as the one handed it: offered to the requester instead, as before
        ("bring a coffee to the visitor", "I hand things only to people of this office"),
    ],
)
def test_default_still_asked(text: str, asked: str) -> None:
    frame = _DEFAULT(text)
    assert frame.question is not None and frame.question.startswith(asked), frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("get Wang a coffee", [("produce", "coffee", "wang")]),
        # a colleague named: "him" is the colleague, as before
        ("Wang is in, could you get a coffee for him?", [("produce", "coffee", "wang")]),
    ],
)
def test_default_a_colleague_receives(text: str, tasks: list[Read]) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == tasks, frame


async def test_the_coffee_comes_to_the_requester() -> None:
    text = "we've got a client visiting from Dublin, could you get me a coffee for him?"
    episode = await ppdr_episode(default_office(), "lee", text, [{"holds": ["lee", "coffee:lee"]}])
    assert metrics.success(episode), (episode.milestones, episode.trace.summary)
    assert metrics.wrong_handovers(episode) == []
