"""The reasoner's factory built after ready: once, by the warm-up or by the first use."""

from __future__ import annotations

import asyncio
import threading

import pytest

from assistantx.agents.base import Reasoner, ReasonerFactory
from assistantx.core.office import PersonId, load_office
from assistantx.core.settings import Settings
from assistantx.service.reasoner_warmup import DeferredFactory
from assistantx.sim.office import SimOffice
from helpers.office import sim_assistant, started
from service.stapler_reasoner import build_factory as stapler_factory


class _Built:
    """A stand-in for a built factory: counts the reasoners it makes."""

    def __init__(self) -> None:
        self.made = 0

    def __call__(self) -> Reasoner:
        self.made += 1
        return object()  # type: ignore[return-value]  # never started here


def test_nothing_is_built_until_the_first_use_and_then_once() -> None:
    builds: list[_Built] = []

    def build() -> ReasonerFactory:
        builds.append(_Built())
        return builds[-1]

    deferred = DeferredFactory(build)
    assert builds == []
    deferred()
    deferred()
    assert len(builds) == 1
    assert builds[0].made == 2


def test_a_first_use_during_the_warm_up_waits_for_it_instead_of_building_again() -> None:
    started, release = threading.Event(), threading.Event()
    builds: list[_Built] = []

    def build() -> ReasonerFactory:
        started.set()
        release.wait(10)
        builds.append(_Built())
        return builds[-1]

    deferred = DeferredFactory(build)
    warm_up = deferred.warm_in_background()
    assert started.wait(10)
    first_use = threading.Thread(target=deferred)
    first_use.start()
    release.set()
    first_use.join(10)
    warm_up.join(10)
    assert len(builds) == 1
    assert builds[0].made == 1


def test_a_failed_warm_up_is_raised_on_first_use(caplog: pytest.LogCaptureFixture) -> None:
    def build() -> ReasonerFactory:
        raise RuntimeError("no lexicon")

    deferred = DeferredFactory(build)
    deferred.warm_in_background().join(10)
    assert "building the reasoner failed: no lexicon" in caplog.text
    with pytest.raises(RuntimeError, match="no lexicon"):
        deferred()


def test_the_warm_up_never_holds_up_the_process_exit() -> None:
    """A stop right after the start: the interpreter does not wait for the warm-up."""
    release = threading.Event()
    deferred = DeferredFactory(lambda: (release.wait(10), _Built())[1])
    thread = deferred.warm_in_background()
    assert thread.daemon
    release.set()
    thread.join(10)


async def test_waiting_for_a_factory_being_built_leaves_the_loop_free() -> None:
    release = threading.Event()
    made = _Built()

    def build() -> ReasonerFactory:
        # Set by the loop: a wait that held the loop would never see it (the guard ends it).
        assert release.wait(timeout=10), "the wait held the loop"
        return made

    deferred = DeferredFactory(build)
    deferred.warm_in_background()
    waiting = asyncio.create_task(deferred.built())
    await asyncio.sleep(0)
    release.set()
    await waiting
    assert deferred.factory() is made


async def test_an_instruction_started_outside_admission_waits_for_the_warm_up_off_the_loop() -> (
    None
):
    # A direct message's instruction calls Assistant.submit itself, not through Admission.
    office = load_office()
    sim = SimOffice(office)
    release = threading.Event()

    def build() -> ReasonerFactory:
        assert release.wait(timeout=10), "the wait held the loop"
        return stapler_factory(office, Settings())

    deferred = DeferredFactory(build)
    assistant = sim_assistant(sim, deferred)
    assistant.reasoner_ready = deferred.built
    async with started(sim, assistant):
        deferred.warm_in_background()
        submitting = asyncio.create_task(assistant.submit(PersonId("lee"), "a stapler please"))
        await asyncio.sleep(0)  # the submission is waiting for the warm-up now
        release.set()  # only a free loop gets here
        stm = await submitting
        assert stm.instruction_id in assistant.running
        assert assistant.cancel(stm.instruction_id)
