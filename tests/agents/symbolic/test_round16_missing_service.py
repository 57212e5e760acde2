"""A service the office does not have, asked for with a second action nobody here can do
("scan my drawings and email them to the client" in a workshop without a scanner,
``helpers.fablab``; the blind round's office and sentences were never read): declined at
once, naming both, never asked about; in a workshop with a scanner the scan is done."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.fablab import costume_works, fablab
from helpers.reading import frame_reader

_frame = frame_reader(fablab, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "scan my drawings and email them to the client",
        "could you scan my drawings and send them to the client?",
        "please scan my drawings and email them to our client",
    ],
)
def test_a_missing_service_with_an_outside_send_is_declined_naming_both(text: str) -> None:
    frame = _frame(text, "ines")
    assert not frame.tasks and frame.question is None
    assert frame.decline is not None
    assert "can't scan" in frame.decline and "client" in frame.decline


async def test_the_decline_asks_nothing_and_moves_nothing() -> None:
    run = await run_instruction(fablab(), "ines", "scan my drawings and email them to the client")
    assert run.actions == ["stop"]
    assert "can't scan" in (run.stm.trace.summary or "")


async def test_with_a_scanner_the_scan_is_done() -> None:
    run = await run_instruction(costume_works(), "ada", "scan my drawings")
    assert run.stm.trace.outcome == "done"
    assert "drawing:ada" in run.sim.world.copied
