"""Two of blind round 28's classes the reader already read right on this office
(``helpers.rota_desk``), kept as tests, and the consent guard brought into line for one: a
title and surname declared as someone's alias ("Mrs Okafor", Rhiannon Pryce's married name),
also said without the title ("to Okafor"): the reader read the surname as her and the guard,
which took name parts from the full name only, refused the hand-over; and an owner's consent
put as a condition ("If Otto doesn't mind, I'd love to borrow his ruler") is a request for
his ruler, Otto asked as for any borrowing."""

from __future__ import annotations

import pytest

from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.reading import frame_reader
from helpers.rota_desk import rota_desk

_frame = frame_reader(rota_desk, "ada")


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        ("send my rota over to Mrs Okafor please", "send_file", "rota"),
        ("could you take my ruler to Mrs. Okafor", "transfer", "ruler"),
        ("take my ruler to mrs okafor", "transfer", "ruler"),
        ("take my ruler to Okafor", "transfer", "ruler"),
    ],
)
def test_a_title_and_surname_alias_names_her_for_reader_and_guard(
    text: str, kind: str, item: str
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [(kind, item, "rhiannon")]
    assert named_recipients(rota_desk(), memory("ada", text)) == {"rhiannon"}


def test_the_guard_still_refuses_who_was_not_named() -> None:
    assert named_recipients(rota_desk(), memory("ada", "take my ruler to Okafor")) == {"rhiannon"}
    assert "rhiannon" not in named_recipients(rota_desk(), memory("ada", "take my ruler to Otto"))


@pytest.mark.parametrize(
    "text",
    [
        "If Otto doesn't mind, I'd love to borrow his ruler for a few minutes",
        "if Otto doesn't mind I'd like to borrow his ruler",
        "if Otto isn't using it, could I borrow his ruler",
    ],
)
def test_the_owners_consent_as_a_condition_still_asks(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "ruler", "otto", "ada")
    ]


def test_the_condition_alone_moves_nothing() -> None:
    assert _frame("if Otto doesn't mind").tasks == []
