"""A described owner said without its determiner or in title case is still a role, not a
colleague (``reading.described_owner``): "print Hartley loss adjuster's report for me" and
"print the Acme Claims Handler's report for me" asked "I don't know anyone called
'adjuster'"; like "the site engineer's report", the paper is the speaker's in hand. A name
opens such a description (a firm, a surname), and a command's verb stands before it. A
colleague named ("print Wang's report") or the office's own title ("the Manager's report")
is still a colleague. On the dataset's default office and harbour."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "may")


def _printed(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        # the class's analogues, said without "the" or in title case
        "print Hartley loss adjuster's report for me pls",
        "print the Acme Claims Handler's report for me",
        "can you print Smith site manager's report for me pls",
        # variants of our own
        "print Jones loss assessor's report for me",
        "print Acme site engineer's invoice for me please",
    ],
)
def test_a_described_owner_in_other_forms_is_no_colleague(text: str) -> None:
    assert _printed(_default(text)) == [("print", "file", "lin", "lin")]


@pytest.mark.parametrize(
    "text",
    [
        "print Marsh loss adjuster's report for me",
        "print the Westgate Port Agent's invoice for me pls",
    ],
)
def test_a_described_owner_in_other_forms_in_harbour(text: str) -> None:
    assert _printed(_harbour(text)) == [("print", "file", "may", "may")]


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("print Wang's report for me", "wang"),  # must not change: a colleague named
        ("print the Manager's report for me", "mao"),  # the office's title, undescribed
    ],
)
def test_a_colleague_is_still_a_colleague(text: str, owner: str) -> None:
    assert _printed(_default(text)) == [("print", "file", owner, "lin")]
