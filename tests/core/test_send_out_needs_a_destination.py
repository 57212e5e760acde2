"""A base instruction whose part sends an item out of the office must say where to: whatever
goes out unaddressed is lost, and the evaluation counts it as a wrong hand-over. Blind round
89's writer gave a courier part with no destination ("my faulty part needs to go back to the
vendor, can it go out with the courier today?"); the generator accepted it and the optimal
policy then shipped the part with no address in every variant. Such a base is refused with
what is missing, in the operation's own words; with a destination it is a task as before."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from assistantx.core.task_spec import BaseInstruction, Part, check_base
from helpers.dataset_offices import default_office_that_sends_out, harbour_that_posts


def _base(requester: str, operation: str, destination: str | None) -> BaseInstruction:
    return BaseInstruction(
        id="o1",
        requester=requester,
        text="please send my document out",
        parts=(Part(kind="heat", operation=operation, destination=destination),),
    )


@pytest.mark.parametrize(
    ("office", "requester", "operation", "asked"),
    [
        (
            default_office_that_sends_out("fax", "fax", "fax", "the fax number"),
            "lee",
            "fax",
            "the fax number",
        ),
        (harbour_that_posts(), "rose", "frank", "the postal address"),
    ],
    ids=["fax", "post"],
)
def test_a_send_out_without_a_destination_is_refused_saying_what_is_missing(
    office: Office, requester: str, operation: str, asked: str
) -> None:
    with pytest.raises(ValueError, match=f"needs its destination \\({asked}\\)"):
        check_base(_base(requester, operation, None), office)
    check_base(_base(requester, operation, "Acme Ltd, 12 Mill Lane"), office)
