"""The service on Matrix as a deployment would run it, for tests played by matrix-nio clients.

``MatrixService`` writes the Matrix YAML, builds the app with ``ASSISTANTX_MESSENGER=matrix``
over one data directory, runs its lifespan with the application-service gateway routed to it,
and restarts it the way SIGTERM and a new start would (the lifespan's shutdown, then a new app
over the same data directory). The decisions come from a script chosen per test (the subject
is the messenger, not the reasoning); the people are real Matrix users at nio clients.
"""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import AsyncIterator, Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml
from fastapi import FastAPI

from assistantx.adapters.messenger.matrix import MatrixConfig
from assistantx.agents.base import AgentContext
from assistantx.core.actions import Action, Inquire, Stop, Wait
from assistantx.core.office import Office as OfficeData
from assistantx.core.settings import Settings
from assistantx.runtime.assistant import ReasonerFactory
from assistantx.service.app import create_app
from helpers.scripted_reasoner import ScriptedReasoner
from synapse.gateway import AppserviceGateway
from synapse.homeserver import Account
from synapse.inbox import Seen
from synapse.nio_people import NioPerson

OPERATOR = "operator-token-for-the-matrix-tests"
Policy = Callable[[AgentContext], list[Action]]

_policy: list[Policy] = []


def scripted(office: OfficeData, settings: object) -> ReasonerFactory:
    """``ASSISTANTX_REASONER_BUILDER`` target: the policy the current test set, every step.

    A policy decides from the instruction's memory (not from a step counter), so an
    instruction resumed after a restart carries on where it was."""
    del office, settings
    policy = _policy[0]
    return lambda: ScriptedReasoner([policy] * 40)


def waiting(ctx: AgentContext, why: str) -> list[Action]:
    """A wait that is new at each step (a repeated identical wait would be refused)."""
    return [Wait(reason=f"{why} (step {ctx.step})", timeout_s=3000)]


def answers_from(ctx: AgentContext, person: str) -> list[str]:
    return [t.text for t in ctx.stm.dialogue if t.direction == "in" and t.person == person]


def asked(ctx: AgentContext) -> list[str]:
    return [t.text for t in ctx.stm.dialogue if t.direction == "out"]


class MatrixService:
    def __init__(
        self,
        config: MatrixConfig,
        gateway: AppserviceGateway,
        data_dir: Path,
        policy: Policy,
    ) -> None:
        self.config = config
        self.gateway = gateway
        self.data_dir = data_dir
        self.config_path = data_dir.parent / f"{data_dir.name}-matrix.yaml"
        self.app: FastAPI | None = None
        self._lifespan: contextlib.AbstractAsyncContextManager[Any] | None = None
        self._an_end = asyncio.Condition()  # notified by the assistant's instruction-end hook
        _policy[:] = [policy]

    @property
    def runtime(self) -> Any:
        assert self.app is not None
        return self.app.state.runtime

    def write_config(self, **update: Any) -> None:
        raw = self.config.model_dump(mode="json")
        raw |= {
            "as_token": self.config.as_token.get_secret_value(),
            "hs_token": self.config.hs_token.get_secret_value(),
        }
        if self.config.pull_access_token is not None:
            raw["pull_access_token"] = self.config.pull_access_token.get_secret_value()
        raw |= update
        self.config = MatrixConfig.model_validate(raw)
        self.config_path.write_text(yaml.safe_dump(raw), encoding="utf-8")

    def use_pull_account(self, account: Account, mode: str) -> None:
        """Mode ``pull`` or ``both`` on ``account``, polling with a short timeout."""
        self.write_config(
            mode=mode,
            pull_user_id=account.user_id,
            pull_access_token=account.access_token,
            sync_timeout_s=1.0,
        )

    async def start(self) -> None:
        self.write_config()
        settings = Settings(
            messenger="matrix",
            matrix_config=self.config_path,
            data_dir=self.data_dir,
            people="human",
            operator_token=OPERATOR,  # type: ignore[arg-type]
            reasoner_builder=f"{__name__}:scripted",
            speedup=100.0,
        )
        self.app = create_app(settings)
        self._lifespan = self.app.router.lifespan_context(self.app)
        await self._lifespan.__aenter__()
        self.runtime.assistant.on_instruction_end(self._note_end)
        self.gateway.mount_app(self.app)
        poller = self.runtime.matrix.messenger.poller
        if poller is not None:
            async with asyncio.timeout(20):
                await poller.ready.wait()

    async def stop(self, *, down: bool = False) -> None:
        """Shut down as on SIGTERM; ``down``: the homeserver's pushes fail meanwhile."""
        if down:
            self.gateway.go_down()
        else:
            self.gateway.unmount()
        if self._lifespan is not None:
            lifespan, self._lifespan = self._lifespan, None
            await lifespan.__aexit__(None, None, None)

    async def restart(self, **update: Any) -> None:
        await self.stop(down=True)
        if update:
            self.write_config(**update)
        await self.start()

    def instructions(self) -> dict[str, Any]:
        assistant = self.runtime.assistant
        return {**assistant.finished, **{k: r.stm for k, r in assistant.running.items()}}

    async def _note_end(self, stm: Any) -> None:
        async with self._an_end:
            self._an_end.notify_all()

    async def wait_ended(self, count: int = 1, timeout_s: float = 30) -> list[Any]:
        finished = self.runtime.assistant.finished
        try:
            async with asyncio.timeout(timeout_s), self._an_end:
                await self._an_end.wait_for(lambda: len(finished) >= count)
        except TimeoutError:
            raise AssertionError(
                f"{count} instruction(s) to end: {len(finished)} ended in {timeout_s:g} s"
            ) from None
        return list(finished.values())


# -- the office of the matrix-nio tests (the `office` fixture is in conftest.py) --------------

PEOPLE = ("lee", "zhang", "mao", "hu")
QUESTION = "May Lee borrow your stapler today?"


@dataclass
class Office:
    config: MatrixConfig
    people: dict[str, NioPerson]
    stranger: NioPerson
    service_for: Callable[[Policy], MatrixService]

    def __getattr__(self, name: str) -> NioPerson:
        return self.people[name]


@contextlib.asynccontextmanager
async def running(service: MatrixService) -> AsyncIterator[MatrixService]:
    await service.start()
    try:
        yield service
    finally:
        await service.stop()


def is_survey(message: Seen) -> bool:
    """The feedback survey each requester gets after an instruction (read apart)."""
    return message.body.startswith("A short survey")


def ask_zhang_through(contact: str, question: str, awaited: str) -> Policy:
    """Ask ``question`` of ``contact`` (Zhang, or a group she is in), wait for her answer, tell
    Lee what she said."""

    def policy(ctx: AgentContext) -> list[Action]:
        if question not in asked(ctx):
            return [Inquire(contact=contact, question=question), Wait(timeout_s=3000)]
        answers = answers_from(ctx, "zhang")
        if not answers:
            return waiting(ctx, awaited)
        return [Stop(outcome="done", summary=f"Zhang answered: {answers[0]}")]

    return policy


borrow = ask_zhang_through("zhang", QUESTION, "Zhang's answer")
BORROW_REQUEST = "Please ask Zhang if I can borrow her stapler."


async def lee_asks_to_borrow(office: Office) -> tuple[str, Seen]:
    """Lee opens a DM with the assistant and asks it to ask Zhang (the ``borrow`` policy);
    returns the DM and the question as Zhang got it."""
    bot = office.config.bot_user_id
    lee_dm = await office.lee.open_dm(bot)
    await office.lee.say(lee_dm, BORROW_REQUEST)
    return lee_dm, await office.zhang.expect(sender=bot)
