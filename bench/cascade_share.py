"""How often the cascade would call the model: the share of the dataset's instructions the
embedded reader is unsure of (its frame asks the requester), per office and level.

Only the cascade's cost is measured here, on the dataset's own phrasings; whether the model's
readings are right is the ``llm_server`` tests' and ``paper_table``'s business. Run:
``python bench/cascade_share.py``; the last line is JSON.
"""

from __future__ import annotations

import json
import time
from collections import Counter
from pathlib import Path

from assistantx.agents.symbolic.frames import InstructionParser
from assistantx.core.office import load_office
from assistantx.evaluation.dataset.tasks import load_tasks

REPO = Path(__file__).resolve().parents[1]
OFFICES = {
    "default": (REPO / "dataset" / "office.yaml", REPO / "dataset" / "tasks.jsonl"),
    "harbour": (
        REPO / "dataset" / "offices" / "harbour" / "office.yaml",
        REPO / "dataset" / "offices" / "harbour" / "tasks.jsonl",
    ),
}


def main() -> None:
    result: dict[str, object] = {}
    for name, (office_file, tasks_file) in OFFICES.items():
        office = load_office(office_file)
        parser = InstructionParser(office)
        unsure: Counter[str] = Counter()
        total: Counter[str] = Counter()
        started = time.perf_counter()
        for task in load_tasks(tasks_file, office):
            frame = parser.parse(task.instruction, task.requester)
            total[task.level] += 1
            unsure[task.level] += frame.question is not None
        elapsed = time.perf_counter() - started
        shares = {level: round(unsure[level] / total[level], 3) for level in sorted(total)}
        result[name] = {
            "instructions": sum(total.values()),
            "would_call_the_model": sum(unsure.values()),
            "share": round(sum(unsure.values()) / max(1, sum(total.values())), 3),
            "share_by_level": shares,
            "read_ms_per_instruction": round(1000 * elapsed / max(1, sum(total.values())), 2),
        }
        print(f"{name}: {result[name]}")
    print(json.dumps(result))


if __name__ == "__main__":
    main()
