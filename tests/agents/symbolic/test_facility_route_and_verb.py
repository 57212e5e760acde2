"""A facility named as the way a thing's work goes, or said in the verb's place (fixer fix61a).

Class 1: "my job bag needs a run through the ultrasonic cleaner", "my forceps need a go in the
autoclave": English asks for the machine's work on the thing by naming the machine as its
route; the reader had told it ("Noted. I did nothing."). Where one operation of that facility
takes the thing, that is the request (the thing back to its owner); several: which is asked.
A machine said to need something ("the autoclave needs a run"), a need with no machine ("my
mug needs a wash") and a machine that takes no such thing are read as before.

Class 2: "can you xrf my job bag" where the XRF analyser's assay has the verbs [assay, xrf],
"can you scanner my document": a facility's name said in the verb's place asks for that
facility's own work on its object, never every service of the thing ("Which should I do with
your document: scan or sign?"). A transfer to the facility and a question about it are read as
before."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import load_office
from helpers import office_builder as ob
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_LAB = ob.parsed(
    lambda: ob.office_file(
        "Lab",
        [
            ob.person("ann", "Ann Lee", "forceps", "parts", "job_bag", "mug", aliases=["Ann"]),
            ob.person("zoe", "Zoe Park", aliases=["Zoe"]),
            ob.person("bob", "Bob Ray", aliases=["Bob"]),
        ],
        rooms=[
            ob.room("shop", "Workshop", 30.0, 6.0),
            ob.room("sterile", "Sterile Room", 40.0, 6.0),
        ],
        item_types=[
            ob.item("forceps", "forceps"),
            ob.item("parts", "parts"),
            ob.item("job_bag", "job bag"),
            ob.item("mug", "mug"),
            ob.item("assay_report", "assay report", "product"),
        ],
        operations=[
            ob.operation("sterilise", "sterilise", "autoclave", input="forceps"),
            ob.operation("degrease", "degrease", input="parts"),
            ob.operation("assay", "assay", "xrf", input="job_bag", product="assay_report"),
            ob.operation("polish", "polish", input="job_bag"),
            ob.operation("buff", "buff", input="job_bag"),
            ob.operation("clean", "clean", name="ultrasonic clean", input="job_bag"),
        ],
        facilities=[
            ob.facility(
                "autoclave", "autoclave", at="sterile", guards=["bob"], operations=["sterilise"]
            ),
            ob.facility(
                "washer",
                "parts washer",
                at="shop",
                guards=["bob"],
                operations=["degrease"],
                synonyms=["washer"],
            ),
            ob.facility("xrf", "XRF analyser", at="shop", guards=["bob"], operations=["assay"]),
            ob.facility(
                "polisher", "polisher", at="shop", guards=["bob"], operations=["polish", "buff"]
            ),
            ob.facility(
                "cleaner", "ultrasonic cleaner", at="shop", guards=["bob"], operations=["clean"]
            ),
        ],
        home="shop",
    )
)
_ann = frame_reader(_LAB, "ann")
_lee = frame_reader(load_office, "lee")
_may = frame_reader(harbour_office, "may")


def _done(frame: Any) -> list[tuple[str | None, str | None, str | None]]:
    assert frame.question is None and frame.decline is None, frame
    return [(t.operation, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "op", "item"),
    [
        ("My job bag needs a run through the ultrasonic cleaner.", "clean", "job_bag"),
        ("my forceps need a go in the autoclave", "sterilise", "forceps"),
        ("these parts could do with a run through the washer", "degrease", "parts"),
        ("my parts could use a quick spin in the parts washer please", "degrease", "parts"),
        # must not change: the thing given or put through the machine, as before
        ("give my forceps a spin in the autoclave", "sterilise", "forceps"),
        ("put my parts through the washer", "degrease", "parts"),
    ],
)
def test_a_machine_named_as_the_route_asks_its_work(text: str, op: str, item: str) -> None:
    assert _done(_ann(text)) == [(op, item, "ann")]


def test_several_works_of_the_machine_ask_which() -> None:
    frame = _ann("my job bag needs a go in the polisher")
    assert not frame.tasks and frame.question is not None, frame
    assert "polish" in frame.question and "buff" in frame.question, frame
    assert "assay" not in frame.question, frame


@pytest.mark.parametrize(
    "text",
    [
        # must not change: the machine needs something; a need with no machine; no such work
        "the autoclave needs a run",
        "the washer needs a clean",
        "my mug needs a wash",
        "my mug needs a run through the washer",
    ],
)
def test_no_machine_work_on_the_thing_is_no_request(text: str) -> None:
    assert not _ann(text).tasks


@pytest.mark.parametrize(
    ("read", "text", "kind", "item", "to"),
    [
        # the XRF's assay makes a report from the job bag (a copy's shape)
        (_ann, "can you xrf my job bag?", "copy", "job_bag", "ann"),
        (_ann, "pls xrf my job bag", "copy", "job_bag", "ann"),
        (_ann, "can you assay my job bag", "copy", "job_bag", "ann"),
        (_ann, "can you autoclave my forceps", "heat", "forceps", "ann"),
        (_may, "can you scanner my document", "copy", "document", "may"),
        (_lee, "can you copier my document", "copy", "document", "lee"),
    ],
)
def test_a_facility_said_as_the_verb_is_its_work(
    read: Any, text: str, kind: str, item: str, to: str
) -> None:
    frame = read(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [(kind, item, to)], frame


def test_a_facility_said_as_the_verb_with_several_works_asks_among_them() -> None:
    frame = _ann("can you polisher my job bag")
    assert not frame.tasks and frame.question is not None, frame
    assert "assay" not in frame.question and "clean" not in frame.question, frame


@pytest.mark.parametrize(
    ("read", "text"),
    [
        # must not change: a question about the facility, told in words
        (_ann, "is the autoclave free?"),
        (_may, "is the scanner free?"),
    ],
)
def test_a_question_about_the_facility_stays(read: Any, text: str) -> None:
    assert not read(text).tasks


def test_taking_a_thing_to_the_facility_stays() -> None:
    frame = _may("take my document to the scanner")
    assert [t.item for t in frame.tasks] == ["document"], frame
