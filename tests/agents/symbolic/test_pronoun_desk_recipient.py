"""A pronoun's desk names the one who receives ("Gao is out of paper, could you drop a few
sheets of mine at her desk"): "her desk" is the desk of the colleague named before, also in a
statement (``screen.rewrites.name_pronouns``: "her" before a place word is possessive, as
before an item), so that colleague receives there. "some of mine", "a few sheets of mine",
"one of mine" (``partitive_quantities`` before "of mine", in ``dangling_possessives``) is a
part of the requester's own item of the kind named before, so the requester stays its owner;
before, "some of mine" was lost and anyone's paper was borrowed."""

from __future__ import annotations

import pytest
from _offices import parser


@pytest.mark.parametrize(
    ("name", "who", "text", "item", "owner", "to"),
    [
        # the class's analogues
        (
            "default",
            "wu",
            "Gao is out of paper, could you drop a few sheets of mine at her desk",
            "paper",
            "wu",
            "gao",
        ),
        (
            "default",
            "wu",
            "Gao needs paper, could you drop some of mine at her desk",
            "paper",
            "wu",
            "gao",
        ),
        # other words, other people, other offices
        (
            "default",
            "wu",
            "Zhang has no paper, please leave a couple of mine on his desk",
            "paper",
            "wu",
            "zhang",
        ),
        (
            "default",
            "wu",
            "Gao is out of paper, could you drop some of my paper at her desk",
            "paper",
            "wu",
            "gao",
        ),
        (
            "default",
            "mao",
            "Gao needs a stapler, could you drop one of mine at her desk",
            "stapler",
            "mao",
            "gao",
        ),
        (
            "harbour",
            "will",
            "Rose has no highlighter, could you drop one of mine at her desk",
            "highlighter",
            "will",
            "rose",
        ),
        (
            "harbour",
            "will",
            "Rose is out of tape, put some of mine on her desk",
            "tape",
            "will",
            "rose",
        ),
        (
            "harbour",
            "will",
            "Mark has no ruler, could you leave one of mine on his desk",
            "ruler",
            "will",
            "mark",
        ),
        # must not change: a colleague's desk named by name
        ("default", "wu", "drop my stapler at Gao's desk", "stapler", "wu", "gao"),
        ("default", "wu", "leave my stapler on Gao's desk", "stapler", "wu", "gao"),
        # must not change: "her" before an item is whose it is
        (
            "harbour",
            "will",
            "Rose is out, could you bring her ruler to my desk",
            "ruler",
            "rose",
            "will",
        ),
    ],
)
def test_the_pronouns_desk_receives(
    name: str, who: str, text: str, item: str, owner: str, to: str
) -> None:
    frame = parser(name).parse(text, who)
    moves = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert frame.question is None and moves == [("transfer", item, owner, to)], frame


def test_a_pronouns_desk_with_nobody_named_is_asked() -> None:
    frame = parser("default").parse("take my stapler to her desk", "wu")
    assert (
        not frame.tasks and frame.question == "Who do you mean by 'her'? Please tell me their name."
    )
