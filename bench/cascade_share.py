"""The cascade on a file of phrasings: how often it calls the model, and whether its results
and the embedded reader's (``--reasoner symbolic``) are right.

Each case runs twice through the CLI's ``assistantx run`` in the simulated office, once per
reasoner, and is judged on its trace against the case's expectation: the outcome matches,
every expected delivery reached the right person, no other item was handed over, every
person whose consent is needed was asked, and nothing physical happened for ``no_action`` and
``decline``. Run::

    python bench/cascade_share.py --phrasings bench/cascade_phrasings.yaml \\
        --model-url http://127.0.0.1:8080/v1 [--model NAME] [--office O] [--anchors A] \\
        [--traces DIR]

The phrasings file (YAML)::

    office: path/to/office.yaml        # optional; --office overrides it
    anchors: path/to/anchors.yaml      # optional; --anchors overrides it
    cases:
      - id: p1
        class: plain                   # free text, reported per class
        requester: lee                 # person id
        text: "bring me Zhang's stapler"
        expect:
          outcome: done                # done | no_action | decline | ask | unachievable
          deliver: [{item: stapler, owner: zhang, to: lee}]   # owner null: anyone's
          consent: [zhang]             # people whose yes is needed

One line per case, a total per class, and last one JSON object
``{"cases", "model_called", "right_symbolic", "right_cascade"}``. A relative path in the file
is relative to the file.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from assistantx.core.errors import OfficeError
from assistantx.core.office import Office, load_office

REASONERS = ("symbolic", "cascade")
# actions that move the robot or hand something over (talk, waits and stop do neither)
PHYSICAL = frozenset({"send_qr", "forward_file", "move", "wait_in_place"})


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", populate_by_name=True)


class Delivery(_Strict):
    item: str = Field(description="item type id")
    owner: str | None = None
    to: str


class Expect(_Strict):
    outcome: Literal["done", "no_action", "decline", "ask", "unachievable"]
    deliver: list[Delivery] = Field(default_factory=list)
    consent: list[str] = Field(default_factory=list)


class Case(_Strict):
    id: str
    class_: str = Field(alias="class")
    requester: str
    text: str
    expect: Expect


class Phrasings(_Strict):
    office: str | None = None
    anchors: str | None = None
    cases: list[Case] = Field(min_length=1)


@dataclass(frozen=True)
class Run:
    """One case run by one reasoner: its judgement and whether it asked the model."""

    right: bool
    why: str
    model_calls: int


def judge(case: Case, trace: dict[str, Any], office: Office) -> tuple[bool, str]:
    """Whether one trace meets the case's expectation, and if not, why (in words).

    What is handed over to have a service done (a file to the printer's keeper, for the
    printout expected) is part of that service, not a delivery."""
    expect = case.expect
    wanted = {d.item for d in expect.deliver}
    service_inputs = {op.input for op in office.operations if op.product in wanted}
    ran = [
        r["action"]
        for step in trace.get("steps", [])
        for r in step.get("results", [])
        if r.get("ok") and not r.get("refused")
    ]
    physical = [a for a in ran if a["type"] in PHYSICAL]
    handed = [
        (a["item"].partition(":")[0], a["item"].partition(":")[2], a["contact"])
        for a in ran
        if a["type"] == "send_qr" and a.get("purpose") == "collect"
    ] + [
        (a.get("file", "file:").partition(":")[0], a["source"], a["target"])
        for a in ran
        if a["type"] == "forward_file"
    ]
    handed = [h for h in handed if h[0] not in service_inputs]
    asked = {a["contact"] for a in ran if a["type"] == "inquire"}
    outcome = trace.get("outcome")
    if expect.outcome == "done" and outcome != "done":
        return False, f"outcome {outcome}, expected done"
    if expect.outcome == "unachievable" and outcome != "unachievable":
        return False, f"outcome {outcome}, expected unachievable"
    if expect.outcome in ("no_action", "decline") and physical:
        return False, f"acted ({physical[0]['type']}) where nothing should happen"
    if expect.outcome == "no_action" and outcome == "failed":
        return False, "failed where nothing was needed"
    if expect.outcome == "decline" and outcome == "done" and not asked:
        return False, "went along with what it should decline"
    if expect.outcome == "ask" and case.requester not in asked:
        return False, "never asked the requester"
    for want in expect.deliver:
        hit = next(
            (
                h
                for h in handed
                if h[0] == want.item and h[2] == want.to and want.owner in (None, h[1])
            ),
            None,
        )
        if hit is None:
            return False, f"{want.item} never handed to {want.to}"
        handed.remove(hit)
    if handed:
        item, owner, to = handed[0]
        return False, f"also handed {item}:{owner} to {to}"
    missing = [p for p in expect.consent if p not in asked]
    if missing:
        return False, f"never asked {', '.join(missing)} for consent"
    return True, "right"


def run_case(
    case: Case, reasoner: str, args: argparse.Namespace, office_file: str | None, office: Office
) -> Run:
    env = dict(os.environ)
    env["ASSISTANTX_LLM_BASE_URL"] = args.model_url
    env["ASSISTANTX_LLM_MODEL"] = args.model
    env["ASSISTANTX_INSTRUCTION_WALL_S"] = str(args.case_wall_s)
    if args.anchors:
        env["ASSISTANTX_MAP_ANCHORS"] = args.anchors
    with tempfile.TemporaryDirectory() as tmp:
        trace_file = Path(tmp) / "trace.json"
        command = [
            sys.executable,
            "-m",
            "assistantx",
            "run",
            case.text,
            "--as",
            case.requester,
            "--reasoner",
            reasoner,
            "--json",
            "--quiet",
            "--max-steps",
            str(args.max_steps),
            "--trace-out",
            str(trace_file),
        ]
        if office_file:
            command += ["--office", office_file]
        done = subprocess.run(command, env=env, capture_output=True, text=True, check=False)
        if not trace_file.exists():
            error = (done.stderr.strip().splitlines() or ["no trace"])[-1]
            return Run(False, f"run failed: {error}", 0)
        trace = json.loads(trace_file.read_text())
        if args.traces:
            args.traces.mkdir(parents=True, exist_ok=True)
            (args.traces / f"{case.id}-{reasoner}.json").write_text(trace_file.read_text())
    right, why = judge(case, trace, office)
    return Run(right, why, int(trace.get("usage", {}).get("llm_calls", 0)))


def _relative(path: str | None, base: Path) -> str | None:
    if path is None:
        return None
    return str(path if Path(path).is_absolute() else (base / path))


def load_phrasings(path: Path) -> Phrasings:
    try:
        raw = yaml.safe_load(path.read_text())
        return Phrasings.model_validate(raw)
    except (OSError, yaml.YAMLError) as exc:
        sys.exit(f"error: cannot read {path}: {exc}")
    except ValidationError as exc:
        first = exc.errors()[0]
        where = ".".join(str(p) for p in first["loc"])
        sys.exit(f"error: {path}: {where}: {first['msg']}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--phrasings", type=Path, required=True)
    parser.add_argument("--office", default=None, help="office YAML (default: the file's)")
    parser.add_argument("--anchors", default=None, help="map anchors YAML (default: the file's)")
    parser.add_argument("--model-url", required=True, help="OpenAI-compatible /v1 URL")
    parser.add_argument("--model", default="local", help="model name sent to the server")
    parser.add_argument("--max-steps", type=int, default=20)
    parser.add_argument("--traces", type=Path, default=None, help="keep each run's trace here")
    parser.add_argument("--case-wall-s", type=float, default=600.0, help="wall bound per run")
    args = parser.parse_args()
    phrasings = load_phrasings(args.phrasings)
    base = args.phrasings.resolve().parent
    office_file = args.office or _relative(phrasings.office, base)
    try:
        office = load_office(office_file)
    except OfficeError as exc:
        sys.exit(f"error: {exc}")
    args.anchors = args.anchors or _relative(phrasings.anchors, base)

    called = 0
    right: Counter[str] = Counter()
    by_class: dict[str, Counter[str]] = {}
    for case in phrasings.cases:
        runs = {r: run_case(case, r, args, office_file, office) for r in REASONERS}
        cascade_called = runs["cascade"].model_calls > 0
        called += cascade_called
        tally = by_class.setdefault(case.class_, Counter())
        tally["cases"] += 1
        tally["model_called"] += cascade_called
        for name, run in runs.items():
            right[name] += run.right
            tally[f"right_{name}"] += run.right
        print(
            f"{case.id} [{case.class_}] model called: {'yes' if cascade_called else 'no'}"
            f" ({runs['cascade'].model_calls} requests); "
            + "; ".join(
                f"{name}: {'right' if run.right else 'wrong'} ({run.why})"
                for name, run in runs.items()
            )
        )
    for name, tally in sorted(by_class.items()):
        print(f"class {name}: {dict(tally)}")
    print(
        json.dumps(
            {
                "cases": len(phrasings.cases),
                "model_called": called,
                "right_symbolic": right["symbolic"],
                "right_cascade": right["cascade"],
            }
        )
    )


if __name__ == "__main__":
    main()
