"""The consent guard counts a person's own place as naming them the recipient ("leave one at
her desk", "in Bram's tray"), by the rule the reader reads it with (``core.receiving_place``),
and nothing more: a place taken from, a wish, an owner or a pronoun that could mean two people
name nobody."""

from __future__ import annotations

import pytest

from assistantx.core.actions import SendQR
from assistantx.core.receiving_place import Ahead, names_receiving_place, pronoun_receiving_place
from assistantx.runtime import consent
from helpers.consent_memory import answered, memory
from helpers.kilnworks import kilnworks
from helpers.playschool import playschool
from helpers.reading import frame_reader


@pytest.mark.parametrize(
    ("before", "after", "names"),
    [
        ("at", "desk", True),
        ("in", "office", True),
        ("on", "tray", True),
        ("at", "station", True),  # a kitchen's or a ramp's workplace: round 22's "Teo's station"
        ("by", "locker", True),
        ("from", "desk", False),  # a source
        ("at", "calculator", False),  # an owner's item, not a place
        ("", "desk", False),
    ],
)
def test_a_place_names_its_person_only_after_a_preposition_of_putting(
    before: str, after: str, names: bool
) -> None:
    assert names_receiving_place(before, after) is names
    assert pronoun_receiving_place(before, "her", after) is names
    assert pronoun_receiving_place(before, "him", after) is False  # not a possessive


@pytest.mark.parametrize(
    "text",
    [
        "Sunniva wants a hole punch, drop one at her desk",
        "Sunniva needs a hole punch. Could you leave one on her desk?",
        "put a hole punch in Sunniva's tray",
        "drop a hole punch at Sunniva's station please",
        "leave a hole punch on her bench, Sunniva needs one",
    ],
)
def test_a_hand_over_at_her_place_is_let_through(text: str) -> None:
    stm = memory("kit", text)
    answered(stm, "sunniva")
    action = SendQR(contact="sunniva", item="hole_punch:kit", purpose="collect")
    assert consent.check(kilnworks(), stm, action) is None


@pytest.mark.parametrize(
    "text",
    [
        "bring me the hole punch from Sunniva's desk",
        "Sunniva wants a hole punch",
        "Sunniva and Wen want a hole punch, drop one at her desk",
    ],
)
def test_a_hand_over_to_someone_not_named_by_a_place_is_refused(text: str) -> None:
    stm = memory("kit", text)
    answered(stm, "sunniva")
    action = SendQR(contact="sunniva", item="hole_punch:kit", purpose="collect")
    refusal = consent.check(kilnworks(), stm, action)
    assert refusal is not None and refusal.rule == "not_a_party"


def test_the_reader_reads_a_workplace_word_as_the_persons_place_too() -> None:
    # the guard and the reader share the place words: what one hands over the other allows
    frame = frame_reader(playschool, "ada")
    for text, kind, item in (
        ("print my script and drop it at Rory's station please", "print", "script"),
        ("leave my stapler at Rory's bench", "transfer", "stapler"),
    ):
        assert [(t.kind, t.item, t.recipient) for t in frame(text).tasks] == [(kind, item, "rory")]


@pytest.mark.parametrize(
    ("ahead", "names"),
    [
        (Ahead(("the", "one")), False),  # "the one on Bram's desk": where it lies
        (Ahead(("those", "ones")), False),
        (Ahead(("book", "that"), contracted=True), False),  # "the book that's on ..."
        (Ahead(("book", "sitting")), False),
        (Ahead(("i", "left")), False),
        (Ahead(("leave", "one")), True),  # "leave one on Bram's desk": where it goes
        (Ahead(("leave", "that")), True),  # "leave that on ...", not "that's"
        (Ahead(("leave", "it")), True),
        (Ahead(), True),
    ],
)
def test_a_place_that_says_where_the_item_lies_names_no_recipient(
    ahead: Ahead, names: bool
) -> None:
    assert names_receiving_place("on", "desk", ahead) is names
    assert pronoun_receiving_place("on", "her", "desk", ahead) is names


@pytest.mark.parametrize(
    "text",
    [
        "bring me a hole punch, the one on Sunniva's desk",
        "can you grab the hole punch that's on Sunniva's desk",
        "fetch the hole punch sitting on Sunniva's bench",
        "Sunniva has a hole punch, bring me the one on her desk",
    ],
)
def test_a_hand_over_to_whoever_has_the_desk_it_lies_on_is_refused(text: str) -> None:
    stm = memory("kit", text)
    answered(stm, "sunniva")
    action = SendQR(contact="sunniva", item="hole_punch:kit", purpose="collect")
    refusal = consent.check(kilnworks(), stm, action)
    assert refusal is not None and refusal.rule == "not_a_party"


@pytest.mark.parametrize(
    "text",
    [
        "bring me a hole punch, the one on Sunniva's desk",
        "can you grab the hole punch that's on Sunniva's desk",
        "fetch me the hole punch sitting on Sunniva's bench",
    ],
)
def test_the_reader_fetches_from_the_desk_it_lies_on(text: str) -> None:
    frame = frame_reader(kilnworks, "kit")(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("hole_punch", "sunniva", "kit")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "leave a hole punch on Sunniva's desk",
        "get two hole punches and leave one on Sunniva's desk",
        "drop the hole punch at her desk, Sunniva needs it",
    ],
)
def test_a_place_it_is_left_at_still_names_the_recipient(text: str) -> None:
    frame = frame_reader(kilnworks, "kit")(text)
    assert [t.recipient for t in frame.tasks] == ["sunniva"], frame
