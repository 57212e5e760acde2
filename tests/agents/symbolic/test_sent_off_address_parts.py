"""A send-out asked in plain English keeps its address's parts (fixer 84k, class 2: "Please
send my invoice out with the courier to Café Lune, 12 Mill Street." told the operator
"dispatch it to Café Lune", the street lost). "send ... out/off to <place>" found the place
with every other word of the message marked as a name of the office, so each part after the
address's comma ("12 Mill Street") was taken for a colleague's and cut; now only the office's
own names are (``reading/send_off.py``), and the address runs on over its comma-joined parts
as it does after the service's own verb. ", thanks" and a clause of its own are no part."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office_that_sends_out, harbour_that_posts
from helpers.reading import frame_reader


def _default_that_dispatches() -> Office:
    """The default office whose printer room dispatches a document by courier, asked for as
    "send out" (so "send ... out" is read in plain English)."""
    return default_office_that_sends_out(
        "courier", "dispatch", "send out", "the name and address of the place"
    )


_dispatch = frame_reader(_default_that_dispatches, "mao")
_post = frame_reader(harbour_that_posts, "may")


def _sent(frame: TaskFrame) -> list[tuple[str | None, str | None]]:
    return [(t.operation, t.destination) for t in frame.tasks if t.operation is not None]


@pytest.mark.parametrize(
    ("text", "where"),
    [
        # the class's analogue
        (
            "Please send my invoice out with the courier to Café Lune, 12 Mill Street.",
            "Café Lune, 12 Mill Street",
        ),
        # variants: other places, more parts, other particles
        ("send my document out to Acme Ltd, 12 Mill Street", "Acme Ltd, 12 Mill Street"),
        (
            "send my document off to Acme Ltd, 12 Mill Street, Leeds LS1 4AP",
            "Acme Ltd, 12 Mill Street, Leeds LS1 4AP",
        ),
    ],
)
def test_the_address_after_the_comma_is_told_on_the_default_office(text: str, where: str) -> None:
    assert _sent(_dispatch(text)) == [("courier", where)]


@pytest.mark.parametrize(
    ("text", "where"),
    [
        (
            "send my document off to Harbour Books, 4 Quay Road, Whitby",
            "Harbour Books, 4 Quay Road, Whitby",
        ),
        (
            "could you send my document out to the Grand Hotel, 22 Marine Parade please",
            "the Grand Hotel, 22 Marine Parade",
        ),
    ],
)
def test_the_address_after_the_comma_is_told_on_harbour(text: str, where: str) -> None:
    assert _sent(_post(text)) == [("frank", where)]


@pytest.mark.parametrize(
    ("read", "text", "op"),
    [
        # must not change: a courtesy or a clause of its own after the comma
        (_dispatch, "send my document out to Café Lune, thanks", "courier"),
        (_post, "send my document off to Harbour Books, thanks", "frank"),
    ],
)
def test_no_address_after_the_comma_reads_as_before(read: Any, text: str, op: str) -> None:
    assert _sent(read(text)) == [(op, text.split(" to ", 1)[1].split(",")[0])]


def test_a_request_after_the_comma_is_its_own() -> None:
    # must not change: "and bring me a coffee" is a second request, no part of the place
    frame = _dispatch("send my document out to Café Lune, and bring me a coffee")
    assert _sent(frame) == [("courier", "Café Lune")]
    assert [(t.item, t.recipient) for t in frame.tasks if t.operation is None] == [
        ("coffee", "mao")
    ]
