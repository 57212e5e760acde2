"""Three readings from round 247's finds lab, each by its mechanism:
- a name the office writes for a thing ("scales" of the weighing scales) is that thing, never
  the plural made from another thing's name ("scale" of the photo scale), which brought the
  photo scale;
- what a purpose's object holds and a preposition left at its end ("something to weigh this
  bag *of nails on*") are part of the purpose, never a thing asked for (the nails were read as
  a colleague's small finds, and whose was asked);
- a record's want said after the request ("..., the register wants weights in grams") says
  why it is asked; "the register" was asked about as if it were a person."""

from __future__ import annotations

import pytest

from helpers.finds_bench import finds_bench
from helpers.reading import frame_reader

_frame = frame_reader(finds_bench, "bo")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("bring me hana's scales pls", "weighing_scales"),
        ("bring me Hana's scale", "photo_scale"),
        ("bring me hana's scale bars", "photo_scale"),
        ("can I borrow hanas balance", "weighing_scales"),
    ],
)
def test_a_name_as_written_beats_a_plural_made_from_another(text: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, "hana", "bo")
    ], frame


_WEIGHING_PURPOSES = {
    "I need something to weigh this bag of nails on": "weighing_scales",
    "need something to weigh my box of coins on": "weighing_scales",
    "something to weigh these nails on pls": "weighing_scales",
}


@pytest.mark.parametrize("text", sorted(_WEIGHING_PURPOSES))
def test_what_a_purposes_object_holds_is_no_thing_asked(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", _WEIGHING_PURPOSES[text], "bo")
    ], frame
    assert frame.question is None, frame


@pytest.mark.parametrize(
    "text",
    [
        "I need something to weigh this bag of nails on. the register wants weights in grams",
        "can you bring me a finds bag, the register wants everything bagged",
        "bring me a finds bag as the database needs every find bagged",
    ],
)
def test_a_records_want_after_the_request_is_its_reason(text: str) -> None:
    frame = _frame(text)
    assert len(frame.tasks) == 1 and frame.question is None, frame
    assert frame.tasks[0].recipient == "bo", frame


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("bring me a finds bag, Uwe needs one too", None),  # a colleague's want: its own part
        ("the register wants weights in grams", None),  # said alone: nothing asked before
    ],
)
def test_wants_of_people_or_said_alone_are_not_dropped(text: str, recipient: str | None) -> None:
    frame = _frame(text)
    assert not (len(frame.tasks) == 1 and frame.tasks[0].recipient == "bo"), frame
