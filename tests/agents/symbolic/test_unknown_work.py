"""Work the reader has no verb for ("sew up the hem on my sample", "polish my boots", "tidy up
my report") is declined, never read as a transfer of its object (the requester's own thing
brought to them); a vague verb of work ("sort out my mug", "deal with my lunch") on a thing
the office's services work on is asked, one service offered or several asked which. Slang
errands the reader knows, a service of the office and a colleague's work stay as they were."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import load_office
from helpers import office_builder as ob
from helpers.dataset_offices import harbour_office
from helpers.reading import answered_reader, frame_reader


def _raw_atelier() -> dict[str, Any]:
    """A fashion studio: each designer's sample on a rail, a pressing table that presses
    samples, a kitchen that washes mugs and a print bench that prints on mugs."""
    people = (
        ob.person("ines", "Ines Costa", ob.kept("sample", at="rail_room", facility="rail")),
        ob.person("tom", "Tom Berg", ob.kept("sample", at="rail_room", facility="rail")),
        ob.person("kai", "Kai Lund"),
    )
    return ob.office_file(
        "atelier",
        people,
        rooms=[
            ob.room("rail_room", "Rail room", 4.0, 20.0),
            ob.room("kitchen", "Kitchen", 12.0, 20.0),
            ob.room("print_room", "Print room", 20.0, 20.0),
        ],
        item_types=[
            ob.item("sample", "sample", "personal", synonyms=["toile"]),
            ob.item("mug", "mug", "personal"),
            ob.item("shirt", "shirt", "personal"),
            ob.item("scissors", "scissors"),
        ],
        operations=[
            ob.operation("press", "press", input="sample"),
            ob.operation("wash", "wash", input="mug"),
            ob.operation("mug_print", "print", name="print on a mug", input="mug"),
        ],
        facilities=[
            ob.facility("rail", "rail", at="rail_room", guards=["kai"]),
            ob.facility(
                "pressing_table",
                "pressing table",
                at="rail_room",
                guards=["kai"],
                operations=["press"],
            ),
            ob.facility("sink", "sink", at="kitchen", guards=["kai"], operations=["wash"]),
            ob.facility(
                "mug_printer",
                "mug printer",
                at="print_room",
                guards=["tom"],
                operations=["mug_print"],
            ),
        ],
        everyone_owns=["mug", "shirt"],
        home="rail_room",
    )


_atelier = ob.parsed(_raw_atelier)
_ines = frame_reader(_atelier, "ines")
_zhang = frame_reader(load_office, "zhang")
_will = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("read", "text", "verb"),
    [
        # the class's own shape, in an office built here
        (_ines, "can you sew up the hem on my sample before 4?", "sew up"),
        (_ines, "can you iron my shirt", "iron"),
        (_ines, "please tidy up my sample", "tidy up"),
        # the default office and harbour, other words
        (_zhang, "could you polish my stapler", "polish"),
        (_zhang, "please tidy up my report", "tidy up"),
        (_zhang, "varnish my stapler", "varnish"),
        (_zhang, "please mend Wang's stapler", "mend"),
        (_will, "could you polish my calculator", "polish"),
        (_will, "can you tidy up my contract", "tidy up"),
        (_will, "hey, can you sharpen my ruler?", "sharpen"),
    ],
)
def test_work_nothing_here_does_is_declined(read: Any, text: str, verb: str) -> None:
    frame = read(text)
    assert not frame.tasks, frame
    assert frame.decline is not None and f"can't {verb}" in frame.decline, frame
    assert "What I can do here" in frame.decline, frame


@pytest.mark.parametrize(
    "text", ["can you sort out my mug", "could you deal with my mug please", "sort my mug out"]
)
def test_vague_work_on_a_thing_of_several_services_is_asked_which(text: str) -> None:
    # the frames stage's question by name (``reading.work_unsaid``), never the mug brought
    frame = _ines(text)
    assert not frame.tasks and frame.decline is None, frame
    assert frame.question is not None and "wash" in frame.question, frame
    assert "print" in frame.question, frame


def test_unknown_work_on_a_thing_of_several_services_is_declined() -> None:
    # "polish" is neither washing nor printing: declined, not asked which of those
    frame = _ines("could you polish my mug")
    assert not frame.tasks and frame.decline is not None and "polish" in frame.decline, frame


@pytest.mark.parametrize(
    ("read", "text", "offer"),
    [
        (_ines, "can you sort out my sample", "Shall I press your sample?"),
        (_zhang, "can you sort out my lunch", "Shall I heat your lunch?"),
        (_zhang, "could you sort my lunch out", "Shall I heat your lunch?"),
        # "could you deal with my document": copying, signing and sealing take it; asked
        # which (fixer fix60g, test_vague_work_said_after_own_thing.py)
    ],
)
def test_vague_work_on_a_thing_of_one_service_offers_it(read: Any, text: str, offer: str) -> None:
    frame = read(text)
    assert not frame.tasks and frame.decline is None, frame
    assert frame.question == offer, frame


def test_vague_work_on_a_thing_no_service_works_on_is_declined() -> None:
    frame = _zhang("can you sort out my stapler")
    assert not frame.tasks and frame.decline is not None and "sort out" in frame.decline, frame


@pytest.mark.parametrize(
    ("read", "text", "kind", "recipient"),
    [
        # slang errands the reader knows, and a thing carried somewhere
        (_zhang, "pop my stapler over to Wang", "transfer", "wang"),
        (_will, "could you nab Mark's ruler for me", "transfer", "will"),
        (_zhang, "grab me Wang's stapler", "transfer", "zhang"),
        # a service of the office, said with its own verb
        (_ines, "can you press my sample", "press", None),
        (_zhang, "could you sort a coffee for me", "produce", "zhang"),
        # a getting verb without a rule of its own, a thing got for someone: an errand
        (_zhang, "could you track down a stapler for me", "transfer", "zhang"),
        (_zhang, "can you scrounge a pen for me", "transfer", "zhang"),
        # sent the speaker's way, a list included; a wish with no one asked
        (_zhang, "chuck a stapler and some scissors my way", "transfer", "zhang"),
        (_zhang, "could murder a coffee rn", "produce", "zhang"),
        (_zhang, "coffee plz, double espresso", "produce", "zhang"),
        (_zhang, "could you retrieve Wang's stapler for me", "transfer", "zhang"),
    ],
)
def test_known_errands_and_services_are_unchanged(
    read: Any, text: str, kind: str, recipient: str | None
) -> None:
    frame = read(text)
    assert frame.decline is None and frame.question is None, frame
    # a service's task carries its operation; an errand its kind
    assert [t.operation or t.kind for t in frame.tasks][:1] == [kind], frame
    if recipient is not None:
        assert frame.tasks[0].recipient == recipient, frame


@pytest.mark.parametrize(
    "text",
    [
        "just so you know I need Zhang's stapler, could you bring it",
        "please note I need a stapler",
        "chuck my stapler in the meeting room",
        "hope you won't mind getting me a coffee",
    ],
)
def test_a_clause_or_a_placement_after_the_verb_is_no_work_declined(text: str) -> None:
    frame = _zhang(text)
    assert frame.decline is None or "nothing in this office does that" not in frame.decline, frame


def test_a_yes_to_the_one_service_offered_runs_it() -> None:
    frame = answered_reader(load_office, "zhang")("can you sort out my lunch", ["yes please"])
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("heat", "lunch", "zhang")], frame


def test_the_speakers_own_doing_is_no_work_asked() -> None:
    # "I need to polish ...": what the speaker will do; not declined as work asked of me
    frame = _zhang("I need to polish my stapler")
    assert frame.decline is None or "polish" not in frame.decline, frame


def test_work_on_the_speakers_own_thing_for_them_is_still_declined() -> None:
    # "for me" of the speaker's own thing says whom the work is for, not where it goes
    frame = _zhang("could you polish my stapler for me")
    assert not frame.tasks and frame.decline is not None and "polish" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "verb"),
    [
        ("can you frame this print for the corridor?", "frame"),
        ("please frame the print, it's for the lobby", "frame"),
    ],
)
def test_a_service_word_said_as_a_noun_is_no_service_asked(text: str, verb: str) -> None:
    # "this print": a thing after its determiner; the verb asked is the one no work here has
    frame = _zhang(text)
    assert not frame.tasks and frame.decline is not None, frame
    assert f"can't {verb}" in frame.decline, frame


def test_the_services_own_verb_before_its_noun_is_still_the_service() -> None:
    frame = _zhang("print this copy")
    assert frame.decline is None and [t.kind for t in frame.tasks] == ["print"], frame


_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "verb"),
    [
        ("can you dust my report for prints", "dust"),
        ("can you dust my cheque for prints", "dust"),
        ("can you swab my mug for prints", "swab"),
        ("could you photograph my report for copies", "photograph"),
    ],
)
def test_a_plural_goal_after_for_is_no_service_asked(text: str, verb: str) -> None:
    """Fixer 60e class 2: "prints" after "for" is what the unknown verb's work looks for, never
    the print service run on the speaker's file."""
    frame = _lee(text)
    assert frame.tasks == []
    assert frame.decline is not None and f"can't {verb}" in frame.decline


@pytest.mark.parametrize(
    ("text", "operation", "recipient"),
    [
        ("can you print my report for Wang", "print", "wang"),
        ("send my file for printing", "print", "lee"),
    ],
)
def test_the_service_asked_or_named_as_purpose_is_unchanged(
    text: str, operation: str, recipient: str
) -> None:
    frame = _lee(text)
    assert [(t.kind, t.recipient) for t in frame.tasks] == [(operation, recipient)]
