"""The speaker's announced taking of a colleague's thing is a borrow request, asked of the
owner (``reading/announced_borrowing``): "my stapler's broken so I'm borrowing Wang's for the
afternoon, if he doesn't mind" fetches Wang's stapler with Wang's consent, never "Noted". The
past ("I borrowed ..."), someone else's borrowing, a giving back and nobody's thing move
nothing."""

from __future__ import annotations

import pytest
from _offices import parser
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.announced_borrowing import announced_borrowings
from helpers.dataset_offices import harbour_office

_DEFAULT = [
    (
        "my stapler's broken so I'm borrowing Wang's for the afternoon, if he doesn't mind",
        ("stapler", "wang"),
    ),
    ("I'm borrowing Sun's scissors for the meeting", ("scissors", "sun")),
    ("I'm borrowing Zhang's stapler for the meeting", ("stapler", "zhang")),
    ("I'm going to borrow Chen's pen", ("pen", "chen")),  # already read: the reference
    ("I'll be borrowing Hu's pen for a bit", ("pen", "hu")),
    ("I'm nicking Wang's stapler for a sec", ("stapler", "wang")),
    ("I'm gonna borrow Dang's mugs for the visitors", ("cup", "dang")),  # a plural synonym
]
_HARBOUR = [
    (
        "my calculator's dead so I'm borrowing Will's for the morning, if he doesn't mind",
        ("calculator", "will"),
    ),
    ("I'll be borrowing Rose's brolly for lunch", ("umbrella", "rose")),
    ("I'm going to pinch Mark's ruler for a minute", ("ruler", "mark")),
    ("Im swiping Bill's charger for a sec", ("charger", "bill")),
]


@pytest.mark.parametrize(("text", "wanted"), _DEFAULT)
def test_an_announced_borrowing_is_asked_of_the_owner_on_the_default_office(
    text: str, wanted: tuple[str, str]
) -> None:
    frame = parser("default").parse(text, "lin")
    assert frame.question is None and frame.decline is None
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", *wanted, "lin")
    ]


@pytest.mark.parametrize(("text", "wanted"), _HARBOUR)
def test_an_announced_borrowing_is_asked_of_the_owner_on_harbour(
    text: str, wanted: tuple[str, str]
) -> None:
    frame = parser("harbour").parse(text, "may")
    assert frame.question is None and frame.decline is None
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", *wanted, "may")
    ]


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("default", "lin", "I borrowed Wang's stapler yesterday"),
        ("default", "lin", "Wang is borrowing my stapler"),
        ("default", "lin", "I'm returning Wang's stapler"),
        ("default", "lin", "I'm borrowing a pen"),
        ("default", "lin", "I'm not borrowing Wang's stapler"),
        # the speaker's own remedy for a lack, decided (test_stated_lack_offered)
        ("default", "lin", "I don't have a pen, I'll borrow Chen's"),
        ("harbour", "may", "I borrowed Will's calculator yesterday"),
        ("harbour", "may", "Rose is borrowing my umbrella"),
        ("harbour", "may", "I'm returning Mark's ruler"),
    ],
)
def test_the_past_someone_elses_borrowing_and_a_return_move_nothing(
    office: str, who: str, text: str
) -> None:
    frame = parser(office).parse(text, who)
    assert not frame.tasks and frame.question is None


async def test_the_owner_is_asked_before_the_thing_is_brought() -> None:
    run = await run_instruction(
        harbour_office(), "may", "I'll be borrowing Rose's brolly for lunch, if she doesn't mind"
    )
    assert run.stm.trace.outcome == "done"
    assert run.actions.index("inquire") < run.actions.index("move")


def _people(word: str) -> bool:
    return word.lower() in {"wang", "hu"}


@pytest.mark.parametrize(
    ("text", "read"),
    [
        (
            "my stapler's broken so I'm borrowing Wang's for the afternoon",
            "my stapler's broken, so can I borrow Wang's for the afternoon",
        ),
        ("thanks. I'll be borrowing Hu's pen", "thanks. can I borrow Hu's pen"),
        ("I'm borrowing the stapler", "I'm borrowing the stapler"),  # nobody's to ask
        ("I'm borrowing Zhou's pen", "I'm borrowing Zhou's pen"),  # no colleague here
        ("I borrowed Wang's pen", "I borrowed Wang's pen"),
    ],
)
def test_announced_borrowings_rewrites_only_a_colleagues_thing(text: str, read: str) -> None:
    assert announced_borrowings(text, _people) == read
