"""The consent guard and the reader agree on who is named (blind round 13, class 1): a
colleague whose given name is also an English word ("penny", "ivy") is named in any casing,
with or without diacritics, possessive ("ivy's desk") or by a declared alias, wherever the
reader reads the person; the guard decides with the reader's own function
(``core.name_reading.read_name``). Properties over generated offices."""

from __future__ import annotations

import functools
from typing import Any

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from assistantx.agents.symbolic import InstructionParser
from assistantx.core import language
from assistantx.core.actions import SendQR
from assistantx.core.office import Office, parse_office
from assistantx.runtime import consent
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import answered, memory

# given names that are also English words, names with diacritics, and plain ones
GIVEN = (
    "Penny",
    "Ivy",
    "Robin",
    "Grace",
    "Hope",
    "Rose",
    "Thảo",
    "Łukasz",
    "Zoë",
    "Jürgen",
    "Idris",
)
SURNAMES = ("Castellanos", "Marchetti", "Okonkwo", "Nguyễn", "Wróbel", "Brandt", "Falk", "Oduya")
NICKNAMES = ("Pen", "Ives", "Bobbin", "Gigi", "Tao", "Luke")

RECEIVING = (
    "take my {item} to {x} pls, she's got a class at 10",
    "drop my {item} on {x}'s desk",
    "could you bring my {item} to {x}?",
    "my {item} is for {x}, can you drop it off",
    "leave my {item} with {x} please",
)
ITEMS = ("puppet", "kick stool", "bone folder")


def _raw(people: list[tuple[str, str, str | None]]) -> dict[str, Any]:
    return {
        "name": "generated",
        "locations": [
            *(
                {
                    "id": f"desk_{n}",
                    "kind": "workstation",
                    "name": f"Desk {n}",
                    "x": 4.0 * n,
                    "y": 6,
                }
                for n in range(1, len(people) + 1)
            ),
            {"id": "workroom", "kind": "facility", "name": "Workroom", "x": 4.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "puppet", "name": "puppet"},
            {"id": "kick_stool", "name": "kick stool"},
            {"id": "bone_folder", "name": "bone folder"},
        ],
        "people": [
            {
                "id": f"p{n}",
                "name": f"{given} {surname}",
                "aliases": [alias] if alias else [],
                "location": f"desk_{n}",
                "handle": f"@p{n}",
                "owns": [{"type": "puppet"}, {"type": "kick_stool"}, {"type": "bone_folder"}],
            }
            for n, (given, surname, alias) in enumerate(people, 1)
        ],
        "facilities": [],
        "groups": [],
        "robot": {"home": "workroom"},
    }


@functools.cache
def _office(people: tuple[tuple[str, str, str | None], ...]) -> Office:
    return parse_office(_raw(list(people)), "generated")


@functools.cache
def _parser(people: tuple[tuple[str, str, str | None], ...]) -> InstructionParser:
    return InstructionParser(_office(people))


@st.composite
def offices(draw: st.DrawFn) -> tuple[tuple[str, str, str | None], ...]:
    n = draw(st.integers(min_value=3, max_value=5))
    given = draw(st.permutations(GIVEN))[:n]
    surnames = draw(st.permutations(SURNAMES))[:n]
    nicknames = draw(st.permutations(NICKNAMES))[:n]
    aliases = [nick if draw(st.booleans()) else None for nick in nicknames]
    return tuple(zip(given, surnames, aliases, strict=True))


def _spellings(person: tuple[str, str, str | None]) -> list[str]:
    given, surname, alias = person
    return [given, f"{given} {surname}", *([alias] if alias else [])]


def _cased(spelling: str, casing: str) -> str:
    written = {"lower": spelling.lower(), "upper": spelling.upper(), "as": spelling}[casing]
    return written


