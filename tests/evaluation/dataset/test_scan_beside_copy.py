"""A scan to PDF on the machine that also copies (the default office's printer given a scan
whose product is the office's own electronic file type): the operator runs the service the
code's message names by its verb ("take … out, scan it, send the electronic file to its
owner"), not the machine's first service. Before, the simulated operator copied instead, the
PDF never reached its owner and `dataset generate` refused every variant (blind round 75's
writer found it)."""

from __future__ import annotations

import asyncio

import pytest

from assistantx.core.task_spec import BaseInstruction, Part
from helpers.dataset_offices import default_office_that_scans
from helpers.dataset_tasks import verify_every_variant

SCAN = BaseInstruction(
    id="scan1",
    requester="wang",
    text="scan my document to pdf please",
    parts=(Part(kind="copy", operation="scan"),),
)
COPY = BaseInstruction(
    id="copy1", requester="wang", text="copy my document please", parts=(Part(kind="copy"),)
)


@pytest.mark.parametrize("base", [SCAN, COPY], ids=["scan", "copy"])
def test_each_service_of_the_machine_is_run_as_asked_in_every_variant(
    base: BaseInstruction,
) -> None:
    tasks = asyncio.run(verify_every_variant(default_office_that_scans("scan", "file"), base))
    achievable = [t for t in tasks if t.achievable]
    assert achievable
    if base is SCAN:
        assert all({"received": ["wang", "file:wang"]} in t.goal for t in achievable)
    else:
        assert all({"holds": ["wang", "copy:wang"]} in t.goal for t in achievable)
