"""A colleague's later use of the thing, said in a part after a request that hands it to the
speaker ("could you fetch me some tape from the supply cupboard? Zhang wants to wrap a parcel
later."), is why the thing is asked for: the speaker receives it, never the colleague (fix201b
class 5: before, Zhang was read as the recipient, and the run tried to send Zhang the locker's
code). A colleague said to take the thing ("Zhang wants to borrow it"), a request that hands it
to the colleague ("take some tape to Zhang? she wants to wrap a parcel") and one that names no
one to hand it to keep their readings."""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import run_instruction

from helpers import office_builder as ob
from helpers.reading import frame_reader


def _raw_studio() -> dict[str, Any]:
    """A small studio: tape and gloves kept in a supply cupboard, owned by nobody."""
    people = (
        ob.person("ana", "Ana Ruiz"),
        ob.person("ben", "Ben Cole"),
        ob.person("zhang", "Zhang Wei"),
    )
    return ob.office_file(
        "studio",
        people,
        rooms=[ob.room("supply_room", "Supply room", 12.0, 20.0)],
        item_types=[ob.item("tape", "tape", synonyms=["sticky tape"]), ob.item("gloves", "gloves")],
        operations=[],
        facilities=[
            ob.facility(
                "supply_cupboard",
                "supply cupboard",
                at="supply_room",
                guards=["ben"],
                supplies=["tape", "gloves"],
            )
        ],
        home="supply_room",
    )


_studio = ob.parsed(_raw_studio)
_ana = frame_reader(_studio, "ana")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        # the class's own shape
        (
            "could you fetch me some tape from the supply cupboard? Zhang wants to wrap a "
            "parcel later.",
            "tape",
        ),
        ("could you fetch me some tape, Zhang wants to wrap a parcel", "tape"),
        ("can you grab me some gloves? Zhang wants to clean the bench later", "gloves"),
        ("I need some tape from the supply cupboard. Zhang wants to wrap a parcel.", "tape"),
    ],
)
def test_the_speaker_receives(text: str, item: str) -> None:
    frame = _ana(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "ana")], (
        frame
    )


@pytest.mark.parametrize(
    "text",
    [
        # must not change: the colleague is whom it is taken to, or takes it
        "could you take some tape to Zhang? she wants to wrap a parcel",
        "could you take some tape to Zhang? Zhang wants to wrap a parcel",
        "could you fetch me some tape? Zhang wants to borrow it",
        "could you fetch some tape? Zhang wants to wrap a parcel",
    ],
)
def test_the_colleague_still_receives(text: str) -> None:
    frame = _ana(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "tape", "zhang")
    ], frame


async def test_end_to_end_the_code_goes_to_the_speaker() -> None:
    text = (
        "could you fetch me some tape from the supply cupboard? Zhang wants to wrap a parcel later."
    )
    run = await run_instruction(_studio(), "ana", text)
    trace = run.stm.trace
    codes = [r.action for r in trace.actions() if r.action.type == "send_qr"]
    collected = [getattr(a, "contact", None) for a in codes if a.purpose == "collect"]
    assert collected == ["ana"], trace.summary
    assert all(getattr(a, "contact", None) != "zhang" for a in codes), trace.summary
    assert trace.outcome == "done", trace.summary
