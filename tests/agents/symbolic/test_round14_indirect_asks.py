"""Polite indirect asks on a community radio station no sentence was written for
(``helpers.radio_station``; the blind round's office and sentences were never read): a
question put to somebody that asks for an office task on something ("would somebody be able
to bring me a glue stick?") is a request; one that asks to be told or to know ("would anyone
know where ...", "is anyone able to tell me who ...") is a question answered in words, and
moves nothing."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.indirect_asks import asked_verb_at, indirect_ask
from helpers.radio_station import radio_station
from helpers.reading import frame_reader

_TASK_VERBS = frozenset({"bring", "grab", "get", "fetch", "find", "print"})


_frame = frame_reader(radio_station, "wren")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        (
            "Would somebody be able to bring me a glue stick from the supply cupboard? Thanks!",
            "glue_stick",
        ),
        ("would anyone be able to bring me a glue stick", "glue_stick"),
        ("is anyone able to grab me a marker pen?", "marker_pen"),
        ("would it be possible to get a glue stick?", "glue_stick"),
        ("would it be possible for someone to fetch me a glue stick?", "glue_stick"),
        ("could someone possibly bring a glue stick over", "glue_stick"),
        ("any chance someone could fetch me a glue stick?", "glue_stick"),
        ("is there any chance somebody could grab me a marker pen?", "marker_pen"),
        # a later time is read as every request with one is: the errand itself
        ("could someone bring me a glue stick tomorrow?", "glue_stick"),
    ],
)
def test_a_polite_indirect_ask_for_a_task_is_a_request(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "wren")]


@pytest.mark.parametrize(
    "text",
    [
        "would anyone know where the glue sticks are?",
        "is anyone able to tell me who has the van keys?",
        "could anyone tell me who has the van keys?",
        "would you know where the glue sticks are?",
        "could you find out whether Linnea has a glue stick?",
        "does anybody have a glue stick?",
    ],
)
def test_an_indirect_ask_to_know_is_answered_in_words(text: str) -> None:
    """Near-misses: asked to know or to tell, nothing is fetched; the answer may offer."""
    frame = _frame(text)
    assert not frame.tasks, frame
    said = frame.question or frame.decline or ""
    assert "As far as I know" in said, said


@pytest.mark.parametrize(
    ("words", "verb"),
    [
        ("would somebody be able to bring me a pen", "bring"),
        ("is anyone able to grab me a pen", "grab"),
        ("would it be possible for you to get a pen", "get"),
        ("is there any chance that someone could possibly fetch a pen", "fetch"),
        ("could you please just bring a pen", "bring"),
    ],
)
def test_the_asking_frame_is_set_aside_to_the_verb(words: str, verb: str) -> None:
    w = words.split()
    at = asked_verb_at(w)
    assert at is not None and w[at] == verb
    assert indirect_ask(w, _TASK_VERBS) == "polite"


@pytest.mark.parametrize(
    ("words", "kind"),
    [
        ("would anyone know where the pens are", "info"),
        ("is anyone able to tell me who has a pen", "info"),
        ("could you find out whether Ana has a pen", "info"),
        ("does anyone have a pen", None),  # no asking frame: the speech stage decides
        ("will Ray be in tomorrow", None),
        ("would somebody be around", None),  # no task verb asked for
        ("could someone bring", None),  # a task verb with nothing to do it on
        ("could you print in colour", None),  # what can be done, nothing to do it on
        ("bring me a pen", None),
    ],
)
def test_what_is_not_a_polite_ask_for_a_task(words: str, kind: str | None) -> None:
    assert indirect_ask(words.split(), _TASK_VERBS) == kind


async def test_the_glue_stick_asked_for_politely_is_brought() -> None:
    run = await run_instruction(
        radio_station(),
        "wren",
        "Would somebody be able to bring me a glue stick from the supply cupboard? Thanks!",
    )
    assert run.stm.trace.outcome == "done"
    assert run.sim.world.holder["glue_stick:linnea"] == "wren"


async def test_a_question_put_politely_moves_nothing() -> None:
    run = await run_instruction(
        radio_station(), "wren", "would anyone know where the glue sticks are?"
    )
    assert not run.sim.world.handovers()
    assert run.sim.world.holder["glue_stick:linnea"] == "store_room"