@st.composite
def requests(draw: st.DrawFn) -> tuple[tuple[tuple[str, str, str | None], ...], str, str, str]:
    """(office people, requester id, recipient id, text): the recipient named in a receiving
    place by one of their declared names, in any casing, diacritics kept or folded."""
    people = draw(offices())
    requester, x = draw(st.permutations(range(len(people))))[:2]
    spelling = draw(st.sampled_from(_spellings(people[x])))
    written = _cased(spelling, draw(st.sampled_from(["lower", "upper", "as"])))
    if draw(st.booleans()):
        written = language.fold(written) if written.islower() else written
    text = draw(st.sampled_from(RECEIVING)).format(item=draw(st.sampled_from(ITEMS)), x=written)
    return people, f"p{requester + 1}", f"p{x + 1}", text


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(requests())
def test_a_person_named_by_any_declared_name_in_any_casing_is_named(
    request: tuple[tuple[tuple[str, str, str | None], ...], str, str, str],
) -> None:
    people, requester, x, text = request
    office = _office(people)
    found = named_recipients(office, memory(requester, text))
    assert found == {x}, text  # the one mentioned counts; nobody not mentioned does
    stm = memory(requester, text)
    answered(stm, x)
    send = SendQR(contact=x, item=f"puppet:{requester}", purpose="collect")
    assert consent.check(office, stm, send) is None, text


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(requests())
def test_whom_the_reader_hands_over_to_the_guard_counts_as_named(
    request: tuple[tuple[tuple[str, str, str | None], ...], str, str, str],
) -> None:
    people, requester, x, text = request
    frame = _parser(people).parse(text, requester)
    recipients = {t.recipient for t in frame.tasks} - {requester}
    assert recipients <= {x}, text  # the reader hands over to the one named, or asks
    assert recipients <= named_recipients(_office(people), memory(requester, text)), text


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(offices(), st.data())
def test_a_name_read_as_a_word_or_not_mentioned_names_nobody(
    people: tuple[tuple[str, str, str | None], ...], data: st.DataObject
) -> None:
    office = _office(people)
    word_names = [p for p in people if language.is_english_word(language.fold(p[0]))]
    requester = "p1"
    if word_names:  # "the penny jar", "a rose for the table": the word, not the colleague
        given = data.draw(st.sampled_from(word_names))[0].lower()
        for text in (f"take my puppet to the {given} jar", f"bring me a {given}, please"):
            assert named_recipients(office, memory(requester, text)) == set(), text
    nobody = data.draw(st.sampled_from(["take my puppet to the front desk", "drop it off at 10"]))
    assert named_recipients(office, memory(requester, nobody)) == set()


def test_round13_analogues_in_lower_case_and_possessive() -> None:
    office = _office(
        (("Penny", "Castellanos", None), ("Ivy", "Marchetti", "Ives"), ("Zoë", "Brandt", None))
    )
    for text, who in (
        ("take my puppet to penny pls, she's got a class at 10", "p1"),
        ("drop my kick stool on ivy's desk", "p2"),
        ("leave my bone folder with ives", "p2"),
        ("bring my puppet to zoe brandt", "p3"),
    ):
        requester = "p3" if who != "p3" else "p1"
        stm = memory(requester, text)
        answered(stm, who)
        assert named_recipients(office, stm) == {who}, text
        send = SendQR(contact=who, item=f"puppet:{requester}", purpose="collect")
        assert consent.check(office, stm, send) is None, text


def test_a_declared_name_with_an_inner_apostrophe_names_its_person() -> None:
    # the guard split "Ms D'Amato" one way in the office file and another in the text, so
    # the signer the requester named was refused
    office = _office(
        (("Renée", "D'Amato", "Ms D'Amato"), ("Ivy", "Marchetti", None), ("Zoë", "Brandt", None))
    )
    for text in ("leave my bone folder with Ms D'Amato", "take my puppet to ms d'amato please"):
        stm = memory("p2", text)
        answered(stm, "p1")
        assert named_recipients(office, stm) == {"p1"}, text


def test_the_one_a_cleft_picks_out_is_named_and_a_plain_wish_is_not() -> None:
    # "it's fern who needs the hard copy": "who" is said of people, so a word-name there is
    # the colleague, and the cleft names the one the item is for (blind round 18)
    people = (("Penny", "Castellanos", None), ("Ivy", "Marchetti", None), ("Zoë", "Brandt", None))
    office = _office(people)
    for text in (
        "can you bring my puppet over? it's ivy who needs it not me",
        "bring my kick stool round, it is Ivy that wants it",
        "take my bone folder over please - it's ivy who needs to use it",
    ):
        assert named_recipients(office, memory("p1", text)) == {"p2"}, text
        frame = _parser(people).parse(text, "p1")
        assert {t.recipient for t in frame.tasks} <= {"p2"}, text  # the reader agrees
    for text in (
        "ivy wants my puppet on the shelf",  # a wish, not a recipient
        "it's ivy's puppet, take it to the workroom",  # an owner
        "is it ivy who broke the kick stool?",  # a question about Ivy
    ):
        assert named_recipients(office, memory("p1", text)) == set(), text
