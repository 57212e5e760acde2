"""Issue #23, fixer fix151c class 3: a reason sentence's description of a product is what it
shows, not a variant the office would have to make (``screen/reason_content``), and the
request after it that makes that product for the one who needs it is one errand
(``needs_met.needs_said_again``). "Zeynep needs the jacket pattern full size for cutting. Can
you plot my pattern file and take it to her?" asked "a jacket pattern plot is not something
this office makes. Shall I get you an ordinary pattern plot?"; "Wang needs a printout for the
meeting. Can you print my file and take it to him?" read two prints for Wang."""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.core.office import load_office
from helpers.atelier import atelier
from helpers.dataset_offices import harbour_office
from helpers.guesthouse import guesthouse
from helpers.reading import frame_reader

_default = frame_reader(load_office, "lee")
_harbour = frame_reader(harbour_office, "will")
_atelier = frame_reader(atelier, "mara")
_guesthouse = frame_reader(guesthouse, "wren")


@pytest.mark.parametrize(
    ("read", "text", "item", "owner", "recipient"),
    [
        (
            _atelier,
            "Zeynep needs the jacket pattern full size for cutting. Can you plot my pattern "
            "file and take it to her?",
            "pattern_file",
            "mara",
            "zeynep",
        ),
        (
            _atelier,
            "Priya needs the sleeve pattern for the fitting. plot my file and give it to her",
            "pattern_file",
            "mara",
            "priya",
        ),
        (
            _default,
            "Wang needs the budget printout for the meeting. Can you print my file and take "
            "it to him?",
            "file",
            "lee",
            "wang",
        ),
        (
            _default,
            "Zhang needs the seating plan printout A3. print my file and give it to her",
            "file",
            "lee",
            "zhang",
        ),
        (
            _default,
            "Wang needs a printout for the meeting. Can you print my file and take it to him?",
            "file",
            "lee",
            "wang",
        ),
        (
            _default,
            "Wang needs the Q3 figures printed for the meeting. Can you print my file and "
            "take it to him?",
            "file",
            "lee",
            "wang",
        ),
        (
            _harbour,
            "Rose needs the floor plan printout. Can you print my file and take it to her?",
            "file",
            "will",
            "rose",
        ),
    ],
)
def test_the_request_makes_one_product_for_the_one_who_needs_it(
    read: Any, text: str, item: str, owner: str, recipient: str
) -> None:
    frame = read(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("print", item, owner, recipient)
    ], frame


def test_a_need_and_another_print_for_someone_else_stay_two() -> None:
    frame = _default("Wang needs a printout. print my file for him and print one for Sun")
    assert sorted(t.recipient for t in frame.tasks) == ["sun", "wang"], frame


@pytest.mark.parametrize(
    ("read", "text", "asked"),
    [
        # neighbours: a need with no request after it; a word that says how it is made; a
        # product made from nothing (the words say which one); the request's own variant
        (_default, "Wang needs the budget printout for the meeting.", "budget printout"),
        (_atelier, "Zeynep needs the jacket pattern plot.", "jacket pattern plot"),
        (
            _default,
            "Wang needs a colour printout for the meeting. Can you print my file and take it "
            "to him?",
            "colour printout",
        ),
        (_guesthouse, "Basil needs an iced tea. Can you brew one for him?", "iced tea"),
        (_guesthouse, "Basil is thirsty. Can you brew him an iced tea?", "iced tea"),
    ],
)
def test_a_variant_is_still_asked(read: Any, text: str, asked: str) -> None:
    frame = read(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert asked in frame.question and "ordinary" in frame.question, frame


async def test_end_to_end_the_plot_goes_to_the_one_who_needs_it() -> None:
    text = (
        "Zeynep needs the jacket pattern full size for cutting. Can you plot my pattern file "
        "and take it to her?"
    )
    run = await run_instruction(atelier(), "mara", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    handed = [(e.detail["item"], e.detail["to"]) for e in run.sim.world.handovers()]
    assert handed == [("pattern_plot:mara", "zeynep")], handed
