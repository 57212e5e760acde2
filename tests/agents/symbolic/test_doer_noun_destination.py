"""A send-out's destination said only by a generic role noun or a kind of place ("courier my
drive back to the distributor today", "courier my drive over to the pressing plant") does not
say where: the service asks its own question (``destination_asked``) before anything moves.

Until fix59d the words decided it by the dictionary alone: "distributor" (like "reseller",
"stockist") is a doer noun the dictionary lacks, so it was taken for a name said in lower case
and the drive was couriered "to the distributor"; "pressing" is a participle the dictionary
knows only as a verb, so "the pressing plant" was taken for more than a kind of place. A doer
noun made by English morphology from a verb the dictionary knows ("distribute" + "-or") is a
common noun (``reading.doer_nouns.is_made_doer_noun``), and a present participle describes a
kind of place as an adjective does ("the *sorting* office"). A proper name, an address, a
place of the office or a colleague is where, as before; a hedged request ("maybe ...?") still
acts."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.bare_place import bare_common_noun
from assistantx.agents.symbolic.reading.doer_nouns import is_made_doer_noun
from assistantx.agents.symbolic.reading.role_destination import names_only_a_role
from helpers import office_builder as ob
from helpers.reading import frame_reader


def _raw() -> ob.Row:
    """A small sound studio: a post desk that sends a drive, a form or a parcel out by courier
    (asking the name and address of the place), a meeting room, a colleague Zhang."""
    return ob.office_file(
        "sound studio",
        (
            ob.person("lee", "Lee Hart", "drive", "form", "parcel", "stapler"),
            ob.person("zhang", "Wei Zhang", "drive"),
            ob.person("ola", "Ola Berg"),
        ),
        rooms=[
            ob.room("front_desk", "Front desk", 20.0, 14.0),
            ob.room("meeting_room", "Meeting room", 30.0, 14.0, kind="room"),
        ],
        item_types=[
            ob.item("drive", "hard drive", "personal", synonyms=["drive"]),
            ob.item("form", "release form", "personal", synonyms=["form"]),
            ob.item("parcel", "parcel", "personal"),
            ob.item("stapler", "stapler"),
        ],
        operations=[
            ob.operation(
                "courier",
                "courier",
                "post",
                "ship",
                name="send by courier",
                input="drive",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
                done="couriered",
            ),
            ob.operation(
                "post_form",
                "post",
                name="post",
                input="form",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
                done="posted",
            ),
            ob.operation(
                "ship_parcel",
                "ship",
                name="ship",
                input="parcel",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
                done="shipped",
            ),
        ],
        facilities=[
            ob.facility(
                "post_desk",
                "post desk",
                at="front_desk",
                guards=["ola"],
                operations=["courier", "post_form", "ship_parcel"],
            ),
        ],
        home="front_desk",
    )


_STUDIO = frame_reader(ob.parsed(_raw), "lee")
_ASKED = "Please give me the name and address of the place."


@pytest.mark.parametrize(
    "text",
    [
        # the class's sentences (their office's item in this one)
        "can you courier my drive back to the distributor today",
        "courier my drive over to the pressing plant",
        # analogues
        "courier my drive to the distributor",
        "courier my drive to our distributors",
        "courier my drive back to the reseller",
        "courier my drive to the sorting office",
        "post my form to the client",
        "ship my parcel over to the supplier",
        "courier my drive back to the lab",
        # fix59e class 2: an "-ist" noun the dictionary lacks, made from a noun it knows
        "courier my drive to the stockist",
        "courier my drive over to our stockists",
        # ... and those it knows, as before
        "post my form to the florist",
        "ship my parcel back to the cellist",
    ],
)
def test_a_role_or_a_kind_of_place_is_asked(text: str) -> None:
    frame = _STUDIO(text)
    assert not frame.tasks, frame
    assert frame.question is not None, frame
    assert frame.question.endswith(_ASKED), frame


@pytest.mark.parametrize(
    ("text", "where"),
    [
        # must not change: a name, a name and a place, an address, a named office
        ("post my form to Harlow Ltd", "Harlow Ltd"),
        ("ship my drive to Warner Bros, Leavesden", "Warner Bros, Leavesden"),
        ("courier my drive to 12 High Street, Leeds", "12 High Street, Leeds"),
        ("post my form to the Leeds office", "the Leeds office"),
        ("courier my drive to the distributor in Leeds", "the distributor in Leeds"),
        ("courier my drive to the stockist in Leeds", "the stockist in Leeds"),
        ("courier my drive to celestia", "celestia"),  # a name said in lower case
        # class 2: a hedged request is still a request
        ("maybe courier my drive to Warner Bros tomorrow?", "Warner Bros"),
        ("might you courier my drive to Harlow Ltd?", "Harlow Ltd"),
    ],
)
def test_a_name_or_an_address_is_sent_to(text: str, where: str) -> None:
    frame = _STUDIO(text)
    assert frame.question is None, frame
    assert [t.destination for t in frame.tasks] == [where], frame


def test_a_place_in_the_office_is_no_send_out() -> None:
    """Carrying in the office, as before: the room is asked about as a room (who there should
    get it), never as a place outside to send to."""
    frame = _STUDIO("take my stapler to the meeting room")
    assert not frame.tasks, frame
    assert frame.question is not None, frame
    assert "who there should get it" in frame.question, frame
    assert _ASKED not in frame.question, frame


def test_a_colleague_is_asked_in_or_out() -> None:
    frame = _STUDIO("courier my drive to Zhang")
    assert not frame.tasks, frame
    assert frame.question is not None, frame
    assert "outside the office" in frame.question, frame


@pytest.mark.parametrize(
    ("word", "made"),
    [
        ("distributor", True),  # distribute + -or
        ("distributors", True),
        ("reseller", True),  # resell + -er
        ("zhang", False),
        ("celestia", False),
        ("harlow", False),
        ("supplier", False),  # the dictionary's own noun, not made here
        ("stockist", True),  # stock + -ist
        ("stockists", True),
        ("kist", False),  # no stem
        ("zhangist", False),  # a stem no dictionary knows
    ],
)
def test_is_made_doer_noun(word: str, made: bool) -> None:
    assert is_made_doer_noun(word) is made


@pytest.mark.parametrize(
    ("phrase", "bare"),
    [
        ("the pressing plant", True),
        ("the sorting office", True),
        ("the distributor", True),
        ("the celestia", False),
        ("the Leeds office", False),
    ],
)
def test_bare_common_noun(phrase: str, bare: bool) -> None:
    assert bare_common_noun(phrase) is bare


@pytest.mark.parametrize(
    ("phrase", "role"),
    [
        ("the distributor", True),
        ("our distributors", True),
        ("the reseller pls", True),
        ("the celestia", False),
        ("the stockist", True),
        ("the pressing plant", False),  # a place head: a kind of place, not a role
    ],
)
def test_names_only_a_role(phrase: str, role: bool) -> None:
    assert names_only_a_role(phrase) is role
