"""Thanks, a withdrawal or a note for information ("thanks for the stapler", "never mind the
scanner paper", "fyi the ruler is back on my desk") moves nothing, whatever the office calls
its things: a Hypothesis property over the default and harbour offices' item names (and
synonyms), with and without "my"/"the", and the thing-at-hand and two-service readings of
this round kept out of them. A withdrawal of a service said by its gerund ("never mind
copying this") withdraws it (speech.withdrawal; before, the gerund was read as a command and
the copy planned). Neighbours that are requests still plan their task."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office
from helpers.dataset_offices import default_office, harbour_office

_OFFICES = {"default": (default_office(), "mao"), "harbour": (harbour_office(), "may")}

_FORMS = [
    "thanks for the {item}",
    "thank you for getting me the {item}!",
    "thanks, the {item} arrived",
    "thanks for sorting my {item} out",
    "never mind the {item}",
    "never mind, I found my {item}",
    "nvm about the {item}, sorted",
    "fyi the {item} is back on my desk",
    "fyi: my {item} went through the scanner already",
    "fyi, I had the {item} copied and signed yesterday",
    "just fyi, this {item} is done",
    "never mind copying the {item}",
    "never mind bringing me the {item}",
    "forget about getting my {item} signed",
    "never mind putting this {item} through the copier",
]


def _names(office: Office) -> list[str]:
    return sorted({n for t in office.item_types if not t.electronic for n in (t.name, *t.synonyms)})


@st.composite
def _sentence(draw: st.DrawFn) -> tuple[str, str]:
    office = draw(st.sampled_from(sorted(_OFFICES)))
    item = draw(st.sampled_from(_names(_OFFICES[office][0])))
    return office, draw(st.sampled_from(_FORMS)).format(item=item)


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_sentence())
def test_thanks_never_mind_and_fyi_plan_no_physical_action(said: tuple[str, str]) -> None:
    name, text = said
    office, who = _OFFICES[name]
    frame = InstructionParser(office).parse(text, who)
    assert frame.tasks == [], (name, text, frame)


@pytest.mark.parametrize(
    ("name", "text"),
    [
        ("default", "thanks, now copy this please"),
        ("harbour", "fyi, can this go thru the scanner"),
        ("default", "never mind, copy this instead"),
    ],
)
def test_a_request_beside_the_thanks_or_withdrawal_is_still_planned(name: str, text: str) -> None:
    office, who = _OFFICES[name]
    frame = InstructionParser(office).parse(text, who)
    assert [t.kind for t in frame.tasks] == ["copy"], frame


@pytest.mark.parametrize(
    "text",
    ["never mind copying this", "forget about printing it", "never mind copying my document"],
)
def test_a_service_withdrawn_by_its_gerund_moves_nothing(text: str) -> None:
    frame = InstructionParser(default_office()).parse(text, "mao")
    assert frame.tasks == [] and frame.decline is not None, frame
