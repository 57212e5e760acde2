"""A colleague's possessive typed without its apostrophe is read as with it, at every stage
(reading/unmarked_possessive.py). Found by dropping the apostrophes of 1,422 probe messages:
79 were read differently without them (a possessive name that is also a word, "Grants off
today", asked what was wanted; "Lucas Bs stopwatch" asked which Lucas); now 19."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.unmarked_possessive import marked_possessives
from assistantx.core.office import load_office
from helpers import office_builder as ob
from helpers.reading import frame_reader

_lee = frame_reader(load_office, "lee")

_STUDIO = ob.parsed(
    lambda: ob.office_file(
        "Studio",
        [
            ob.person("priya", "Priya Raman", aliases=["Priya"]),
            ob.person("grant", "Grant Okoye", "stopwatch", aliases=["Grant"]),
            ob.person("lucas_b", "Lucas Brandt", "stopwatch", aliases=["Lucas B"]),
            ob.person("lucas_f", "Lucas Ferreira", "stopwatch", aliases=["Lucas F"]),
        ],
        rooms=[ob.room("studio", "Studio", 30.0, 6.0)],
        item_types=[ob.item("stopwatch", "stopwatch")],
        operations=[],
        facilities=[],
        home="studio",
    )
)
_priya = frame_reader(_STUDIO, "priya")


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("Could you bring me Lucas Bs stopwatch please", "lucas_b"),
        ("can i borrow lucas fs stopwatch for a bit", "lucas_f"),
        ("Grants stopwatch please, mine is dead", "grant"),
    ],
)
def test_a_possessive_without_its_apostrophe_is_the_colleagues(text: str, owner: str) -> None:
    frame = _priya(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stopwatch", owner, "priya")
    ], frame


def test_a_statement_about_a_colleague_asks_nothing() -> None:
    frame = _lee("Wangs off today, shes at the dentist")
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("Grants off today", "Grant's off today"),
        ("get me amaras file", "get me amara's file"),
        ("Lucas Bs stopwatch", "Lucas B's stopwatch"),
        # left as said: an ordinary word in lower case, a name that ends in s, a letter alone
        ("the grants came in", "the grants came in"),
        ("Lucas is in", "Lucas is in"),
        ("As soon as you can", "As soon as you can"),
        ("Grant's off today", "Grant's off today"),
    ],
)
def test_the_rewrite(text: str, read: str) -> None:
    names = {"grant", "amara", "lucas", "b", "a"}
    assert marked_possessives(text, names, lambda p: p.lower() == "lucas b") == read
