"""Ids and aliases are not confused: group ``station`` and a person called "the station
manager" both normalize to "station" (titles and articles drop out), yet a message to
``station`` goes to the group and one to "the station manager" to the person. Only a spelling
written exactly like both stays ambiguous, and loading such an office says so in one line."""

from __future__ import annotations

import logging
from typing import Any

import pytest

from assistantx.core.actions import Inquire, Wait
from assistantx.core.errors import AmbiguousNameError
from assistantx.core.office import Office, contact_clashes, parse_office
from assistantx.memory.resolve import Resolver
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice
from helpers.clinic import raw_clinic
from helpers.office import run_one, sim_assistant
from helpers.scripted_reasoner import ScriptedReasoner


def _clinic_with_station(*aliases: str) -> dict[str, Any]:
    raw = raw_clinic()
    raw["groups"].append({"id": "station", "name": "Nurses station", "members": ["dawn", "hal"]})
    rich = next(p for p in raw["people"] if p["id"] == "rich")
    rich["aliases"] = list(aliases)
    return raw


@pytest.fixture(scope="module")
def station() -> Office:
    return parse_office(_clinic_with_station("the station manager"), "clinic")


@pytest.mark.parametrize(
    ("written", "meant"),
    [
        ("station", ("group", "station")),
        ("  station ", ("group", "station")),
        ("Nurses station", ("group", "station")),
        ("the station manager", ("person", "rich")),
        ("The Station Manager", ("person", "rich")),
        ("rich", ("person", "rich")),
        ("Rich Adeyemi", ("person", "rich")),
    ],
)
def test_a_contact_is_what_its_id_or_declared_spelling_says(
    station: Office, written: str, meant: tuple[str, str]
) -> None:
    assert Resolver(station).contact(written) == meant


def test_a_spelling_declared_for_neither_that_matches_both_stays_ambiguous(
    station: Office,
) -> None:
    with pytest.raises(AmbiguousNameError):
        Resolver(station).contact("station manager")


async def test_a_group_inquire_by_id_reaches_the_group(station: Office) -> None:
    sim = SimOffice(station)
    ask = Inquire(contact="station", question="Does anyone have a thermometer Ines could borrow?")
    reasoner = ScriptedReasoner([[ask, Wait(timeout_s=30)]])
    assistant = sim_assistant(
        sim, lambda: reasoner, reasoner_name="scripted", limits=LoopLimits(max_steps=2)
    )
    stm = await run_one(sim, assistant, "ines", "Could you get me a thermometer?")
    first = stm.trace.steps[0].results[0]
    assert first.ok and not first.refused, first.observation
    assert any(m.chat.id == "station" for m in sim.messenger.sent)


def test_a_true_clash_is_one_warning_line_naming_both(caplog: pytest.LogCaptureFixture) -> None:
    with caplog.at_level(logging.WARNING, logger="assistantx.core.office"):
        office = parse_office(_clinic_with_station("Station"), "clinic.yaml")
    clashes = [r.getMessage() for r in caplog.records if "like group" in r.getMessage()]
    assert len(clashes) == 1 and "\n" not in clashes[0]
    assert clashes[0].startswith(
        "clinic.yaml: person 'rich' is also called 'Station', like group 'station':"
    )
    # the id still means its group; the clashing spelling written otherwise is the person's
    assert Resolver(office).contact("station") == ("group", "station")
    with pytest.raises(AmbiguousNameError):
        Resolver(office).contact("Station")


def test_an_office_without_clashes_loads_without_a_warning(station: Office) -> None:
    assert contact_clashes(station) == []
