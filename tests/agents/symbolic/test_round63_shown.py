"""What the rounds shown this stop (278, 280, 282, 284, written blind) showed once read, each
by its mechanism, on offices of the tests' own:

- a seal named "chop" is asked for as "get my certs chopped", as "stamped" is;
- a request reported by "she"/"he" is the one colleague the message named before, and
  "to her desk" says it goes to her;
- the speaker about to do the office's own work ("I'm about to degrease") is their doing,
  even where the dictionary lacks the verb."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers import office_builder as ob
from helpers.reading import frame_reader

_STUDIO = ob.parsed(
    lambda: ob.office_file(
        "Print studio",
        [
            ob.person("lucia", "Lucia Ferrer", aliases=["Lucia"]),
            ob.person("dev", "Dev Malhotra", "respirator", aliases=["Dev"]),
            ob.person("bjorn", "Bjorn Halvorsen", "chop", aliases=["Bjorn"]),
        ],
        rooms=[ob.room("wash", "Washout bay", 30.0, 6.0)],
        item_types=[
            ob.item("document", "certificate", "personal", synonyms=["cert"], signable=True),
            ob.item("chop", "studio chop", synonyms=["chop", "blind stamp"], seals=True),
            ob.item("respirator", "respirator"),
            ob.item("screen", "screen"),
        ],
        operations=[ob.operation("reclaim", "reclaim", "strip", "degrease", input="screen")],
        facilities=[
            ob.facility(
                "washout", "washout booth", at="wash", guards=["dev"], operations=["reclaim"]
            )
        ],
        home="wash",
        everyone_owns=["document", "screen"],
    )
)
_lucia = frame_reader(_STUDIO, "lucia")
_bjorn = frame_reader(_STUDIO, "bjorn")


@pytest.mark.parametrize(
    "text",
    ["get my certs chopped before the show tmrw?", "can you get my cert chopped", "chop my cert"],
)
def test_a_chop_is_asked_in_every_form(text: str) -> None:
    frame = _lucia(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("seal", "document", "lucia")]


@pytest.mark.parametrize(
    "text",
    [
        "Please bring me Dev's respirator, I'm about to degrease with solvent.",
        "Please bring me Dev's respirator, I'm about to degrease",
    ],
)
def test_about_to_do_the_offices_work_is_the_speakers_doing(text: str) -> None:
    frame = _bjorn(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "respirator", "dev", "bjorn")
    ], frame


_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "item", "owner", "to"),
    [
        (
            "chen's lunch is in the fridge, she asked if someone could bring it to her desk",
            "lunch",
            "chen",
            "chen",
        ),
        ("chen asked if someone could bring her lunch to her desk", "lunch", "chen", "chen"),
        # must not change: the reported receiver said as "her"
        ("chen asked if someone could bring her a stapler", "stapler", None, "chen"),
    ],
)
def test_a_reported_request_goes_to_the_one_who_asked(
    text: str, item: str, owner: str | None, to: str
) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, to)
    ], frame


def test_she_of_two_colleagues_named_is_left_as_said() -> None:
    frame = _lee("chen and wang are busy, she asked if someone could bring it to her desk")
    assert frame.tasks == [], frame
