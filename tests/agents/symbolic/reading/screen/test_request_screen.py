"""The request screen: the speech acts and sanity checks of each piece of a message, before the
request is read, and what they make of the whole message."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.screen import RequestScreen
from assistantx.core.office import Office


@pytest.fixture(scope="module")
def screen(office: Office) -> RequestScreen:
    return RequestScreen(office, Lexicon.from_office(office))


def test_a_request_passes_on_unchanged(screen: RequestScreen) -> None:
    out = screen.screen("bring me a stapler", "lee")
    assert (out.text, out.decline, out.question) == ("bring me a stapler", None, None)


@pytest.mark.parametrize(
    "text",
    [
        "forget about the stapler",  # a withdrawal
        "thanks for the pen!",  # thanks
        "please keep everyone away from Mao's seal today",  # a wish
    ],
)
def test_what_is_no_request_is_answered_in_words_and_nothing_is_left_to_read(
    screen: RequestScreen, text: str
) -> None:
    out = screen.screen(text, "lee")
    assert out.decline is not None and out.outcome == "done"


def test_a_question_that_may_be_a_request_is_answered_then_offered(
    screen: RequestScreen,
) -> None:
    out = screen.screen("does anyone have a stapler?", "lee")
    assert out.question is not None and out.question.endswith("Shall I bring you one?")
    assert out.offer == "bring me a stapler"


def test_a_destructive_request_is_declined(screen: RequestScreen) -> None:
    out = screen.screen("throw away Wang's stapler", "lee")
    assert out.decline is not None and out.outcome == "unachievable"


def test_a_fact_becomes_a_hint_and_the_rest_is_the_request(screen: RequestScreen) -> None:
    out = screen.screen("Wang is away. Bring me a stapler", "lee")
    assert [h.kind for h in out.hints] == ["availability"]
    assert "Wang" not in out.text and "stapler" in out.text


def test_the_verdicts_judge_each_piece_once_and_say_what_is_left(screen: RequestScreen) -> None:
    spoken = screen.verdicts("Wang is away. Bring me a pen, thanks. Never mind", "lee")
    assert [(f.verdict, f.piece.text) for f in spoken.findings] == [
        ("fact", "Wang is away"),
        ("thanks", "thanks"),
        ("withdrawn", "Never mind"),
    ]
    assert spoken.cut == len(spoken.msg.text)  # all before the withdrawal is dropped
    assert spoken.live == [] and spoken.kept == [] and spoken.left == ""
    assert [h.kind for h in spoken.hints] == ["availability"]  # the fact still holds
    kept = screen.verdicts("Wang is away. Bring me a pen", "lee")
    assert [p.text for p in kept.kept] == ["Bring me a pen"]
    assert [f.piece.text for f in kept.live] == ["Wang is away"]


def test_the_request_left_is_rewritten_for_the_later_stages(screen: RequestScreen) -> None:
    spoken = screen.verdicts("Wang's stapler is broken, bring me another one", "lee")
    assert spoken.left == "bring me another one"
    request = screen.request(spoken)
    assert "stapler" in request.text and "another one" not in request.text
    assert request.evidence  # the rewrite is said in words


def test_the_decision_keeps_the_rewritten_request_only_when_one_is_asked(
    screen: RequestScreen,
) -> None:
    asked = screen.verdicts("Wang is away. Bring me a stapler", "lee")
    out = screen.decide(asked, screen.request(asked))
    assert out.text.strip(" .") == "Bring me a stapler" and not out.answered
    told = screen.verdicts("thanks for the stapler", "lee")
    out = screen.decide(told, screen.request(told))
    assert out.answered and out.text == "thanks for the stapler"  # nothing left to read
