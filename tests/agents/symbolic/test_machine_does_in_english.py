"""What a machine does, said in a decline (an unknown test: "there is no NMR here. The IR
spectrometer can ..."; a wrong instrument): English for every shape of operation name and
whether its input is named one or several (fixer fix59e, class 3). It said "can run an IR
samples" where the operation is "run an IR" on a "sample"; now "can run an IR on samples".
Which requests are declined is unchanged."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.wrong_instrument import does
from assistantx.core.office import Operation
from assistantx.core.wording import things_worked_on, works_on
from helpers import office_builder as ob
from helpers.reading import frame_reader


@pytest.mark.parametrize(
    ("name", "thing", "said"),
    [
        ("run an IR", "sample", "run an IR on samples"),  # the name's object is the work
        ("laminate", "paper", "laminate papers"),
        ("laminate", "papers", "laminate papers"),  # named plural already
        ("spin down", "sample", "spin down samples"),  # a particle stays with its verb
        ("send to the lab", "sample", "send samples to the lab"),  # before its complement
        ("patch a tube", "inner tube", "patch inner tubes"),  # the object is the thing
        ("heat seal", "curtain", "heat seal curtains"),
        ("frank", "bill of lading", "frank bills of lading"),
        ("shred", "data", "shred data"),  # stuff
    ],
)
def test_works_on_says_the_work_in_english(name: str, thing: str, said: str) -> None:
    op = Operation(id="op", name=name, input="thing")
    assert works_on(op, things_worked_on(thing)) == said


def _raw() -> ob.Row:
    return ob.office_file(
        "ir lab",
        (ob.person("lee", "Lee Park", "sample", "paper", aliases=["Lee"]),),
        rooms=[ob.room("lab", "Lab", 4.0, 20.0), ob.room("kitchen", "Kitchen", 20.0, 20.0)],
        item_types=[
            ob.item("sample", "sample"),
            ob.item("paper", "papers", synonyms=["paper"]),
        ],
        operations=[
            ob.operation("ir", "run", name="run an IR", input="sample"),
            ob.operation("laminate", "laminate", input="paper"),
        ],
        facilities=[
            ob.facility(
                "spectrometer",
                "IR spectrometer",
                at="lab",
                guards=["lee"],
                operations=["ir"],
                synonyms=["IR", "spectrometer"],
            ),
            ob.facility(
                "laminator", "laminator", at="lab", guards=["lee"], operations=["laminate"]
            ),
        ],
        home="kitchen",
    )


_office = ob.parsed(_raw)
_lee = frame_reader(_office, "lee")


def test_the_machines_are_said_in_english() -> None:
    office = _office()
    assert does(office, office.facility("spectrometer")) == (
        "The IR spectrometer can run an IR on samples"
    )
    assert does(office, office.facility("laminator")) == "The laminator can laminate papers"


def test_an_unknown_test_is_declined_naming_the_work_in_english() -> None:
    frame = _lee("run an NMR on my sample pls")
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and "no NMR here" in frame.decline, frame
    assert "can run an IR on samples" in frame.decline, frame
    assert "an IR samples" not in frame.decline, frame


def test_the_offices_own_test_is_still_run() -> None:
    frame = _lee("run an IR on my sample")
    assert frame.decline is None and frame.question is None, frame
    assert [t.item for t in frame.tasks] == ["sample"], frame
