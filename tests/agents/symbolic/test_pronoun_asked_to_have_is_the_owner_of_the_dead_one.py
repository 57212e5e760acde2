"""Issue #23, fixer fix97h class 2: "will's calculator has died, can he have mine?": the
owner of the broken or used-up thing, said again by he/she/they asked to have the thing
("can he have", "could she borrow"), is its receiver. The reader read it so; the consent
guard (``runtime.recipients``) only took object pronouns ("give him mine") and refused."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.parser import shared_parser
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office, harbour_office


@pytest.mark.parametrize(
    ("office", "who", "text", "item", "receiver"),
    [
        # the class's analogues
        ("harbour", "rose", "will's calculator has died, can he have mine?", "calculator", "will"),
        ("default", "lee", "Wang's pen has run out, can she have mine?", "pen", "wang"),
        # variants of our own
        ("harbour", "ray", "grace's charger has packed in, can she borrow mine?", "charger",
         "grace"),
        ("default", "lee", "Zhang's mug has cracked, could he have mine?", "cup", "zhang"),
    ],
)  # fmt: skip
def test_the_owner_of_the_dead_one_asked_to_have_mine_receives_it(
    office: str, who: str, text: str, item: str, receiver: str
) -> None:
    here = harbour_office() if office == "harbour" else default_office()
    frame = shared_parser(here).parse_with_answers(text, who, [])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, who, receiver)
    ]
    assert named_recipients(here, memory(who, text)) == {receiver}


def test_i_asked_to_have_theirs_names_no_one_else() -> None:
    # neighbour: "can I have Will's calculator? mine has died": the requester receives it
    text = "can I have Will's calculator? mine has died"
    frame = shared_parser(harbour_office()).parse_with_answers(text, "rose", [])
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("calculator", "will", "rose")]
    assert named_recipients(harbour_office(), memory("rose", text)) == set()


def test_he_asked_to_get_me_one_is_no_receiver() -> None:
    # neighbour: "could he get me one" makes him the one who gets it for the requester
    text = "Zhang's mug has cracked, could he get me a book?"
    assert named_recipients(default_office(), memory("lee", text)) == set()
