"""A colleague's thing given back goes from the speaker to its owner (``reading/given_back``):
"return Wang's stapler" collects Wang's stapler from the speaker and hands it to Wang, never
asks Wang to lend it, never borrows Zhang's for Wang, never asks who should get it. The
simulated requester has the thing they give back (``sim/lent_back``), so the run ends done.
The speaker's own thing given ("return my book to Zhang"), a borrow ("bring me Wang's
stapler") and the past ("Wang returned my stapler") stay as they were."""

from __future__ import annotations

import pytest
from _offices import parser
from symbolic_run import run_instruction

from assistantx.sim.lent_back import gives_back, lent_to_requester
from assistantx.sim.requester import Wish
from helpers.dataset_offices import default_office, harbour_office

_DEFAULT = [
    ("return Wang's stapler", ("stapler", "wang")),
    ("please return Wang's stapler, I'm done with it", ("stapler", "wang")),
    ("can you return the stapler to Wang", ("stapler", "wang")),
    ("can you return Zhang's book for me", ("book", "zhang")),
    ("take Wang's stapler back to him", ("stapler", "wang")),
    ("give Wang his stapler back", ("stapler", "wang")),
    ("hand Sun back her scissors", ("scissors", "sun")),
    ("could you bring Zhang's stapler back to him please", ("stapler", "zhang")),
    ("Wang lent me his stapler, please return it to him", ("stapler", "wang")),
]
_HARBOUR = [
    ("return Will's calculator", ("calculator", "will")),
    ("can you return the ruler to Mark", ("ruler", "mark")),
    ("give Rose her brolly back", ("umbrella", "rose")),
    ("take Bill's charger back to him please", ("charger", "bill")),
    ("please hand Mark back his ruler, I'm finished with it", ("ruler", "mark")),
    # the owner said, though the office does not know the ruler as Ray's: no guess made
    ("the ruler on my desk belongs to Ray, please return it to him", ("ruler", "ray")),
]


def _read(office: str, text: str, requester: str) -> list[tuple[str | None, ...]]:
    frame = parser(office).parse(text, requester)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.recipient, t.source) for t in frame.tasks]


@pytest.mark.parametrize(("text", "thing"), _DEFAULT)
def test_given_back_goes_from_the_speaker_to_the_owner(text: str, thing: tuple[str, str]) -> None:
    item, owner = thing
    assert _read("default", text, "lin") == [("transfer", item, owner, owner, "lin")]


@pytest.mark.parametrize(("text", "thing"), _HARBOUR)
def test_given_back_goes_from_the_speaker_to_the_owner_on_harbour(
    text: str, thing: tuple[str, str]
) -> None:
    item, owner = thing
    assert _read("harbour", text, "may") == [("transfer", item, owner, owner, "may")]


@pytest.mark.parametrize(
    ("office", "text", "requester", "task"),
    [
        ("default", "return my book to Zhang", "lin", ("transfer", "book", "lin", "zhang", None)),
        ("default", "give Wang my stapler", "lin", ("transfer", "stapler", "lin", "wang", None)),
        (
            "default",
            "bring me Wang's stapler",
            "lin",
            ("transfer", "stapler", "wang", "lin", None),
        ),
        ("harbour", "return my tape to Will", "may", ("transfer", "tape", "may", "will", None)),
        (
            "harbour",
            "bring me Rose's umbrella",
            "may",
            ("transfer", "umbrella", "rose", "may", None),
        ),
    ],
)
def test_neighbours_keep_their_reading(
    office: str, text: str, requester: str, task: tuple[str | None, ...]
) -> None:
    assert _read(office, text, requester) == [task]


@pytest.mark.parametrize(
    ("office", "text", "requester"),
    [("default", "Wang returned my stapler", "lin"), ("harbour", "Mark returned my tape", "may")],
)
def test_a_past_return_is_a_statement(office: str, text: str, requester: str) -> None:
    frame = parser(office).parse(text, requester)
    assert frame.tasks == [] and frame.question is None


