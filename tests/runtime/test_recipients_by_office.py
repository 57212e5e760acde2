"""The consent guard's reading of who was named is kept per office and text: the same words
read against another office (other people, other spellings) are read against that office,
and a later reply in the requester's chat still counts."""

from __future__ import annotations

from assistantx.core.dialogue import DialogueTurn
from assistantx.core.office import parse_office
from assistantx.core.ports.messenger import ChatRef
from assistantx.runtime.recipients import named_doers, named_recipients
from helpers.clinic import clinic, raw_clinic
from helpers.consent_memory import memory


def _renamed(old: str, new: str) -> dict[str, object]:
    raw = raw_clinic()
    for person in raw["people"]:
        if person["name"] == old:
            person["name"] = new
    return raw


def test_the_same_words_are_read_against_each_office_own_people() -> None:
    office = clinic()
    renamed = parse_office(_renamed("Hal Brooks", "Hal Price"))
    text = "take my clipboard to Brooks"
    assert named_recipients(office, memory("rich", text)) == {"hal"}
    # "Brooks" is nobody's name in the second office: read again there, not remembered
    assert named_recipients(renamed, memory("rich", text)) == set()
    assert named_recipients(office, memory("rich", text)) == {"hal"}  # and back


def test_another_office_built_alike_reads_alike() -> None:
    text = "could you bring Dawn my thermometer"
    first = named_recipients(clinic(), memory("hal", text))
    second = named_recipients(parse_office(raw_clinic()), memory("hal", text))
    assert first == second == {"dawn"}


def test_who_wrote_the_words_is_part_of_their_reading() -> None:
    office = clinic()
    text = "please hand Rich my clipboard"
    assert named_recipients(office, memory("hal", text)) == {"rich"}
    assert named_recipients(office, memory("rich", text)) == set()  # never the requester


def test_a_reply_in_the_requesters_chat_adds_to_a_remembered_reading() -> None:
    office = clinic()
    stm = memory("hal", "take my thermometer over please")
    assert named_recipients(office, stm) == set()
    own = ChatRef(kind="dm", id="hal")
    stm.dialogue += [
        DialogueTurn(time=1, direction="in", chat=own, person="hal", text="Dawn Ellis.")
    ]
    assert named_recipients(office, stm) == {"dawn"}
    assert "dawn" in named_doers(office, stm)
