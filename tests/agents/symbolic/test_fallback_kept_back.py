"""A fallback offered beside a request ("bring me a stapler, or if there isn't one, scissors",
"..., failing that any folder", "a coffee please, or a water if the machine's down", "can I
borrow Zhang's stapler? if he's not in, Wang's will do"): one thing is wanted, the first, so
the second is never fetched too (fix60d class 1). The fallback is kept back and named in the
reading's evidence. Two things joined with no condition, the same two offered as "or" (asked
which), and a condition alone on a person or a machine read as before."""

from __future__ import annotations

import pytest
from symbolic_run import Run, run_instruction

from assistantx.core.office import load_office
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_sun = frame_reader(load_office, "sun")
_may = frame_reader(harbour_office, "may")
_STAPLER_OR_SCISSORS = "bring me a stapler, or if there isn't one, scissors"


def _rows(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.owner) for t in frame.tasks]


def _kept_back(frame: TaskFrame, second: str) -> bool:
    return any(e.meaning.startswith("a fallback: ") and second in e.meaning for e in frame.evidence)


@pytest.mark.parametrize(
    ("text", "first", "second"),
    [
        ("bring me a stapler, or if there isn't one, scissors", "stapler", "scissors"),
        ("bring me a stapler, or if there's none, the scissors", "stapler", "scissors"),
        ("bring me scissors - or a stapler if you can't find any", "scissors", "stapler"),
        ("bring me a stapler or the scissors if there isn't one", "stapler", "scissors"),
        ("bring me a stapler, failing that scissors", "stapler", "scissors"),
        ("bring me the scissors, otherwise a stapler", "scissors", "stapler"),
        ("bring me a stapler or else scissors please", "stapler", "scissors"),
    ],
)
def test_the_first_is_fetched_and_the_fallback_kept_back(
    text: str, first: str, second: str
) -> None:
    frame = _sun(text)
    assert _rows(frame) == [("transfer", first, None)], frame.explain()
    assert _kept_back(frame, second), frame.explain()


def test_a_fallback_on_the_owner_being_out_borrows_the_first_owners_only() -> None:
    frame = _sun("can I borrow Zhang's stapler? if he's not in, Wang's will do")
    assert _rows(frame) == [("transfer", "stapler", "zhang")], frame.explain()
    assert _kept_back(frame, "Wang's"), frame.explain()


def test_a_fallback_on_the_machine_being_down_makes_only_the_first() -> None:
    frame = _sun("a coffee please, or a water if the machine's down")
    assert [t.item for t in frame.tasks] == ["coffee"], frame.explain()
    assert _kept_back(frame, "water"), frame.explain()


def test_in_another_office_the_same_holds() -> None:
    frame = _may("could you bring me a ruler, or if there isn't one, a calculator")
    assert [t.item for t in frame.tasks] == ["ruler"], frame.explain()
    assert _kept_back(frame, "calculator"), frame.explain()


# -- must not change -------------------------------------------------------------------------


def test_two_things_joined_are_both_fetched() -> None:
    frame = _sun("bring me a stapler and scissors")
    assert _rows(frame) == [("transfer", "stapler", None), ("transfer", "scissors", None)]
    assert not _kept_back(frame, "")


def test_two_things_offered_as_or_are_asked_which() -> None:
    frame = _sun("bring me the stapler or the scissors")
    assert frame.question == "Which would you like: the stapler or the scissors?"


def test_a_condition_on_a_person_is_read_as_before() -> None:
    frame = _sun("if Zhang's in, ask him to sign my form")
    assert [(t.kind, t.actor) for t in frame.tasks] == [("sign", "zhang")], frame.explain()
    assert not _kept_back(frame, "")


def test_a_condition_on_a_machine_with_no_thing_asked_is_read_as_before() -> None:
    frame = _sun("if there's no paper in the printer, top it up")
    assert not frame.tasks and not _kept_back(frame, ""), frame.explain()


def test_a_reason_after_otherwise_is_no_fallback() -> None:
    frame = _sun("bring me a stapler, otherwise I can't finish the report")
    assert not _kept_back(frame, ""), frame.explain()


# -- end to end ------------------------------------------------------------------------------


def _handed_to(run: Run, person: str) -> set[str]:
    """The kinds of thing the robot gave ``person`` a code to collect."""
    sent = (r.action for r in run.stm.trace.actions() if not r.refused)
    return {
        str(a.item).split(":")[0]
        for a in sent
        if a.type == "send_qr"
        and getattr(a, "contact", None) == person
        and getattr(a, "purpose", None) == "collect"
    }


async def test_end_to_end_only_the_first_is_handed_over_and_the_fallback_told() -> None:
    run = await run_instruction(load_office(), "sun", _STAPLER_OR_SCISSORS)
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    handed = _handed_to(run, "sun")
    assert handed == {"stapler"}, trace.summary
    assert "fallback" in (trace.summary or "") and "scissors" in (trace.summary or "")
    assert "was not needed" in (trace.summary or ""), trace.summary


async def test_end_to_end_two_things_joined_are_both_handed_over_untold() -> None:
    run = await run_instruction(load_office(), "sun", "bring me a stapler and scissors")
    trace = run.stm.trace
    assert _handed_to(run, "sun") == {"stapler", "scissors"}, trace.summary
    assert "fallback" not in (trace.summary or "")
