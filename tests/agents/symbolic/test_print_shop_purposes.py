"""Round 244 (a students' union print shop, read after the final measure), two classes:

- A product named as what another thing is for or used on ("a foam board *to mount the RAG
  week poster*", "Drew's artwork *for the climbing soc banner*") is no variant of the product
  to make: the words before it say which poster, and the thing asked is the other one. It
  asked "Shall I get you an ordinary poster instead?" (``screen.variant``).
- A thing's name right after another's, heading the noun phrase that a verb follows ("my
  poster *proof* needs the stamp"), is the thing, never a state said of the first ("proof"
  is an adjective too; ``said_of``)."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.reading import frame_reader


def _shop() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "Print shop",
            [
                ob.person("drew", "Drew Baker", "artwork", "proof", aliases=["Drew"]),
                ob.person("zoe", "Zoe Hart", "artwork", "proof", aliases=["Zoe"]),
                ob.person("mei", "Mei Chua", "stamp", aliases=["Mei"]),
            ],
            rooms=[ob.room("shop", "Shop floor", 20.0, 6.0)],
            item_types=[
                ob.item("foam_board", "foam board"),
                ob.item("artwork", "artwork", "electronic"),
                ob.item("proof", "proof", "personal", signable=True),
                ob.item("stamp", "approval stamp", seals=True),
                ob.item("poster", "large format poster", "product", synonyms=["poster", "banner"]),
            ],
            operations=[ob.operation("plot", "plot", input="artwork", product="poster")],
            facilities=[
                ob.facility(
                    "plotter",
                    "plotter",
                    at="shop",
                    guards=["mei"],
                    operations=["plot"],
                    supplies=["foam_board"],
                )
            ],
            home="shop",
        )
    )()


_frame = frame_reader(_shop, "drew")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I need a foam board to mount the RAG week poster.", "foam_board"),
        ("can you get me a foam board for the freshers banner", "foam_board"),
    ],
)
def test_what_a_thing_is_for_is_no_variant(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, "drew")], frame


def test_a_variant_asked_for_itself_is_still_asked() -> None:
    frame = _frame("can you plot me an iced poster")
    assert frame.question is not None and "ordinary" in frame.question, frame


def test_the_compound_head_before_a_verb_is_the_thing() -> None:
    frame = _frame("My poster proof needs the approval stamp before it goes up.")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("seal", "proof", "drew")], frame
