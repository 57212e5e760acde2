"""``cascade_share`` against a scripted reader: a server on 127.0.0.1 that answers each
understanding call with the right reading of the sample's unsure phrasings (an ideal model),
and "not sure" for anything else. It shows what the cascade can gain at best, and that the
grounding still holds a reading the request's words do not carry. Run:
``python bench/cascade_scripted.py [cascade_share options, without --model-url]``.
"""

from __future__ import annotations

import asyncio
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from fakes.scripted_llm import RecordedRequest, Reply, ScriptedLLM

HERE = Path(__file__).resolve().parent
# words of the request → the reading an ideal model gives
READINGS = {
    "scissors -> Lee": {
        "sure": True,
        "tasks": [{"kind": "transfer", "item": "scissors", "owner": "Chen", "recipient": "Lee"}],
    },
    "cutting thing": {
        "sure": True,
        "tasks": [{"kind": "transfer", "item": "scissors", "owner": "Chen Jie"}],
    },
}
NOT_SURE = {"sure": False, "tasks": []}


def answer(request: RecordedRequest) -> Reply:
    text = request.last_user_text
    reading = next((r for words, r in READINGS.items() if words in text), NOT_SURE)
    return Reply(content=json.dumps(reading))


async def main() -> int:
    async with ScriptedLLM() as server:
        server.respond_with(answer)
        command = [
            sys.executable,
            str(HERE / "cascade_share.py"),
            "--model-url",
            server.base_url,
            *(sys.argv[1:] or ["--phrasings", str(HERE / "cascade_phrasings.yaml")]),
        ]
        process = await asyncio.create_subprocess_exec(*command)
        code = await process.wait()
        print(f"scripted server: {len(server.requests)} requests", file=sys.stderr)
        return code


if __name__ == "__main__":
    sys.exit(asyncio.run(main()))
