"""Overhead of the LLM client stack against the scripted server on 127.0.0.1.

Measures what our code adds per call (HTTP round trip, JSON, retries bookkeeping), not a
model: plain completions sequentially and 8 at a time, and structured calls that need one
repair. Run: ``python bench/llm_client.py [--calls N]``; the last line is JSON.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from pydantic import BaseModel

from assistantx.adapters.model import (
    ChatRequest,
    Message,
    OpenAICompatibleModel,
    RetryPolicy,
    structured_call,
)
from fakes.scripted_llm import ScriptedLLM, json_reply


class Answer(BaseModel):
    answer: str


def request(agent: str) -> ChatRequest:
    return ChatRequest(
        messages=(
            Message(role="system", content=f"AGENT: {agent}\n" + "memory line\n" * 200),
            Message(role="user", content="What next?"),
        ),
        agent=agent,
    )


def percentile_ms(samples: list[float], q: float) -> float:
    ordered = sorted(samples)
    return 1000 * ordered[min(len(ordered) - 1, int(q * len(ordered)))]


async def run(calls: int) -> dict[str, float]:
    async with ScriptedLLM() as server:
        server.respond_with(lambda _: "ok", agent="plain")
        bad_then_good = iter([json_reply({"wrong": 1}), json_reply({"answer": "x"})] * calls)
        server.respond_with(lambda _: next(bad_then_good), agent="structured")
        model = OpenAICompatibleModel(server.base_url, "bench", retry=RetryPolicy(seed=0))
        async with model:
            latencies = []
            started = time.perf_counter()
            for _ in range(calls):
                latencies.append((await model.complete(request("plain"))).latency_s)
            sequential_s = time.perf_counter() - started

            started = time.perf_counter()
            for _ in range(calls // 8):
                await asyncio.gather(*(model.complete(request("plain")) for _ in range(8)))
            concurrent_s = time.perf_counter() - started

            started = time.perf_counter()
            structured = max(1, calls // 4)
            for _ in range(structured):
                await structured_call(model, request("structured"), Answer)
            structured_s = time.perf_counter() - started
    return {
        "calls": calls,
        "sequential_calls_per_s": round(calls / sequential_s, 1),
        "p50_ms": round(percentile_ms(latencies, 0.5), 2),
        "p95_ms": round(percentile_ms(latencies, 0.95), 2),
        "concurrent8_calls_per_s": round((calls // 8) * 8 / concurrent_s, 1),
        "structured_with_one_repair_ms": round(1000 * structured_s / structured, 2),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--calls", type=int, default=400)
    args = parser.parse_args()
    figures = asyncio.run(run(args.calls))
    print(
        f"sequential: {figures['sequential_calls_per_s']} calls/s "
        f"(p50 {figures['p50_ms']} ms, p95 {figures['p95_ms']} ms)"
    )
    print(f"8 concurrent: {figures['concurrent8_calls_per_s']} calls/s")
    print(f"structured call with one repair: {figures['structured_with_one_repair_ms']} ms")
    print(json.dumps(figures))


if __name__ == "__main__":
    main()
