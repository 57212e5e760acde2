"""A fault told the chat way ("printer jammed again") with who deals with it ("Wang is on it",
"Zhang's looking at it", "Gao has it in hand") is a statement: answered in words, nothing
done, nothing asked. "Wang is on it" was read as a whereabouts ("Wang Fang is away"); "printer
jammed again" asked what to do. Asking the assistant to get someone to look at it is still a
request, and a thing that did something to a thing ("jammed my strip") is not a bare fault."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "zhang")
_harbour = frame_reader(harbour_office, "mark")


@pytest.mark.parametrize(
    ("office", "text", "who"),
    [
        ("default", "printer jammed again, Wang is on it", "Wang Fang"),
        ("default", "coffee machine's down, Zhang's looking at it", "Zhang Wei"),
        ("default", "scanner jammed again, Hu is on it", "Hu Jing"),
        ("default", "kettle died again, Gao has it in hand", "Gao Min"),
        ("default", "the fridge broke down this morning, Wang is sorting it", "Wang Fang"),
        ("harbour", "laminator jammed again, Pat is on it", "Pat Nowak"),
        ("harbour", "the kettle died, Grace has it in hand", "Grace Huang"),
    ],
)
def test_a_fault_someone_deals_with_is_words(office: str, text: str, who: str) -> None:
    frame = (_default if office == "default" else _harbour)(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and f"{who} is dealing with it" in frame.decline, frame
    assert "away" not in frame.decline, frame


def test_a_bare_fault_alone_is_told_with_what_cannot_be_done() -> None:
    frame = _default("printer jammed again")
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "can't repair" in frame.decline, frame


def test_a_whereabouts_is_still_read_as_one() -> None:
    frame = _default("Wang is on leave")
    assert frame.decline is not None and "away" in frame.decline, frame


def test_asking_to_get_someone_to_look_is_no_statement() -> None:
    frame = _default("printer jammed again, can you get Wang to look at it?")
    assert frame.tasks == [] and frame.question is not None, frame


def test_what_a_thing_did_to_a_thing_is_not_a_bare_fault() -> None:
    frame = _default("the scanner jammed my strip")
    assert frame.decline is None or "Thanks for letting me know" not in frame.decline, frame
