"""A request hedged as a hope about someone's leave ("i hope mark won't mind if i borrow his
ruler") asks for what follows "if I": Mark's ruler, with Mark asked as always. Without a
"but" it had been answered "Noted." A thing already done ("... if i borrowed his ruler") is
still told, and back-story after an errand does not make the errand done."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_harbour = frame_reader(harbour_office, "will")
_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "i hope mark wont mind if i borrow his ruler",
        "I hope Mark won't mind if I borrow his ruler",
        "hope you dont mind if i borrow mark's ruler",
        "i hope mark wont mind but i need to borrow his ruler",
    ],
)
def test_a_hedged_borrowing_asks_for_the_thing(text: str) -> None:
    frame = _harbour(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "ruler", "mark", "will")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "i hope mark wont mind if i borrowed his ruler",
        "i hope mark wont mind that i borrowed his ruler",
    ],
)
def test_a_thing_done_is_still_told(text: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [], frame


def test_back_story_after_an_errand_leaves_the_errand_to_do() -> None:
    frame = _default("bring my contract to Wang. She already sent hers to Zhang by mistake")
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("transfer", "lee", "wang")], (
        frame
    )
