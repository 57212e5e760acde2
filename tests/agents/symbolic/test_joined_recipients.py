"""Two or more people joined by "and" where one recipient stands each receive: a product is
made once for each, one physical thing is asked about, and the thing never goes to the
requester when the sentence names others (``reading.joined_recipients``)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.joined_recipients import joined_recipients
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import tokenize
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_DEFAULT = frame_reader(default_office, "lee")
_HARBOUR = frame_reader(harbour_office, "will")


def _tasks(frame: object) -> list[tuple[str, str | None, str | None, str]]:
    tasks = getattr(frame, "tasks", [])
    return sorted((t.kind, t.item, t.owner, t.recipient) for t in tasks)


@pytest.mark.parametrize(
    ("text", "item", "people"),
    [
        ("bring Wang and Sun a coffee", "coffee", ["sun", "wang"]),  # the class's analogue
        ("bring a coffee for Wang and Sun", "coffee", ["sun", "wang"]),
        ("get Wang, Sun and Mao a water", "water", ["mao", "sun", "wang"]),
        ("Wang and Sun need a water", "water", ["sun", "wang"]),
        ("Wang and Sun are in. bring them both a water", "water", ["sun", "wang"]),
        ("could you get a water for both of them? Wang and Sun", "water", ["sun", "wang"]),
    ],
)
def test_a_product_is_made_for_each_joined_recipient(
    text: str, item: str, people: list[str]
) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [("produce", item, None, p) for p in people], frame


def test_a_pronoun_in_the_group_is_the_colleague_named_before() -> None:
    frame = _DEFAULT("Wang needs my stapler, bring him and Sun a coffee")
    assert frame.question is None, frame
    assert _tasks(frame) == [
        ("produce", "coffee", None, "sun"),
        ("produce", "coffee", None, "wang"),
        ("transfer", "stapler", "lee", "wang"),
    ], frame


@pytest.mark.parametrize(
    ("text", "people"),
    [
        ("print my file for Wang and Sun", ["sun", "wang"]),
        ("print the agenda for Mao and Zhang", ["mao", "zhang"]),
        ("email my file to Wang and Sun", ["sun", "wang"]),  # once each, not twice
    ],
)
def test_a_print_or_file_goes_to_each(text: str, people: list[str]) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    kinds = {t.kind for t in frame.tasks}
    assert len(kinds) == 1, frame
    assert sorted(t.recipient for t in frame.tasks) == people, frame
    assert all(t.owner == "lee" for t in frame.tasks), frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "get Rose and Mark a tea each",
            [("produce", "tea", None, "mark"), ("produce", "tea", None, "rose")],
        ),
        (
            "print the agenda for Rose and Mark",
            [("print", "file", "will", "mark"), ("print", "file", "will", "rose")],
        ),
        (
            "bring me and Mark a tea",
            [("produce", "tea", None, "mark"), ("produce", "tea", None, "will")],
        ),
    ],
)
def test_harbour_joined_recipients(text: str, tasks: list[tuple[str, str, str, str]]) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert _tasks(frame) == tasks, frame


@pytest.mark.parametrize(
    "text",
    [
        "Wang and Sun need a stapler",  # a neighbour: one stapler, two in need
        "give Wang and Sun my stapler",
        "take the book to Wang and Sun",
    ],
)
def test_one_physical_thing_for_two_is_asked(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.tasks == [], frame
    assert frame.question is not None
    assert "Wang Fang, or to Sun Li?" in frame.question, frame


def test_the_requester_joined_with_a_colleague_both_receive() -> None:
    """Neighbour: "me and Wang" (the requester included) is both, as before."""
    frame = _DEFAULT("bring me and Wang a coffee")
    assert _tasks(frame) == [
        ("produce", "coffee", None, "lee"),
        ("produce", "coffee", None, "wang"),
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Wang is in. bring them both a water",  # both of one named: whom?
        "bring them both a water",
    ],
)
def test_them_both_of_nobody_two_is_asked(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.tasks == [], frame
    assert frame.question is not None and "'them'" in frame.question, frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # neighbours: one recipient each, no group
        ("bring Wang a coffee", [("produce", "coffee", None, "wang")]),
        ("bring me a coffee", [("produce", "coffee", None, "lee")]),
        (
            "bring my stapler to Wang and a coffee for me",
            [("produce", "coffee", None, "lee"), ("transfer", "stapler", "lee", "wang")],
        ),
    ],
)
def test_one_recipient_each_is_unchanged(text: str, tasks: list[tuple[str, str, str, str]]) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == sorted(tasks), frame


def _mentions(words: str, kinds: dict[int, tuple[str, str]]) -> list[Mention]:
    return [
        Mention(kind, n, n + 1, (who,) if kind == "person" else (), text=words.split()[n])  # type: ignore[arg-type]
        for n, (kind, who) in sorted(kinds.items())
    ]


def test_a_comma_alone_joins_no_group() -> None:
    """ "Wang, Sun needs a water": Wang is addressed; a list needs its "and"."""
    tokens = tokenize("Wang, Sun needs a water")
    ms = _mentions("Wang Sun needs a water", {0: ("person", "wang"), 1: ("person", "sun")})
    assert joined_recipients(tokens, ms, "lee", []) == []


def test_a_name_that_starts_a_clause_is_no_member() -> None:
    """ "take it to Wang and Sun will sign it": Sun is the next clause's subject."""
    tokens = tokenize("take it to Wang and Sun will sign it")
    ms = _mentions(
        "take it to Wang and Sun will sign it", {3: ("person", "wang"), 5: ("person", "sun")}
    )
    assert joined_recipients(tokens, ms, "lee", []) == []


@pytest.mark.parametrize(
    ("read", "text", "expected"),
    [
        (
            _DEFAULT,
            "make a coffee for me and for Chen",
            [("produce", "coffee", None, "chen"), ("produce", "coffee", None, "lee")],
        ),
        (
            _DEFAULT,
            "print my file for me and for Wang Fang",
            [("print", "file", "lee", "lee"), ("print", "file", "lee", "wang")],
        ),
        (
            _DEFAULT,
            "take a water to Mao and to Sun",
            [("produce", "water", None, "mao"), ("produce", "water", None, "sun")],
        ),
        # a sequence word between: only Wang's printout was made, and "me" was dropped
        (
            _DEFAULT,
            "print my file for me and then for Wang",
            [("print", "file", "lee", "lee"), ("print", "file", "lee", "wang")],
        ),
        (
            _DEFAULT,
            "take a water to Mao and also to Sun",
            [("produce", "water", None, "mao"), ("produce", "water", None, "sun")],
        ),
    ],
)
def test_the_receiving_word_said_again_joins_the_same_group(
    read: ReadFrame, text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    """ "for me and for Chen": before, only the last got the thing and "me" was dropped unsaid
    (one coffee, Chen's)."""
    frame = read(text)
    assert frame.question is None, frame
    assert _tasks(frame) == expected, frame


@pytest.mark.parametrize(
    "text",
    ["bring Wang's stapler to Mao and to Sun", "bring Wang's stapler to Mao and then to Sun"],
)
def test_one_thing_for_two_said_again_is_asked_about(text: str) -> None:
    frame = _DEFAULT(text)
    assert not frame.tasks
    assert frame.question is not None and "only one of them" in frame.question
