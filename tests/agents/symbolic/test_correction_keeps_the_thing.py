"""A request taken back by "no wait"/"sorry"/"actually" and said again with "it" keeps the
withdrawn request's thing and takes the new recipient (``screen.actually_instead``: a
sentence opening with "actually" and a request of its own corrects, as "no wait" does); the
same work added with "also"/"too"/"as well" is done once more for the other person
(``screen.same_work_added``), never moved away from the requester."""

from __future__ import annotations

import pytest
from _offices import parser

from assistantx.agents.symbolic import InstructionParser
from helpers.rota_desk import rota_desk

_Row = tuple[str, str | None, str | None, str]


def _parser(name: str) -> InstructionParser:
    return InstructionParser(rota_desk()) if name == "rota" else parser(name)


def _tasks(name: str, who: str, text: str, answers: list[str] | None = None) -> list[_Row]:
    p = _parser(name)
    frame = p.parse_with_answers(text, who, answers) if answers else p.parse(text, who)
    assert frame.question is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("name", "who", "text", "done"),
    [
        # the class's analogue, in an office whose file is a rota
        (
            "rota",
            "ada",
            "print the rota for me pls. actually, print it for Bill Okoro, he's running it",
            [("print", "rota", "ada", "bill")],
        ),
        (
            "rota",
            "ada",
            "print the rota for me pls. no wait, print it for Bill Okoro, he's running it",
            [("print", "rota", "ada", "bill")],
        ),
        # other work, people and offices
        (
            "default",
            "lee",
            "heat my lunch for me. actually, heat it for Wang Fang",
            [("heat", "lunch", "lee", "wang")],
        ),
        (
            "harbour",
            "dawn",
            "print the deck for me pls. Actually, print it for Ray Castillo, he's presenting it",
            [("print", "file", "dawn", "ray")],
        ),
        (
            "default",
            "lee",
            "bring me a stapler. actually, can you bring me a pen",
            [("transfer", "pen", None, "lee")],
        ),
    ],
)
def test_actually_with_a_request_of_its_own_takes_back_the_one_before(
    name: str, who: str, text: str, done: list[_Row]
) -> None:
    assert _tasks(name, who, text) == done


@pytest.mark.parametrize(
    ("text", "answer"),
    [
        # "plan" is only the head of the office's "shift plan": which file "it" is is asked,
        # and the answer put in its place must not bring the withdrawn printout back
        ("print the plan for me pls. actually, print it for Bill Okoro, he's running it", "Mine."),
        ("print the plan for me. sorry, print it for Bill Okoro", "My rota."),
        ("print the plan for me pls. no wait, print it for Bill Okoro", "Mine."),
    ],
)
def test_the_answer_about_it_keeps_the_new_recipient(text: str, answer: str) -> None:
    asked = _parser("rota").parse(text, "ada")
    assert asked.question is not None and "'it'" in asked.question, asked
    assert _tasks("rota", "ada", text, [answer]) == [("print", "rota", "ada", "bill")]


@pytest.mark.parametrize(
    ("name", "who", "text", "done"),
    [
        # must not change (the class's neighbour): the same work added is done twice
        (
            "rota",
            "ada",
            "print the rota for me. also print it for Bill Okoro",
            [("print", "rota", "ada", "ada"), ("print", "rota", "ada", "bill")],
        ),
        (
            "rota",
            "ada",
            "print the rota for me pls. actually, print it for Bill Okoro too",
            [("print", "rota", "ada", "ada"), ("print", "rota", "ada", "bill")],
        ),
        (
            "harbour",
            "dawn",
            "laminate my badge for me. laminate it for Pat Nowak too",
            [("heat", "badge", "dawn", "dawn"), ("heat", "badge", "dawn", "pat")],
        ),
        (
            "default",
            "lee",
            "print my file for me, and print it for Wang Fang as well",
            [("print", "file", "lee", "lee"), ("print", "file", "lee", "wang")],
        ),
        # another thing added is its own task, as before
        (
            "default",
            "lee",
            "heat my lunch. also bring me a pen",
            [("heat", "lunch", "lee", "lee"), ("transfer", "pen", None, "lee")],
        ),
    ],
)
def test_the_same_work_added_for_another_is_done_once_more(
    name: str, who: str, text: str, done: list[_Row]
) -> None:
    assert _tasks(name, who, text) == done


@pytest.mark.parametrize(
    ("name", "who", "text"),
    [
        ("rota", "ada", "print the rota. no wait, don't"),
        ("default", "lee", "print my file. actually, don't"),
    ],
)
def test_must_not_change_a_request_taken_back_does_nothing(name: str, who: str, text: str) -> None:
    frame = _parser(name).parse(text, who)
    assert frame.tasks == [] and frame.decline is not None, frame


def test_must_not_change_actually_before_news_is_no_correction() -> None:
    """ "actually, Wang Fang has one" says where one is: the stapler is still wanted."""
    assert _tasks("default", "lee", "bring me a stapler. actually, Wang Fang has one") == [
        ("transfer", "stapler", "wang", "lee")
    ]
