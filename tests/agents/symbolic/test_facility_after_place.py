"""A facility named with where it stands ("kitchen coffee machine", "copy room printer") and
a state of being broken ("is leaking", "is broken", "has died", "keeps jamming") is a report
about the facility, answered in words; nothing moves. Before, "kitchen coffee machine is
leaking again ffs" was answered "Sorry, I'm not sure what you need"."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_mao = frame_reader(default_office, "mao")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("read", "text", "said"),
    [
        (_mao, "kitchen coffee machine is leaking again ffs", "the coffee machine is leaking"),
        (_mao, "the kitchen coffee machine is broken", "the coffee machine is broken"),
        (_mao, "the print room printer keeps jamming", "the printer keeps jamming"),
        (_mao, "kitchen fridge has died", "the fridge has died"),
        (_mao, "the upstairs microwave has packed up", "the microwave has packed up"),
        (_may, "copy room printer is broken", "the printer is broken"),
        (_may, "the kitchen kettle has died again", "the kettle has died"),
        (_may, "copy room scanner keeps jamming", "the scanner keeps jamming"),
    ],
)
def test_a_placed_facility_out_of_order_is_a_report(read: ReadFrame, text: str, said: str) -> None:
    frame = read(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and f"Thanks for letting me know {said}." in frame.decline
    assert "can't repair" in frame.decline


@pytest.mark.parametrize(
    ("read", "text", "item"),
    [
        (_mao, "the coffee machine is working again, can I have a coffee", "coffee"),
        (_mao, "make me a coffee in the kitchen", "coffee"),
        (_may, "make me a tea in the kitchen please", "tea"),
    ],
)
def test_a_request_beside_or_at_the_place_is_still_made(
    read: ReadFrame, text: str, item: str
) -> None:
    frame = read(text)
    assert [t.item for t in frame.tasks] == [item], frame


def test_an_unplaced_report_reads_as_before() -> None:
    frame = _mao("the printer is jammed again ugh")
    assert frame.decline is not None
    assert "Thanks for letting me know the printer is jammed." in frame.decline
