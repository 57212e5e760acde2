"""Small wording a person reads: the right indefinite article ("a pair of scissors", never "a
scissors"; "an umbrella"), and a forwarded file that does not name its sender twice."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.roles import Role, Roles
from assistantx.core.actions import ForwardFile
from assistantx.core.office import load_office
from assistantx.core.wording import a_thing, is_are
from assistantx.sim.session import SimSession


@pytest.mark.parametrize(
    ("name", "said"),
    [
        ("stapler", "a stapler"),
        ("umbrella", "an umbrella"),
        ("electronic file", "an electronic file"),
        ("scissors", "a pair of scissors"),
        ("reading glasses", "a pair of reading glasses"),
    ],
)
def test_the_indefinite_article(name: str, said: str) -> None:
    assert a_thing(name) == said


def test_a_group_is_asked_for_a_pair_of_scissors() -> None:
    office = load_office()
    roles = Roles(office, office.distance)
    role = Role(key="0.source", kind="lend", requester="lee", item_type="scissors")
    question = roles.group_question(role)
    assert "lend Lee Ming a pair of scissors" in question
    assert "a scissors" not in question


async def test_a_file_forwarded_from_its_owner_names_them_once() -> None:
    office = load_office()
    text = "get Mao's report and send it to Zhang"  # Zhang is named: a party to the file
    async with SimSession(office, requester="lee", text=text) as s:
        s.stm.files_received["mao"] = ["file:mao"]
        r = await s.do(ForwardFile(source="mao", target="zhang", file="file:mao"))
        assert r.ok, r.observation
        assert s.sim.messenger.sent[-1].text == "Forwarding Mao Jun's electronic file."
        s.stm.files_received["mao"].append("file:lee")
        await s.do(ForwardFile(source="mao", target="zhang", file="file:lee"))
        assert (
            s.sim.messenger.sent[-1].text == "Forwarding Lee Ming's electronic file from Mao Jun."
        )


@pytest.mark.parametrize(
    ("name", "mass", "said"),
    [
        ("handling gloves", False, "some handling gloves"),
        ("wipes", False, "some wipes"),
        ("sticky notes", False, "some sticky notes"),
        ("glue", False, "some glue"),
        ("stationery", False, "some stationery"),
        ("gaffer tape", True, "some gaffer tape"),
        ("gaffer tape", False, "a gaffer tape"),
        ("battery", False, "a battery"),
        ("seal", False, "a seal"),
        ("pair of scissors", False, "a pair of scissors"),
    ],
)
def test_a_plural_or_stuff_takes_some(name: str, mass: bool, said: str) -> None:
    """The morphology library says which nouns are plural ("gloves" is a form of glove) or
    only stuff ("glue" has no other plural); a noun used both ways ("tape") is stuff when the
    office says its item is (``mass``)."""
    assert a_thing(name, mass=mass) == said


@pytest.mark.parametrize(
    ("name", "verb"), [("gloves", "are"), ("scissors", "are"), ("tape", "is"), ("seal", "is")]
)
def test_the_verb_agrees_with_the_item(name: str, verb: str) -> None:
    assert is_are(name) == verb
