"""What a role's person is asked to do takes the article its noun takes: "no one could lend
an umbrella", never "a umbrella" (the wording used a bare "a " before every item type)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.planning import role_text
from assistantx.agents.symbolic.roles import Role
from helpers.dataset_offices import default_office, harbour_office
from helpers.music_school import music_school


@pytest.mark.parametrize(
    ("office", "item_type", "expected"),
    [
        ("harbour", "umbrella", "lend an umbrella"),
        ("harbour", "ruler", "lend a ruler"),
        ("default", "scissors", "lend a pair of scissors"),
        ("default", "stapler", "lend a stapler"),
    ],
)
def test_the_lend_wording_takes_the_nouns_article(
    office: str, item_type: str, expected: str
) -> None:
    the_office = harbour_office() if office == "harbour" else default_office()
    role = Role(key="0.source", kind="lend", requester="x", item_type=item_type)
    assert role_text(role, the_office) == expected


@pytest.mark.parametrize(
    ("operation", "item_type", "expected"),
    [
        # "no one could patch the trumpet", never "polish a trumpet the trumpet"
        ("polish", "trumpet", "polish the trumpet"),
        ("restring", "guitar", "restring the guitar"),
        ("rehair", "bow", "rehair the bow"),
    ],
)
def test_a_services_own_object_gives_way_to_the_thing(
    operation: str, item_type: str, expected: str
) -> None:
    role = Role(
        key="0.heater", kind="heat", requester="x", item_type=item_type, operation=operation
    )
    assert role_text(role, music_school()) == expected
