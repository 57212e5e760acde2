"""A colleague asked with a modal to do the work by hand ("could Hal sign my form?", "would
Hal be able to stamp it?") is named as its doer, so the consent guard lets the signing code
go to them, as it does for "get Hal to sign". Blind round 93's writer found the gap: with a
second request after it ("... And a coffee for me please.") the reader asks "Shall I ...?"
first, so its frame named no doer, and the generator's optimal policy was refused the code
to the signer and ended "failed" on a fair base instruction.

A modal before a name makes them a doer only when the work done by hand follows: "could Hal
bring it?" or "can Hal have it?" are other roles, read by their own rules."""

from __future__ import annotations

from pathlib import Path

import pytest

from assistantx.core.office import load_office
from assistantx.core.task_spec import BaseInstruction, Part, check_base
from assistantx.runtime.recipients import named_doers, named_recipients
from helpers.clinic import clinic
from helpers.consent_memory import memory
from helpers.dataset_tasks import verify_every_variant

DEFAULT_OFFICE = Path(__file__).resolve().parents[2] / "dataset" / "office.yaml"


@pytest.mark.parametrize(
    "text",
    [
        "Could Hal sign my document? And a thermometer for me please.",
        "can Hal sign my document pls",
        "would Hal be able to sign my document? thanks",
        "Will Hal initial my document before lunch?",
        "could Hal countersign it? it's my document",
    ],
)
def test_a_colleague_asked_with_a_modal_to_sign_is_its_doer(text: str) -> None:
    office = clinic()
    assert "hal" in named_doers(office, memory("dawn", text))


@pytest.mark.parametrize(
    "text",
    [
        # other work: Hal would carry or be given it, which other rules read
        "could Hal bring my document over? Rich needs it",
        "can Hal tell me where my document is",
        # Hal is only said to be able to, and asked nothing: no doer
        "Hal can't sign anything this week, he's away",
    ],
)
def test_a_modal_before_other_work_names_no_doer(text: str) -> None:
    office = clinic()
    assert "hal" not in named_doers(office, memory("dawn", text))
    assert "hal" not in named_recipients(office, memory("dawn", text))


SIGN_AND_COFFEE = BaseInstruction(
    id="m1",
    requester="lee",
    text="Could Zhang sign my document? And a coffee for me please.",
    parts=(Part(kind="sign", signer="zhang"), Part(kind="coffee")),
)
ABLE_TO_SIGN_AND_WATER = BaseInstruction(
    id="m2",
    requester="mao",
    text="would Wang be able to sign my contract? and a water for me",
    parts=(Part(kind="sign", signer="wang"), Part(kind="water")),
)


@pytest.mark.parametrize("base", [SIGN_AND_COFFEE, ABLE_TO_SIGN_AND_WATER], ids=lambda b: b.id)
async def test_the_optimal_policy_solves_a_modal_signature_with_a_second_request(
    base: BaseInstruction,
) -> None:
    office = load_office(DEFAULT_OFFICE)
    check_base(base, office)
    await verify_every_variant(office, base)
