"""After "I need <thing> <participle> [by <person>]", a verbless ", and a <thing>" is a second
thing needed, for the requester (``reading.verbless_conjunct``, the need put into the
conjunct): the participle ends the first need's thing, so the coffee is no second object of
the signing, which was asked about."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import load_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE


@functools.cache
def _parser(base: str) -> InstructionParser:
    return InstructionParser(load_office(HARBOUR_FILE if base == "harbour" else DEFAULT_FILE))


def _read(base: str, requester: str, text: str) -> list[tuple[str, str | None, str | None, str]]:
    frame = _parser(base).parse(text, requester)
    assert frame.question is None, frame.question
    return [(t.kind, t.actor, t.recipient, t.item) for t in frame.tasks]


@pytest.mark.parametrize(
    ("base", "requester", "text", "tasks"),
    [
        (
            "default",
            "lin",
            "I need my contract signed by Wang, and a coffee, cheers",
            [("sign", "wang", "lin", "document"), ("produce", None, "lin", "coffee")],
        ),
        (
            "default",
            "lin",
            "I need my report printed, and a stapler please",
            [("print", None, "lin", "file"), ("transfer", None, "lin", "stapler")],
        ),
        (
            "default",
            "lin",
            "I need my contract stamped by Zhang and a stapler",
            [("seal", "zhang", "lin", "document"), ("transfer", None, "lin", "stapler")],
        ),
        (
            "harbour",
            "will",
            "I need my document signed by Joy, and a tea please",
            [("sign", "joy", "will", "document"), ("produce", None, "will", "tea")],
        ),
        (
            "harbour",
            "will",
            "I need my document scanned and a ruler",
            [("copy", None, "will", "document"), ("transfer", None, "will", "ruler")],
        ),
    ],
)
def test_the_thing_after_a_need_done_is_needed_too(
    base: str, requester: str, text: str, tasks: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(base, requester, text) == tasks


@pytest.mark.parametrize(
    ("base", "requester", "text", "doers"),
    [
        # a second name after "and" is no thing needed: a second signer (``joined_doers``)
        ("default", "lin", "I need my contract signed by Wang and Zhang", ("wang", "zhang")),
        ("harbour", "will", "I need my document signed by Joy and Ray", ("joy", "ray")),
    ],
)
def test_a_second_signer_is_no_thing_needed(
    base: str, requester: str, text: str, doers: tuple[str, ...]
) -> None:
    assert _read(base, requester, text) == [("sign", d, requester, "document") for d in doers]


def test_a_paper_after_the_work_is_left_to_the_work() -> None:
    # must not change: "the invoice" is a paper the signing may take, never fetched for me
    tasks = _read("default", "lin", "I need my contract signed by Wang and the invoice")
    assert all(t[0] == "sign" for t in tasks)
