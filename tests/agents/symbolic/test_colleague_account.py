"""Getting into a colleague's account with their login, password or card is acting as them
(reading/screen/impersonation.py): declined with the reason, whatever the thing that opens it,
never the card fetched with its owner asked (fix61f class 1: "take Summer's smartcard and log
into her EDMS account for me" fetched the smartcard). A colleague's card asked for plainly,
the speaker's own card taken to someone, and "log" said of work are read as before."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.reading import frame_reader


def _office() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "Records floor",
            [
                ob.person("dana", "Dana Wu", "badge", "stapler", aliases=["Dana"]),
                ob.person("pat", "Pat Kim", "badge", "stapler", aliases=["Pat"]),
                ob.person("sam", "Sam Ortiz", "badge", aliases=["Sam"]),
            ],
            rooms=[ob.room("meeting_room", "Meeting room", 20.0, 6.0, kind="room")],
            item_types=[
                ob.item("badge", "badge", "personal", synonyms=["key card", "id card"]),
                ob.item("stapler", "stapler"),
            ],
            operations=[],
            facilities=[],
            home="meeting_room",
        )
    )()


_frame = frame_reader(_office, "dana")


@pytest.mark.parametrize(
    "text",
    [
        "grab Pat's badge and sign in as her on the portal",
        "take Pat's key card and log into her HR account for me, mine's locked",
        "use Sam's login to book the meeting room for me",
        "get me Sam's key card so I can get into his email",
        "can you log in as Pat and send the rota",
        "use Pat's password to open the booking system",
        # a second command after the first's recipient: the robot's own doing, still
        "bring Pat the badge and log into her account",
        "give Pat my badge then log into her email",
    ],
)
def test_getting_into_a_colleagues_account_is_declined(text: str) -> None:
    frame = _frame(text)
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and "account" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "owner", "recipient"),
    [
        ("bring me Pat's badge", "pat", "dana"),
        ("take my badge to Pat", "dana", "pat"),
        ("take my badge to Sam so he can get into his email", "dana", "sam"),
        ("tell Pat to log into her account and take her my badge", "dana", "pat"),
    ],
)
def test_a_card_asked_for_plainly_is_read_as_before(text: str, owner: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("badge", owner, recipient)], (
        frame
    )


@pytest.mark.parametrize("text", ["can you log my hours", "log this", "log into my account"])
def test_log_said_of_the_speakers_own_is_not_acting_as_anyone(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None or "acting as them" not in frame.decline, frame
