"""A first name two colleagues share, once with a diacritic (Zoe Park, called Zoe, beside Zoë
Lund, declared "Zoë"): said without the mark ("zoe") it is either, folded the two are one
word and people drop accents, so which is asked, as for two plain namesakes (reading/
exact_spelling.py ``plainly_called``; fix61f class 2: "take my torch to sean" went to Seán,
whose bare alias won the folded word). Typed with the mark ("Zoë") it means only the one who
spells it so; a name only one colleague has is read as before."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.reading import frame_reader


def _office() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "Workshop",
            [
                ob.person("pat", "Pat Kim", "stapler", aliases=["Pat"]),
                ob.person("zoe_p", "Zoe Park", "stapler", aliases=["Zoe P", "Park"]),
                ob.person("zoe_l", "Zoë Lund", "stapler", aliases=["Zoë", "Zoe L", "Lund"]),
                ob.person("rene_d", "Rene Dubois", aliases=["Rene D"]),
                ob.person("rene_m", "René Martin", aliases=["René", "Martin"]),
            ],
            rooms=[ob.room("stores", "Stores", 20.0, 6.0)],
            item_types=[ob.item("stapler", "stapler")],
            operations=[],
            facilities=[],
            home="stores",
        )
    )()


_frame = frame_reader(_office, "pat")


@pytest.mark.parametrize(
    ("text", "both"),
    [
        ("take my stapler to zoe", ("Zoe Park", "Zoë Lund")),
        ("can you take my stapler to Zoe, she needs one", ("Zoe Park", "Zoë Lund")),
        ("take my stapler to rene", ("Rene Dubois", "René Martin")),
    ],
)
def test_a_name_said_without_its_mark_asks_which(text: str, both: tuple[str, str]) -> None:
    frame = _frame(text)
    assert not frame.tasks and frame.question is not None, frame
    assert all(name in frame.question for name in both), frame


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("take my stapler to Zoë", "zoe_l"),
        ("take my stapler to René", "rene_m"),
        ("take my stapler to Zoe P", "zoe_p"),
        ("take my stapler to Lund", "zoe_l"),
    ],
)
def test_a_name_one_colleague_spells_or_has_is_theirs(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [(t.item, t.recipient) for t in frame.tasks] == [("stapler", recipient)], frame
