"""The Matrix part of the service, built by the runtime's start like every other component.

Built once the journal is open (every message in and out is also journaled, like the built-in
messenger's), before the Assistant (which talks through it); started once the Assistant's
inbox is connected (it replays what a previous run accepted and never acknowledged). Its stop
is on the caller's ``AsyncExitStack`` from the moment it is built, so a start that fails later
still closes its HTTP client and its store."""

from __future__ import annotations

from contextlib import AsyncExitStack

from assistantx.adapters.messenger.matrix import MatrixRuntime, MatrixSetup
from assistantx.adapters.messenger.matrix.adapter import Relay, Transcript
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.assistant import Assistant


def build_matrix(
    stack: AsyncExitStack, setup: MatrixSetup, *, transcript: Transcript, relay: Relay
) -> MatrixRuntime:
    """The messenger (not started), writing to ``transcript`` and handing every sent message
    to ``relay``; closed with ``stack``."""
    matrix = setup.build(transcript=transcript)
    stack.push_async_callback(matrix.aclose)  # stops the messenger, closes client and store
    matrix.messenger.relay_to(relay)
    return matrix


async def start_matrix(stack: AsyncExitStack, matrix: MatrixRuntime, assistant: Assistant) -> None:
    """Hook the messenger to ``assistant``'s instructions and start it; it stops with ``stack``
    (pushed before the runtime's own stop, it stops after it: the last acknowledgements are
    written)."""
    messenger = matrix.messenger

    async def ended(stm: ShortTermMemory) -> None:
        await messenger.instruction_ended(stm.instruction_id)

    async def started(stm: ShortTermMemory) -> None:
        # "On it: ...": a Matrix requester sees at once that the work started.
        await messenger.instruction_started(stm.instruction_id, stm.requester, stm.text)

    assistant.on_instruction_end(ended)
    assistant.on_instruction_start(started)
    stack.push_async_callback(messenger.stop)
    await messenger.start()
