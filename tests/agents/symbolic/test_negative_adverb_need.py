"""An adverb that denies the verb after it ("hardly", "barely", "scarcely", "seldom",
"rarely", "never", "no longer") makes a need a denial: "Wang hardly needs a stapler" says there
is no need, answered in words, nothing offered or moved (``speech``: the statement's
negations; ``screen.negation``: the negators of the speaker's own errand). The list is
English's own (``negative_adverbs``), the same that ``subject_adverbs`` never reads away."""

from __future__ import annotations

import pytest
from _offices import parser


@pytest.mark.parametrize(
    ("name", "who", "text"),
    [
        # the class's analogue
        ("default", "mao", "Wang hardly needs a stapler"),
        # other adverbs, other people, other things, other offices
        ("default", "mao", "Wang barely needs a stapler"),
        ("default", "mao", "Zhang seldom needs the stapler"),
        ("default", "lee", "Lee rarely needs scissors"),
        ("default", "mao", "Wang hardly ever needs a stapler"),
        ("default", "mao", "she hardly needs a stapler"),
        ("harbour", "will", "Rose hardly needs an umbrella"),
        ("harbour", "will", "Mark scarcely needs a ruler"),
        ("harbour", "will", "Rose no longer needs an umbrella"),
        # the speaker's own
        ("default", "mao", "I hardly need a stapler"),
        ("default", "mao", "I barely need a stapler"),
        ("harbour", "will", "I scarcely need a calculator"),
        # must not change: "never" was a denial already
        ("default", "mao", "I never need a stapler"),
    ],
)
def test_a_denied_need_is_answered_in_words(name: str, who: str, text: str) -> None:
    frame = parser(name).parse(text, who)
    assert not frame.tasks and frame.question is None and frame.decline, frame


def test_the_rest_of_a_message_is_still_asked() -> None:
    """A denied need beside a request: the request alone is done."""
    frame = parser("default").parse("Wang hardly needs a stapler, bring him a pen", "mao")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "pen", "wang")]


@pytest.mark.parametrize(
    ("text", "question"),
    [
        # must not change: a need, with or without an adverb that says how much
        ("Wang needs a stapler", "Shall I bring a stapler to Wang Fang?"),
        ("Wang really needs a stapler", "Shall I bring a stapler to Wang Fang?"),
    ],
)
def test_a_need_is_still_offered(text: str, question: str) -> None:
    frame = parser("default").parse(text, "mao")
    assert frame.question == question, frame
