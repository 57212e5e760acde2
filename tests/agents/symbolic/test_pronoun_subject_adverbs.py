"""An adverb between a pronoun subject and its need's verb ("Wang's back. she *really* needs a
stapler") is read as the need itself: the pronoun is the colleague named before it, by the
dictionary's adverbs (``subject_adverbs.is_adverb_before_verb``, in
``screen.pronoun_subject``), not a list of them. One that denies ("she *hardly* needs")
states no need. Before a need's verb "still" is an adverb too ("Wang still needs a stapler")."""

from __future__ import annotations

import pytest
from _offices import parser


@pytest.mark.parametrize(
    ("name", "who", "text", "question"),
    [
        # the class's analogue
        ("default", "mao", "Wang's back. she really needs a stapler", "a stapler to Wang Fang"),
        # other adverbs, other people, other things, other offices
        ("default", "mao", "Zhang's here. he definitely needs a stapler", "a stapler to Zhang Wei"),
        (
            "default",
            "mao",
            "Zhang's here. he definitely needs scissors",
            "a pair of scissors to Zhang Wei",
        ),
        ("default", "mao", "Wang's back. she certainly needs a stapler", "a stapler to Wang Fang"),
        ("default", "mao", "Wang's back. she still needs a stapler", "a stapler to Wang Fang"),
        (
            "default",
            "mao",
            "Wang's back. she really really needs a stapler",
            "a stapler to Wang Fang",
        ),
        (
            "harbour",
            "will",
            "Rose is in. she definitely needs an umbrella",
            "an umbrella to Rose Adeyemi",
        ),
        ("harbour", "will", "Mark's back. he seriously needs a ruler", "a ruler to Mark Lindqvist"),
        # "still" after a name, before a need
        ("default", "mao", "Wang still needs a stapler", "a stapler to Wang Fang"),
        ("harbour", "will", "Rose still needs an umbrella", "an umbrella to Rose Adeyemi"),
        # must not change: no adverb
        ("default", "mao", "Wang's back. she needs a stapler", "a stapler to Wang Fang"),
    ],
)
def test_the_pronoun_is_the_one_named_before(name: str, who: str, text: str, question: str) -> None:
    frame = parser(name).parse(text, who)
    assert not frame.tasks and frame.question == f"Shall I bring {question}?", frame


def test_with_nobody_named_the_pronoun_is_asked() -> None:
    frame = parser("default").parse("she definitely needs a stapler", "mao")
    assert (
        not frame.tasks and frame.question == "Who do you mean by 'she'? Please tell me their name."
    )


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # must not change: the speaker's own need, with or without an adverb
        ("I really need a stapler", [("transfer", "stapler", None, "mao")]),
        ("I need a stapler", [("transfer", "stapler", None, "mao")]),
    ],
)
def test_the_speakers_own_need(text: str, tasks: list[tuple[str, str, None, str]]) -> None:
    frame = parser("default").parse(text, "mao")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == tasks, frame


@pytest.mark.parametrize(
    "text",
    [
        # must not change: a denial, and where a thing is
        "Wang's back. she hardly needs a stapler",
        "Wang still has my stapler",
    ],
)
def test_no_need_is_read(text: str) -> None:
    frame = parser("default").parse(text, "mao")
    assert not frame.tasks and frame.question is None and frame.decline, frame
