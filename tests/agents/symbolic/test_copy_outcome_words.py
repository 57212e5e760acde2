"""The outcome of a copy says where each thing went: a copy for a colleague goes to them and
the original back to whoever put it in ("the photocopy of your document was handed to Zhang
Wei, and the original back to you"); before, it read "your document and its result were
handed to Zhang Wei", though the original never went to Zhang."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.dataset_offices import default_office


@pytest.mark.parametrize(
    ("text", "summary"),
    [
        (
            "make a copy of my document for Zhang",
            "the photocopy of your document was handed to Zhang Wei, and the original back to you",
        ),
        (
            "make Lin a copy of Zhang's document",
            "the photocopy of Zhang Wei's document was handed to Lin Tao, and the original back to"
            " Zhang Wei",
        ),
        ("make a copy of my document", "your document and its photocopy were handed to you"),
    ],
)
async def test_the_copy_outcome_names_where_the_copy_and_the_original_went(
    text: str, summary: str
) -> None:
    run = await run_instruction(default_office(), "wang", text)
    assert run.stm.trace.outcome == "done"
    assert summary in (run.stm.trace.summary or ""), run.stm.trace.summary
