"""A thing's one-word name that is also a helping verb ("can" of a watering can) is the verb
where it opens an ask before its subject: "can you rotavate plot 12" asks nothing of the can
(round 216, read after its final measure: every "can you ..." had fetched a watering can,
once on a case that should have been declined). Said where a noun goes, it is the thing."""

from __future__ import annotations

import pytest

from helpers.office_builder import item, office_file, parsed, person, room
from helpers.reading import frame_reader


def _allotment_raw() -> dict[str, object]:
    return office_file(
        "Allotments",
        [person("bjorn", "Björn Dahl", "watering_can"), person("sage", "Sage Morrow")],
        rooms=[room("hut", "Hut", 5.0, 5.0)],
        item_types=[item("watering_can", "watering can", synonyms=["can"])],
        operations=[],
        facilities=[],
        home="hut",
    )


_read = frame_reader(parsed(_allotment_raw), "sage")


@pytest.mark.parametrize(
    "text",
    ["can you rotavate plot 12 for me this week", "can you sort that thing out for me"],
)
def test_the_helping_verb_fetches_nothing(text: str) -> None:
    assert _read(text).tasks == []


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("can you bring me the can", None),
        ("Can I borrow Björn's can?", "bjorn"),
        ("bring me a can", None),
        ("the can is leaking, can someone bring me another", None),
    ],
)
def test_the_thing_said_as_a_noun_is_the_thing(text: str, owner: str | None) -> None:
    frame = _read(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("watering_can", owner, "sage")
    ], frame
