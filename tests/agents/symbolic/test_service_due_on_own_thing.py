"""The requester's own thing said to be due one of the office's services (fix103d, class 2):
"my 4-gas is due a bump test, can you take it down the gas bay" asks for the bump test on the
requester's own gas monitor, brought back after; before, "is due a bump test" was read as a
statement and "take it down the gas bay" fetched and handed over a gas monitor with no service
named. "<thing> is (over)due (for) a <service>" reads as "<thing> needs a <service>"
(``reading.due_service``), the services being the office's own; an operation whose display
name is its own declared verb phrase ("bump test") is read as that phrase after a need, not as
its first word alone (``reading.operation_nouns``)."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of
from symbolic_run import run_instruction

from helpers.reading import frame_reader
from helpers.seed_lab import seed_lab

_lab = frame_reader(seed_lab, "ines")


@pytest.mark.parametrize(
    ("text", "item", "operation"),
    [
        # the class's analogue
        (
            "my 4-gas is due a bump test, can you take it down the gas bay",
            "gas_monitor",
            "bump_test",
        ),
        ("my gas monitor is due a bump test", "gas_monitor", "bump_test"),
        (
            "my 4-gas is overdue for its bump test, could you run it over to the gas bay",
            "gas_monitor",
            "bump_test",
        ),
        ("my gas monitor's due a quick bump test", "gas_monitor", "bump_test"),
        ("my gas monitor needs a bump test", "gas_monitor", "bump_test"),
        ("my 4-gas needs bump testing, take it down the gas bay", "gas_monitor", "bump_test"),
        (
            "my seed samples are due a dry, can you take them down to the drying room",
            "seed_sample",
            "dry",
        ),
    ],
)
def test_the_service_runs_on_the_requesters_own_thing(text: str, item: str, operation: str) -> None:
    frame = _lab(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        ("heat", item, "ines", "ines", operation)
    ], frame


def test_another_owner_says_it_of_their_own() -> None:
    frame = _lab("my 4-gas is due a bump test, can you take it down the gas bay", "olek")
    assert [(t.item, t.owner, t.operation) for t in frame.tasks] == [
        ("gas_monitor", "olek", "bump_test")
    ], frame


@pytest.mark.parametrize(
    ("office", "requester", "text", "item", "kind"),
    [
        ("default", "lee", "my lunch is due a reheat", "lunch", "heat"),  # fix129e: has lunch
        (
            "default",
            "lee",
            "my lunch is due a warm-up, can you take it down to the kitchenette",
            "lunch",
            "heat",
        ),
        (
            "harbour",
            "may",
            "my badge is due a lamination, can you take it over to the badge office",
            "badge",
            "heat",
        ),
        ("harbour", "may", "my document is due a scan", "document", "copy"),
    ],
)
def test_the_same_on_the_dataset_offices(
    office: str, requester: str, text: str, item: str, kind: str
) -> None:
    assert tasks_of(office, text, requester) == [(kind, item, requester, requester)]


def test_a_paper_due_a_colleagues_signature_goes_to_them_to_sign() -> None:
    # a colleague's work on a paper is a service of the office too ("signature" of sign)
    frame = parser("default").parse(
        "my contract is due Zhang's signature, can you take it over", "sun"
    )
    assert [(t.kind, t.item, t.owner, t.actor, t.recipient) for t in frame.tasks] == [
        ("sign", "document", "sun", "zhang", "sun")
    ], frame


def test_a_signature_due_from_an_unsaid_signer_is_asked() -> None:
    # "a signature from Zhang" is read as "needs a signature from Zhang" is: who signs is asked
    frame = _lab("my contract is due a signature, can you take it over")
    assert not frame.tasks and frame.question, frame


# -- must not change: "due" of no service of the office ------------------------------------
@pytest.mark.parametrize(
    ("office", "requester", "text"),
    [
        ("harbour", "may", "my badge is due for renewal"),
        ("seed", "ines", "my gas monitor is due back on Friday"),
        ("default", "sun", "my report is due on Friday"),
    ],
)
def test_due_of_no_service_is_still_a_statement(office: str, requester: str, text: str) -> None:
    frame = _lab(text) if office == "seed" else None
    tasks = (
        [t.kind for t in frame.tasks] if frame is not None else tasks_of(office, text, requester)
    )
    assert tasks == [], tasks


def test_a_request_after_a_due_date_is_still_read() -> None:
    assert tasks_of("harbour", "my report is due on Friday, can you bring me the ruler", "may") == [
        ("transfer", "ruler", None, "may")
    ]


async def test_the_requesters_own_gas_monitor_is_tested_and_back() -> None:
    run = await run_instruction(
        seed_lab(), "ines", "my 4-gas is due a bump test, can you take it down the gas bay"
    )
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    # never another colleague's monitor handed over: only Ines's own moved, and back to her
    assert run.sim.world.holder.get("gas_monitor:ines") == "ines", trace.summary
    for other in ("seun", "olek"):
        assert run.sim.world.holder.get(f"gas_monitor:{other}") == other, trace.summary
