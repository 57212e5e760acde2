"""Smart lock figures: code sealing/unsealing, QR rendering, handshake and command latency
over a real TCP link on 127.0.0.1. Last line of stdout: one JSON object with the figures."""

from __future__ import annotations

import asyncio
import json
import statistics
import time

from assistantx.adapters.lock.protocol import CodeIssuer, LockKeys, render_png, unseal
from assistantx.adapters.lock.tcp import TcpLocker
from assistantx.core.clock import WallClock
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.server import LockServer

ROUNDS = 200


def _per_op_us(started: float, count: int) -> float:
    return (time.perf_counter() - started) / count * 1e6


async def _link_figures(keys: LockKeys) -> dict[str, float]:
    clock = WallClock()
    server = LockServer(LockController("locker-1", keys.codes, clock), keys.link_key)
    host, port = await server.start()
    try:
        connects = []
        for _ in range(20):
            started = time.perf_counter()
            async with TcpLocker(host, port, keys, clock=clock, render_png=False):
                connects.append((time.perf_counter() - started) * 1e3)
        async with TcpLocker(host, port, keys, clock=clock, render_png=False) as locker:
            hand_overs = []
            for _ in range(ROUNDS):
                started = time.perf_counter()
                qr = await locker.issue_code(
                    instruction_id="i", person="lee", purpose="collect", item="x"
                )
                await locker.simulate_scan(qr.payload)
                await locker.simulate_close()
                hand_overs.append((time.perf_counter() - started) * 1e3)
            pings = []
            for _ in range(ROUNDS):
                started = time.perf_counter()
                await locker.client.request("ping")
                pings.append((time.perf_counter() - started) * 1e3)
    finally:
        await server.stop()
    return {
        "connect_handshake_ms_median": statistics.median(connects),
        "ping_rtt_ms_median": statistics.median(pings),
        "ping_rtt_ms_p95": statistics.quantiles(pings, n=20)[-1],
        "hand_over_3_commands_ms_median": statistics.median(hand_overs),
    }


def main() -> None:
    keys = LockKeys.generate()
    issuer = CodeIssuer("locker-1", keys.codes, WallClock(), render=False)
    started = time.perf_counter()
    payloads = [
        issuer.issue(instruction_id="ins-1", person="lee", purpose="sign", item="document:lee")[1]
        for _ in range(ROUNDS)
    ]
    seal_us = _per_op_us(started, ROUNDS)
    started = time.perf_counter()
    for payload in payloads:
        unseal(payload, keys.codes)
    unseal_us = _per_op_us(started, ROUNDS)
    started = time.perf_counter()
    png_sizes = [len(render_png(payload)) for payload in payloads[:20]]
    png_ms = _per_op_us(started, 20) / 1e3
    figures: dict[str, float] = {
        "payload_chars": float(len(payloads[0])),
        "seal_us": seal_us,
        "unseal_us": unseal_us,
        "png_render_ms": png_ms,
        "png_bytes": float(statistics.median(png_sizes)),
    }
    figures.update(asyncio.run(_link_figures(keys)))
    for name, value in figures.items():
        print(f"{name:>32}: {value:10.3f}")
    print(json.dumps({k: round(v, 3) for k, v in figures.items()}))


if __name__ == "__main__":
    main()
