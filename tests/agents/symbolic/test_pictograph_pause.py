"""A pictograph between two words ends the clause before it, as a comma would ("Wang's
forgotten his scissors again 😩 can you take him mine": Wang gets the speaker's scissors).
On main the face was only taken out, "again can you take him mine" ran into one clause, and
the reader asked about Wang's own scissors ("Wang Fang has no scissors of their own").
Neighbours: the same request with no one named before ("can you take her mine") still asks
who; a request with the face at its end reads as before (``reading.pictographs``)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")  # Lin keeps scissors


@pytest.mark.parametrize(
    "text",
    [
        "Wang's forgotten his scissors again 😩 can you take him mine",
        "Wang's forgotten his scissors again 🙄🙄 can you take him mine",
        "Wang forgot his scissors 🙄 could you bring him mine",
    ],
)
def test_default_a_face_between_clauses_ends_the_first(text: str) -> None:
    tasks = _default(text).tasks
    assert [(t.kind, t.item, t.owner, t.recipient) for t in tasks] == [
        ("transfer", "scissors", "lin", "wang")
    ], tasks


@pytest.mark.parametrize(
    ("who", "text", "item", "recipient"),
    [
        ("ken", "June's forgotten her charger again 🙄 can u take her mine", "charger", "june"),
        ("joy", "Bill's forgotten his ruler again 🙄 can you take him mine", "ruler", "bill"),
    ],
)
def test_harbour_a_face_between_clauses_ends_the_first(
    who: str, text: str, item: str, recipient: str
) -> None:
    tasks = frame_reader(harbour_office, who)(text).tasks
    assert [(t.kind, t.item, t.owner, t.recipient) for t in tasks] == [
        ("transfer", item, who, recipient)
    ], tasks


def test_no_one_named_before_is_still_asked() -> None:
    frame = _default("can you take her mine 🙄")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "'her'" in frame.question, frame.question
