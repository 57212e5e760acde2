"""Fix129a, class 3 (analogues, not the measured sentences): a possessive owner described
after its determiner ("the site engineer's", "the Acme account manager's", "the Hartley loss
adjuster's") is a role, nobody of the office, and the paper to print is the requester's own
(reading/described_owner.py). A colleague named ("Wang's") or called by the office's title
word with no description ("the manager's", "the office manager's") is still that colleague."""

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
        "print the Acme account manager's report for me",  # the class's analogues
        "print the site engineer's report for me pls",
        "print the Hartley loss adjuster's report for me pls",
        "print the Smith account manager's invoice for me",
        "could you print the county planning officer's report for me",
    ],
)
def test_a_described_owner_is_no_colleague(text: str) -> None:
    assert _printed(_default(text)) == [("print", "file", "lin", "lin")]


@pytest.mark.parametrize(
    "text",
    [
        "print the Acme account manager's timesheet for me",
        "print the port agent's invoice for me pls",
    ],
)
def test_a_described_owner_is_no_colleague_in_harbour(text: str) -> None:
    assert _printed(_harbour(text)) == [("print", "file", "may", "may")]


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("print Wang's report for me", "wang"),  # neighbour: a colleague named
        ("print the manager's report for me", "mao"),  # the office's title, undescribed
        ("print the office manager's report for me", "mao"),  # placed in this office
    ],
)
def test_a_colleague_is_still_a_colleague(text: str, owner: str) -> None:
    assert _printed(_default(text)) == [("print", "file", owner, "lin")]


@pytest.mark.parametrize(
    ("text", "to"),
    [
        # the role said before "it": the same reading wherever the paper is named
        ("the Acme account manager's report is ready, print it for me", "lin"),
        ("print the Acme account manager's report and give it to Wang", "wang"),
    ],
)
def test_a_described_owners_paper_named_before_it(text: str, to: str) -> None:
    assert _printed(_default(text)) == [("print", "file", "lin", to)]


def test_the_undescribed_title_before_it_is_still_the_colleague() -> None:
    frame = _default("the manager's report is ready, print it for me")
    assert _printed(frame) == [("print", "file", "mao", "lin")]


def test_a_described_owners_thing_to_fetch_is_still_asked_about() -> None:
    frame = _default("bring me the site engineer's report")
    assert frame.tasks == [] and frame.question is not None


def test_a_word_of_grammar_ends_the_description() -> None:
    """Neighbour: "on" describes nobody, so "wang's" is still the colleague in lower case."""
    frame = _default("drop my contract on wang's desk")
    assert _printed(frame) == [("transfer", "document", "lin", "wang")]


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
def test_a_colleague_is_still_a_colleague_in_other_forms(text: str, owner: str) -> None:
    assert _printed(_default(text)) == [("print", "file", owner, "lin")]
