"""``python -m assistantx lock-sim`` as its own process, driven over TCP."""

from __future__ import annotations

import asyncio
import os
import signal
import sys
from collections.abc import AsyncIterator
from dataclasses import dataclass
from pathlib import Path

import pytest

from assistantx.adapters.lock.protocol import LockKeys
from assistantx.adapters.lock.protocol.keys import new_key
from assistantx.adapters.lock.tcp import TcpLocker
from assistantx.core.clock import WallClock
from assistantx.core.errors import InvalidCodeError, LockAuthError
from helpers.eventually import eventually
from helpers.servers import free_port

from .conftest import FAST, QUICK_RETRY

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow


@dataclass
class LockSim:
    process: asyncio.subprocess.Process
    port: int
    key_file: Path


@pytest.fixture
async def lock_sim(tmp_path: Path) -> AsyncIterator[tuple[LockSim, LockKeys]]:
    keys = LockKeys.generate()
    key_file = tmp_path / "keys.json"
    key_file.write_text(keys.to_json())
    port = free_port()
    env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
    process = await asyncio.create_subprocess_exec(
        sys.executable,
        "-m",
        "assistantx",
        "lock-sim",
        "--port",
        str(port),
        "--key-file",
        str(key_file),
        "--lock-id",
        "locker-7",
        "--handshake-timeout",
        "0.5",
        stdout=asyncio.subprocess.PIPE,
        env=env,
    )
    assert process.stdout is not None
    async with asyncio.timeout(20):
        banner = (await process.stdout.readline()).decode()
    assert f"listening on 127.0.0.1:{port}" in banner, banner
    try:
        yield LockSim(process, port, key_file), keys
    finally:
        if process.returncode is None:
            process.kill()
            await process.wait()


async def test_hand_over_with_the_emulator_process(lock_sim: tuple[LockSim, LockKeys]) -> None:
    sim, keys = lock_sim
    clock = WallClock()
    async with TcpLocker(
        "127.0.0.1",
        sim.port,
        keys,
        lock_id="locker-7",
        clock=clock,
        timeouts=FAST,
        backoff=QUICK_RETRY,
        expiry_s=60,
    ) as locker:
        events = locker.subscribe()
        qr = await locker.issue_code(
            instruction_id="ins-1", person="lee", purpose="collect", item="key:lee"
        )
        assert (await locker.simulate_scan(qr.payload)).kind == "code_accepted"
        assert (await locker.simulate_close()).person == "lee"
        assert (await locker.simulate_scan(qr.payload)).reason == "replayed"
        async with asyncio.timeout(2):
            kinds = [(await events.get()).kind for _ in range(4)]
        assert kinds == ["code_accepted", "door_opened", "door_closed", "code_rejected"]

    intruder = LockKeys(link_key=new_key(), codes=keys.codes)
    with pytest.raises(LockAuthError):
        await TcpLocker("127.0.0.1", sim.port, intruder, timeouts=FAST).start()

    sim.process.send_signal(signal.SIGTERM)
    async with asyncio.timeout(5):
        assert await sim.process.wait() == 0


async def test_sighup_reloads_rotated_keys(lock_sim: tuple[LockSim, LockKeys]) -> None:
    sim, keys = lock_sim
    async with TcpLocker(
        "127.0.0.1",
        sim.port,
        keys,
        clock=WallClock(),
        timeouts=FAST,
        backoff=QUICK_RETRY,
        render_png=False,
    ) as locker:
        old = await locker.issue_code(instruction_id="i", person="lee", purpose="seal", item="x")
        keys.codes.rotate("k2", new_key())
        sim.key_file.write_text(keys.to_json())
        # Before the lock reloads, it cannot read codes under the new key...
        _, early = locker.issuer.issue(instruction_id="i", person="lee", purpose="seal", item="x")
        assert (await locker.simulate_scan(early)).reason == "unknown_key"
        sim.process.send_signal(signal.SIGHUP)
        # Until the signal is handled, issuing under the new key fails.
        new = await eventually(
            lambda: locker.issue_code(instruction_id="i", person="zhang", purpose="seal", item="y"),
            what="the lock to reload its keys after SIGHUP",
            timeout_s=3,
            ignore=(InvalidCodeError,),
        )
        # ...afterwards codes of both keys open the door, on the same connection.
        assert (await locker.simulate_scan(old.payload)).kind == "code_accepted"
        await locker.simulate_close()
        assert (await locker.simulate_scan(new.payload)).kind == "code_accepted"
        assert locker.client.connections == 1
