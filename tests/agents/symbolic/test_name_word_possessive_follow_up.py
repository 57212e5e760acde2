"""A colleague whose name is also a verb ("Hope"), written capitalised with "'s" after a
need or a request, names the owner ("need a calculator. Hope's please"): a verb is never
spelled with an apostrophe, so the hope screen (``screen.hope``) leaves "Hope's" to the
lexicon, which reads it as hers. Lower-case "hope's not lost" is still the ordinary word."""

from __future__ import annotations

import pytest
from _offices import parser


def _read(name: str, who: str, text: str) -> list[tuple[str, str | None, str | None, str]]:
    frame = parser(name).parse(text, who)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("name", "who", "text", "tasks"),
    [
        # the class's analogue
        (
            "harbour",
            "will",
            "need a calculator. Hope's please",
            [("transfer", "calculator", "hope", "will")],
        ),
        # other phrasings, other things, other name words
        (
            "harbour",
            "will",
            "need a calculator. Hope's would do",
            [("transfer", "calculator", "hope", "will")],
        ),
        (
            "harbour",
            "mark",
            "can I borrow a ruler? Hope's please",
            [("transfer", "ruler", "hope", "mark")],
        ),
        (
            "harbour",
            "mark",
            "I need a calculator. Hope's would be great",
            [("transfer", "calculator", "hope", "mark")],
        ),
        (
            "harbour",
            "mark",
            "need a calculator. Will's please",
            [("transfer", "calculator", "will", "mark")],
        ),
        (
            "harbour",
            "mark",
            "need a ruler. Rose's would do",
            [("transfer", "ruler", "rose", "mark")],
        ),
        # must not change: a name that is no word, on the default office
        (
            "default",
            "mao",
            "need a stapler. Wang's please",
            [("transfer", "stapler", "wang", "mao")],
        ),
        (
            "default",
            "mao",
            "need a stapler. Wang's would do",
            [("transfer", "stapler", "wang", "mao")],
        ),
    ],
)
def test_capitalised_name_with_s_names_the_owner(
    name: str, who: str, text: str, tasks: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(name, who, text) == tasks


def test_lower_case_word_stays_a_hope() -> None:
    """must not change: "hope's not lost" is the ordinary word, answered in words."""
    frame = parser("harbour").parse("hope's not lost", "will")
    assert not frame.tasks and frame.question is None, frame
    assert (frame.decline or "").startswith("I hope so too"), frame


def test_a_hope_about_a_colleague_is_still_one() -> None:
    """must not change: the verb itself, about a colleague named as a word ("Mark")."""
    frame = parser("harbour").parse("hoping Mark finds his keys", "will")
    assert not frame.tasks and (frame.decline or "").startswith("I hope so too"), frame
