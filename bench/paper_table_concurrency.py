"""``paper_table --concurrency 8`` against ``--concurrency 1``, on a scripted server.

The scripted OpenAI-compatible server on 127.0.0.1 answers every call after ``--delay-s``
(a stand-in for a model's generation time) with a decision that ends the episode, so each
episode is one model call and the figure is what running episodes side by side buys when the
server is the bottleneck. Run: ``python bench/paper_table_concurrency.py [--per-level 8]
[--delay-s 3] [--method direct]``; the last line is JSON with both wall times and the speed-up.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import paper_table

from fakes.scripted_llm import RecordedRequest, Reply, ScriptedLLM

STOP = {
    "thought": "scripted",
    "actions": [{"type": "stop", "outcome": "unachievable", "summary": "scripted answer"}],
}


async def measure(args: argparse.Namespace) -> dict[str, object]:
    async with ScriptedLLM() as server:

        def answer(_request: RecordedRequest) -> Reply:
            return Reply(content=json.dumps(STOP), delay_s=args.delay_s)

        server.respond_with(answer)
        walls: dict[int, float] = {}
        with tempfile.TemporaryDirectory() as out:
            for concurrency in (1, 8):
                run = argparse.Namespace(
                    base_url=server.base_url,
                    model="scripted",
                    api_key=None,
                    tasks=paper_table.REPO / "dataset" / "tasks.jsonl",
                    per_level=args.per_level,
                    methods=args.method,
                    max_steps=4,
                    wall_s=None,
                    max_tokens=64,
                    context=8192,
                    call_budget_s=args.delay_s * 10,
                    concurrency=concurrency,
                    out=Path(out),
                )
                result = await paper_table.paper_table(run)
                methods = result["methods"]
                assert isinstance(methods, dict)
                walls[concurrency] = float(methods[args.method]["wall_s"])
                tasks = len(result["tasks"])  # type: ignore[arg-type]
        return {
            "method": args.method,
            "tasks": tasks,
            "delay_s": args.delay_s,
            "requests": len(server.requests),
            "wall_s_concurrency_1": round(walls[1], 2),
            "wall_s_concurrency_8": round(walls[8], 2),
            "speedup": round(walls[1] / walls[8], 2),
        }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--per-level", type=int, default=8)
    parser.add_argument("--delay-s", type=float, default=3.0)
    parser.add_argument("--method", default="direct", choices=sorted(paper_table.METHODS))
    print(json.dumps(asyncio.run(measure(parser.parse_args()))))


if __name__ == "__main__":
    main()
