"""A thing said to be where it is kept, then the speaker's own need of it joined by "and"
("the label maker is still locked in the stationery cupboard and I need it at my desk", "my
lunch is stuck in the fridge and I need it up here") is a request to fetch it for the
speaker: the need is cut from the statement, and its "it" is the thing the statement named.
A statement alone ("..., fyi"), an open offer ("if anyone needs it"), a need with no speaker
("and needs heating") and a statement of a fault ("the printer is jammed and I need ...")
stay as they were."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_HARBOUR = frame_reader(harbour_office, "will")
_DEFAULT = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        (
            "the label maker is still locked in the stationery cupboard and I need it at my desk",
            "label_maker",
            None,
        ),
        ("my lunch is stuck in the fridge and I need it up here", "lunch", "will"),
        ("my lunch is in the fridge and I want it at my desk", "lunch", "will"),
        ("the calculator is sitting in the lounge and I need it here", "calculator", None),
        ("Pat's tape is in the post room and I need it", "tape", "pat"),
    ],
)
def test_harbour_the_need_beside_the_place_fetches_it(
    text: str, item: str, owner: str | None
) -> None:
    frame = _HARBOUR(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, owner, "will")], frame


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("my lunch is stuck in the fridge and I need it up here", "lunch", "lee"),
        ("my lunch is in the fridge and we want it at my desk", "lunch", "lee"),
        ("Zhang's stapler is on his desk and I need it", "stapler", "zhang"),
    ],
)
def test_default_office_the_need_beside_the_place_fetches_it(
    text: str, item: str, owner: str | None
) -> None:
    frame = _DEFAULT(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, owner, "lee")], frame


@pytest.mark.parametrize(
    ("reader", "text"),
    [
        (_HARBOUR, "the label maker is in the stationery cupboard, fyi"),
        (_HARBOUR, "my lunch is in the fridge if anyone needs it"),
        (_HARBOUR, "my lunch is in the fridge and I need nothing else"),
        (_HARBOUR, "my lunch is in the fridge and needs heating"),
        (_DEFAULT, "my lunch is in the fridge, fyi"),
        (_DEFAULT, "the printer is jammed and I need my file printed"),  # a fault, told
    ],
)
def test_must_not_change_statements_stay_words(reader: object, text: str) -> None:
    frame = reader(text)  # type: ignore[operator]
    assert not frame.tasks and frame.question is None, frame


async def test_end_to_end_the_lunch_comes_out_of_the_fridge() -> None:
    text = "my lunch is stuck in the fridge and I need it up here"
    run = await run_instruction(harbour_office(), "will", text)
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    assert run.sim.world.holder["lunch:will"] == "will", trace.summary
