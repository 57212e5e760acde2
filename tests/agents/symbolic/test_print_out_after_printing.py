"""A service's product said by its verb as a noun after the service was asked ("print my file
and take the print-out to Mao", "the print out", "the print", "the scans") is that work's own
product: one printout, handed to whom it is taken to, titles before the name included; never
a second one for the speaker (fix180a class 3)."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import load_office
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_lee = frame_reader(load_office, "lee")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("read", "text", "kind", "recipient"),
    [
        (_lee, "print my file and take the print-out to Mao", "print", "mao"),
        (_lee, "print my file and take the print out to Manager Mao", "print", "mao"),
        (_lee, "print my file and then take the print to Dr Zhang", "print", "zhang"),
        (_lee, "print my file and take the print out of the tray to Wang", "print", "wang"),
        (_may, "print my file and take the print-out to Manager Whitfield", "print", "sue"),
        (_may, "scan my letter and take the scans to Dr Huang", "copy", "grace"),
        # must not change: the product's own name, and "it"
        (_lee, "print my file and take the printout to Mao", "print", "mao"),
        (_lee, "print my file and take it to Mao", "print", "mao"),
        (_lee, "copy my contract and take the copy to Mao", "copy", "mao"),
    ],
)
def test_the_work_said_as_a_noun_is_its_one_product(
    read: Any, text: str, kind: str, recipient: str
) -> None:
    frame = read(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.recipient) for t in frame.tasks] == [(kind, recipient)], frame


def test_two_services_asked_stay_two() -> None:
    frame = _lee("print my file and a copy of my contract")
    assert [t.kind for t in frame.tasks] == ["print", "copy"], frame
