"""A colleague asked to run a service is its doer only if they keep a facility that offers it
(``reading.named_doer``, the service shapes of ``named_maker``): "could Wang print my file?"
where Wang keeps no printer is said and asked ("Wang Fang doesn't look after the printer.
Shall I ...?"), a yes doing it with the keepers; a keeper so named does it. A name after the
verb or before a need is whom it is for, as before."""

from __future__ import annotations

import pytest
from _offices import parser
from symbolic_run import run_instruction

from helpers.mending_room import mending_room
from helpers.reading import answered_reader

_Row = tuple[str, str | None, str | None, str, str | None]


def _tasks(name: str, who: str, text: str, answers: list[str] | None = None) -> list[_Row]:
    p = parser(name)
    frame = p.parse_with_answers(text, who, answers) if answers else p.parse(text, who)
    return [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks]


@pytest.mark.parametrize(
    ("name", "who", "text", "question", "done"),
    [
        # the class's analogue
        (
            "default",
            "mao",
            "could Wang print my file?",
            "Wang Fang doesn't look after the printer. Shall I print your file for you?",
            ("print", "file", "mao", "mao", None),
        ),
        # other services, other people, other offices
        (
            "default",
            "lee",  # fix129e: one with lunch in the fridge
            "can Wang heat my lunch?",
            "Wang Fang doesn't look after the microwave. Shall I heat your lunch for you?",
            ("heat", "lunch", "lee", "lee", None),
        ),
        (
            "default",
            "lee",
            "could Zhang copy my document please",
            "Zhang Wei doesn't look after the printer. Shall I copy your document for you?",
            ("copy", "document", "lee", "lee", None),
        ),
        (
            "harbour",
            "will",
            "could Rose scan my document?",
            "Rose Adeyemi doesn't look after the scanner. Shall I scan your document for you?",
            ("copy", "document", "will", "will", None),
        ),
        (
            "harbour",
            "will",
            "could Rose laminate my badge?",
            "Rose Adeyemi doesn't look after the laminator. Shall I laminate your badge for you?",
            ("heat", "badge", "will", "will", None),
        ),
    ],
)
def test_one_who_keeps_no_facility_for_it_is_said_and_asked(
    name: str, who: str, text: str, question: str, done: _Row
) -> None:
    frame = parser(name).parse(text, who)
    assert not frame.tasks and frame.question == question, frame
    assert _tasks(name, who, text, ["yes"]) == [done]
    assert _tasks(name, who, text, ["no"]) == []


@pytest.mark.parametrize(
    ("name", "who", "text", "done"),
    [
        # a keeper of a facility that offers it does it
        (
            "default",
            "mao",
            "could Xu print my file?",
            ("print", "file", "mao", "mao", "xu"),
        ),
        (
            "default",
            "wang",
            "could Mao print my file?",
            ("print", "file", "wang", "wang", "mao"),
        ),
        (
            "default",
            "lee",  # fix129e: one with lunch in the fridge
            "can Hu heat my lunch?",
            ("heat", "lunch", "lee", "lee", "hu"),
        ),
        (
            "harbour",
            "will",
            "could Mark scan my document?",
            ("copy", "document", "will", "will", "mark"),
        ),
        (
            "harbour",
            "will",
            "could Sue laminate my badge?",
            ("heat", "badge", "will", "will", "sue"),
        ),
        # must not change: whom it is for, after the verb or before a need
        (
            "default",
            "mao",
            "could you print my file for Wang",
            ("print", "file", "mao", "wang", None),
        ),
    ],
)
def test_named_keeper_does_it_and_others_receive(
    name: str, who: str, text: str, done: _Row
) -> None:
    assert _tasks(name, who, text) == [done]


def test_a_need_of_a_colleague_is_still_whom_it_is_for() -> None:
    """must not change: "Wang needs my file printed" offers it to Wang."""
    frame = parser("default").parse("Wang needs my file printed", "mao")
    assert frame.question == "Shall I print your file for Wang Fang?", frame


async def test_the_named_keeper_is_the_one_asked() -> None:
    """Mao is the printer's second keeper: asked, not the first on the list."""
    from _offices import office

    run = await run_instruction(office("default"), "wang", "could Mao print my file?")
    asked = [
        r.action.contact
        for r in run.stm.trace.actions()
        if r.action.type == "inquire" and not r.refused
    ]
    assert asked[:1] == ["mao"], asked


_MENDING = answered_reader(mending_room, "rosa")  # the mending bench: Nell Oduya, Omar Vance


def test_a_small_office_of_its_own_words() -> None:
    """An office's own service and verbs ("mend", "repair"): Lee keeps no bench, Omar does."""
    asked = _MENDING("can Lee repair my book")
    assert not asked.tasks, asked
    assert asked.question == (
        "Lee Hart doesn't look after the mending bench. Shall I mend your book for you?"
    )
    assert [
        (t.item, t.recipient, t.actor) for t in _MENDING("can Lee repair my book", ["yes"]).tasks
    ] == [("book", "rosa", None)]
    done = _MENDING("could Omar fix my book?")
    assert [(t.item, t.recipient, t.actor) for t in done.tasks] == [("book", "rosa", "omar")]
