"""A pronoun of whose after an outsider the sentence opens on ("customer at counter 1 wants a
copy of their contract, can you photocopy the one on my desk") is that outsider's: a paper in
the speaker's hand, never a colleague to ask about (round 272: "Who do you mean by 'their'?")."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.outsider_pronoun import outsider_pronouns
from assistantx.core.office import load_office
from helpers.reading import frame_reader

_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        (
            "customer at counter 1 wants a copy of their contract, can you photocopy the one on "
            "my desk",
            "copy",
        ),
        ("a visitor needs his form stamped, can you do it", "seal"),
    ],
)
def test_an_outsiders_pronoun_is_the_paper_in_hand(text: str, kind: str) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        (kind, "document", "lee", "lee")
    ], frame


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("the customer wants their form back", "the customer wants the customer's form back"),
        (
            "Visitor needs her form. Print her pass",
            "Visitor needs the visitor's form. Print her pass",
        ),
        ("the customer wants his stapler back", "the customer wants his stapler back"),  # no paper
        ("courier my form to her office", "courier my form to her office"),  # a verb first
        # left as said: a colleague named before it, a vague subject, no outsider first
        ("the courier gave Wang her form", "the courier gave Wang her form"),
        ("someone wants their form back", "someone wants their form back"),
        ("Wang needs her stapler", "Wang needs her stapler"),
    ],
)
def test_the_rewrite(text: str, read: str) -> None:
    assert outsider_pronouns(text, lambda w: w.lower() == "wang", {"form", "contract"}) == read
