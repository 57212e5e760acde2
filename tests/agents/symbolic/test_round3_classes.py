"""Classes found by the third blind round, as mechanisms, on the clinic office (own
sentences): a spaced dash joins sentences; a correction right after a name or item replaces
it; a colleague's possessive is not the product word it folds to ("Chip's" is not "chips");
a container noun after a statement about an item is that item; a file goes to every person
named as a recipient."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser, build_factory
from assistantx.core.settings import Settings
from assistantx.core.trace import Trace
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.recipients import named_recipients
from assistantx.sim.run import run_in_sim
from helpers.clinic import clinic


def _tasks(
    clinic_parser: InstructionParser, text: str
) -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in clinic_parser.parse(text, "ines").tasks]


def test_a_spaced_dash_ends_a_statement(clinic_parser: InstructionParser) -> None:
    assert _tasks(clinic_parser, "I'm on the ward all day - please print my rota") == [
        ("print", "file", "ines", "ines")
    ]
    assert _tasks(clinic_parser, "my clipboard snapped - could you bring me Rich's?") == [
        ("transfer", "clipboard", "rich", "ines")
    ]


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("bring me Rich's clipboard - sorry, I meant Dawn's", ("clipboard", "dawn", "ines")),
        ("bring me Rich's clipboard, no wait, Dawn's", ("clipboard", "dawn", "ines")),
        ("bring Hal my form. Sorry, I meant Dawn", ("document", "ines", "dawn")),
        ("bring me a clipboard, sorry I mean a thermometer", ("thermometer", None, "ines")),
    ],
)
def test_a_correction_replaces_what_it_corrects(
    clinic_parser: InstructionParser, text: str, task: tuple[str, str | None, str]
) -> None:
    assert [(i, o, r) for _, i, o, r in _tasks(clinic_parser, text)] == [task], text


def test_a_colleagues_possessive_is_not_a_product_word(clinic_parser: InstructionParser) -> None:
    assert _tasks(clinic_parser, "could you bring me Chip's clipboard") == [
        ("transfer", "clipboard", "chip", "ines")
    ]
    assert "can't get you any chips" in (
        clinic_parser.parse("bring me some chips", "ines").decline or ""
    )


def test_a_container_after_a_statement_is_the_stated_item(clinic_parser: InstructionParser) -> None:
    assert _tasks(clinic_parser, "I ran out of thermometers. Could you bring me a box?") == [
        ("transfer", "thermometer", None, "ines")
    ]


@pytest.mark.parametrize(
    "text", ["send my rota to Hal and to Dawn", "send my rota to Hal and Dawn"]
)
def test_a_file_goes_to_each_recipient_and_the_guard_agrees(
    clinic_parser: InstructionParser, text: str
) -> None:
    assert [t[3] for t in _tasks(clinic_parser, text)] == ["hal", "dawn"]
    trace = Trace(instruction_id="i", requester="ines", text=text, reasoner="t", started_at=0)
    stm = ShortTermMemory(instruction_id="i", requester="ines", text=text, trace=trace)
    assert named_recipients(clinic(), stm) == {"hal", "dawn"}


async def test_a_pronoun_recipient_whose_own_item_broke_gets_the_requesters() -> None:
    # the reader names Hal, and the guard agrees: "Hal's" is the broken one, not the one moved
    office = clinic()
    text = "Hal's clipboard snapped, lend him mine"
    run = await run_in_sim(office, "ines", text, build_factory(office, Settings()))
    assert run.trace.outcome == "done", run.trace.summary
    assert run.sim.world.check({"holds": ["hal", "clipboard:ines"]})


def test_a_role_title_in_an_alias_names_its_holder(clinic_parser: InstructionParser) -> None:
    # Rich's alias is "Manager Rich": "by the manager" is Rich, and the guard agrees
    text = "could you get my form signed by the manager"
    assert [(t.kind, t.actor) for t in clinic_parser.parse(text, "ines").tasks] == [
        ("sign", "rich")
    ]
    trace = Trace(instruction_id="i", requester="ines", text=text, reasoner="t", started_at=0)
    stm = ShortTermMemory(instruction_id="i", requester="ines", text=text, trace=trace)
    assert named_recipients(clinic(), stm) == {"rich"}
    # followed by a name, the title is a title: "Manager Rich", not two people
    frame = clinic_parser.parse("take my form to Manager Rich", "ines")
    assert [t.recipient for t in frame.tasks] == ["rich"]
