"""A thing whose name holds a word of work by hand ("date stamp", "signature pad") is a thing:
a simulated colleague asked to lend it reads no request to seal or sign, so the oracle (and
the dataset generator's check that plays it) can fetch one. A one-word "stamp" before an
object still asks for the work."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, parse_office
from assistantx.core.task_spec import BaseInstruction, Part
from assistantx.evaluation.dataset.generate import verify_tasks
from assistantx.sim.understanding import mentioned_requests
from helpers import office_builder as ob
from helpers.dataset_tasks import every_task


@functools.cache
def clerks_office() -> Office:
    people = (
        ob.person("ann", "Ann Roe"),
        ob.person("bea", "Bea Lund", "date_stamp", "seal"),
        ob.person("cy", "Cy Park", "date_stamp", "signature_pad"),
    )
    return parse_office(
        ob.office_file(
            "clerks",
            people,
            everyone_owns=["form"],
            rooms=[ob.room("post_room", "Post room", 14.0, 20.5)],
            item_types=[
                ob.item("date_stamp", "date stamp", synonyms=["rubber stamp"]),
                ob.item("signature_pad", "signature pad"),
                ob.item("seal", "seal", seals=True),
                ob.item("form", "form", "personal", signable=True),
            ],
            operations=[],
            facilities=[],
            home="post_room",
        ),
        "clerks",
    )


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("Hi Bea, could you lend Ann Roe your date stamp?", []),
        ("Could you lend Ann your rubber stamp for an hour?", []),
        ("Cy, could Ann borrow your signature pad?", []),
        ("Could you stamp Ann Roe's form with your seal?", ["seal"]),
        ("Could you sign Ann Roe's form?", ["sign"]),
    ],
)
def test_a_things_name_is_no_request_for_the_work_inside_it(text: str, kinds: list[str]) -> None:
    assert mentioned_requests(clerks_office(), text) == kinds


async def test_the_generators_check_fetches_a_date_stamp() -> None:
    office = clerks_office()
    base = BaseInstruction(
        id="d1",
        requester="ann",
        text="Could you get me a date stamp?",
        parts=(Part(kind="fetch", item="date_stamp"),),
    )
    tasks = every_task(office, base)
    assert tasks
    await verify_tasks(office, tasks)  # raises DatasetError where the oracle fails
