"""A guard asked to run an operation whose verb is also its machine's name ("could you
autoclave Ana's glassware in the autoclave?"; here "could you microwave Hu Jing's lunch in the
microwave?") answers it as an operation request: the machine's name was taken out as a thing
first, and the guard answered "Sorry, I don't have Hu Jing's lunch" (blind rounds 43-48: four
tasks ended unachievable). The machine named as a place or asked about asks no work."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.answers import stance
from assistantx.core.office import load_office
from assistantx.sim.people import direct_reply
from assistantx.sim.understanding import mentioned_requests
from assistantx.sim.world import World


@pytest.mark.parametrize(
    "text",
    [
        "Hi Yang, could you microwave Hu Jing's lunch in the microwave? The robot will come to "
        "you for the hand-over.",
        "could you microwave my lunch",
        "please microwave Hu Jing's lunch",
    ],
)
def test_the_verb_named_as_the_machine_asks_the_work(text: str) -> None:
    assert mentioned_requests(load_office(), text) == ["heat"]


@pytest.mark.parametrize(
    "text", ["is the microwave free?", "could you bring Hu Jing's lunch to the microwave?"]
)
def test_the_machine_named_asks_no_work(text: str) -> None:
    assert mentioned_requests(load_office(), text) == []


def test_the_other_guard_says_yes_to_the_work() -> None:
    asked = (
        "Hi Yang, could you microwave Hu Jing's lunch in the microwave? The robot will come to "
        "you for the hand-over."
    )
    reply = direct_reply(World.from_office(load_office()), "yang", asked)
    assert reply is not None and stance(reply.text) == "yes", reply