@pytest.mark.parametrize(
    ("office", "text", "requester", "name"),
    [
        ("default", "return the stapler", "lin", "stapler"),
        ("default", "could you take the book back", "lin", "book"),
        ("harbour", "return the calculator please", "may", "calculator"),
    ],
)
def test_a_return_of_nobody_said_asks_whose(
    office: str, text: str, requester: str, name: str
) -> None:
    frame = parser(office).parse(text, requester)
    assert frame.tasks == []
    assert frame.question == f"Whose {name} is it, and who should I give it back to?"


def test_a_thing_noun_return_is_no_giving_back() -> None:
    frame = parser("default").parse("bring me Wang's tax return", "lin")
    assert not any(t.source == "lin" for t in frame.tasks)


@pytest.mark.parametrize(
    ("office", "requester", "text", "owner", "item"),
    [
        ("default", "lin", "return Wang's stapler", "wang", "stapler:wang"),
        ("default", "lin", "give Wang his stapler back", "wang", "stapler:wang"),
        ("harbour", "may", "can you return the ruler to Mark", "mark", "ruler:mark"),
    ],
)
async def test_the_run_collects_from_the_speaker_and_hands_to_the_owner(
    office: str, requester: str, text: str, owner: str, item: str
) -> None:
    run = await run_instruction(
        default_office() if office == "default" else harbour_office(), requester, text
    )
    assert run.stm.trace.outcome == "done"
    # the summary says it went back, in words, never "X now has X's stapler"
    thing = item.split(":")[0]
    assert f"now has their {thing} back" in run.stm.trace.summary, run.stm.trace.summary
    codes = [(c.person, c.purpose, c.item) for c in run.sim.codes]
    assert codes == [(requester, "deposit", item), (owner, "collect", item)]
    assert run.sim.world.holder[item] == owner
    asked = [r.action for r in run.stm.trace.actions() if r.action.type == "inquire"]
    assert all("lend" not in getattr(a, "question", "") for a in asked)


def test_the_simulated_requester_has_only_what_they_give_back() -> None:
    office = default_office()
    holder = {"stapler:wang": "wang", "stapler:zhang": "locker"}
    said = Wish.from_words(office, "lin", "return Wang's stapler")
    assert lent_to_requester(office, holder, said, "stapler:wang")
    borrowed = Wish.from_words(office, "lin", "bring me Wang's stapler")
    assert not lent_to_requester(office, holder, borrowed, "stapler:wang")
    elsewhere = Wish.from_words(office, "lin", "return Zhang's stapler")
    assert not lent_to_requester(office, holder, elsewhere, "stapler:zhang")  # moved: as left
    goal = Wish.from_goal(office, "lin", [{"holds": ["wang", "stapler:wang"]}])
    assert gives_back(office, goal, "stapler:wang")
    to_other = Wish.from_goal(office, "lin", [{"holds": ["lin", "stapler:wang"]}])
    assert not gives_back(office, to_other, "stapler:wang")


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "bring me a pen and return Wang's stapler",
            [("pen", None, "lin", None), ("stapler", "wang", "wang", "lin")],
        ),
        (
            "return Wang's stapler and bring me a pen",
            [("stapler", "wang", "wang", "lin"), ("pen", None, "lin", None)],
        ),
        (
            "grab me Sun's scissors, then take Zhang's stapler back",
            [("scissors", "sun", "lin", None), ("stapler", "zhang", "zhang", "lin")],
        ),
    ],
)
def test_only_the_clause_that_gives_back_returns_its_thing(
    text: str, tasks: list[tuple[str | None, ...]]
) -> None:
    frame = parser("default").parse(text, "lin")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner, t.recipient, t.source) for t in frame.tasks] == tasks


@pytest.mark.parametrize(
    "text",
    [
        "I need a stapler and I'll give it back later",  # the speaker's own doing, told
        "Take my lamp to Wang, and could I borrow Zhang's stapler in return?",  # a noun
        "borrow Wang's stapler and take it back to him",  # taken first: not the speaker's
    ],
)
def test_no_request_to_give_back_takes_nothing_from_the_speaker(text: str) -> None:
    frame = parser("default").parse(text, "lin")
    assert not any(t.source == "lin" for t in frame.tasks), frame


def test_a_thing_the_speaker_wants_back_is_theirs_to_have() -> None:
    frame = parser("default").parse("bring me Wang's stapler back", "lin")
    assert [(t.owner, t.recipient, t.source) for t in frame.tasks] == [("wang", "lin", None)]
