"""A correction after "actually": "bring me a pen from chen. actually lee's, chen's using his"
brought Chen's pen. The later owner replaces the earlier one, said as whom the thing comes from
("from Chen") or as its possessive ("Chen's pen"), after a sentence end, a comma or a dash; the
reason said beside it ("chen's using his") is context (``screen.correction``: "actually" and
one word before a pause or the end; ``possessive_corrections``: the bare possessive right after
"from <name>"; ``accepted_owner``: a possessive after a correction's word is no second choice).
A real second request after "actually" is read as one, and "actually" with no person or thing
after it corrects nothing."""

from __future__ import annotations

import pytest
from _offices import tasks_of


@pytest.mark.parametrize(
    ("office", "requester", "text", "owner"),
    [
        # the class's analogue
        ("default", "sun", "bring me a pen from chen. actually lee's, chen's using his", "lee"),
        # variants: the possessive said first, a comma, a dash, other people, things, offices
        ("default", "sun", "bring me Chen's pen. actually lee's, chen's using his", "lee"),
        ("default", "sun", "bring me a pen from chen. actually, lee's", "lee"),
        ("default", "mao", "grab me a stapler from Zhang. actually Wang's, Zhang needs his",
         "wang"),
        ("default", "sun", "bring me a pen from Chen Jie - actually Lee's, Chen's using his",
         "lee"),
        ("harbour", "may", "could you bring me a ruler from Mark. actually Art's, Mark's using his",
         "art"),
        ("harbour", "may", "get me a calculator from Will - actually Dawn's, Will needs hers",
         "dawn"),
    ],
)  # fmt: skip
def test_the_later_owner_replaces_the_earlier(
    office: str, requester: str, text: str, owner: str
) -> None:
    tasks = tasks_of(office, text, requester)
    assert [(owner_, recipient) for _, _, owner_, recipient in tasks] == [(owner, requester)]


@pytest.mark.parametrize(
    ("office", "requester", "text", "got"),
    [
        # a thing said after "actually" replaces the thing
        ("harbour", "may", "bring me a ruler. actually a calculator",
         [("transfer", "calculator", None, "may")]),
        # a person said alone after "actually" replaces the receiver
        ("harbour", "may", "take my letter to Mark. Actually, Art.",
         [("transfer", "document", "may", "art")]),
    ],
)  # fmt: skip
def test_a_thing_or_a_receiver_said_after_actually_replaces_it(
    office: str, requester: str, text: str, got: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of(office, text, requester) == got


@pytest.mark.parametrize(
    ("office", "requester", "text", "got"),
    [
        # a real second request: both stand
        ("harbour", "may",
         "bring me a ruler from Mark. Actually, could you also bring me a charger from Bill?",
         [("transfer", "ruler", "mark", "may"), ("transfer", "charger", "bill", "may")]),
        ("default", "sun", "bring me a pen from chen. Actually, could you also bring me a stapler",
         [("transfer", "pen", "chen", "sun"), ("transfer", "stapler", None, "sun")]),
        # "actually" with nobody and no thing after it corrects nothing
        ("default", "sun", "bring me a pen from chen. actually, thanks",
         [("transfer", "pen", "chen", "sun")]),
        # the owner said after a second thing is that thing's, not a correction of the source
        ("default", "sun", "bring me a pen from chen and a stapler, Zhang's",
         [("transfer", "pen", "chen", "sun"), ("transfer", "stapler", "zhang", "sun")]),
    ],
)  # fmt: skip
def test_must_not_change(
    office: str, requester: str, text: str, got: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of(office, text, requester) == got
