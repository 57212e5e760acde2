"""``assistantx dataset generate``: the task file from an office and its base instructions."""

from __future__ import annotations

import argparse
from collections import Counter
from pathlib import Path

from assistantx.core.errors import DatasetError, OfficeError
from assistantx.core.office import DEFAULT_OFFICE, load_office

DATASET_DIR = DEFAULT_OFFICE.parent


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = sub.add_parser("dataset", help="generate the task dataset")
    dsub = p.add_subparsers(dest="dataset_command", required=True, metavar="ACTION")
    g = dsub.add_parser("generate", help="write tasks.jsonl from base instructions")
    g.add_argument("--seed", type=int, default=0, help="draws the availability variants")
    g.add_argument("--office", default=str(DEFAULT_OFFICE))
    g.add_argument("--base", default=str(DATASET_DIR / "base_instructions.yaml"))
    g.add_argument("--out", default=str(DATASET_DIR / "tasks.jsonl"))
    g.add_argument(
        "--no-verify",
        action="store_true",
        help="skip running every task through the simulator with the optimal policy",
    )
    g.set_defaults(func=_generate)


def _generate(args: argparse.Namespace) -> int:
    from assistantx.evaluation.dataset import dump_tasks, generate, load_base_instructions

    try:
        office = load_office(args.office)
        bases = load_base_instructions(args.base, office)
        tasks = generate(office, bases, args.seed, verify=not args.no_verify)
    except (OfficeError, DatasetError) as exc:
        print(f"error: {exc}")
        return 2
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(dump_tasks(tasks), encoding="utf-8")
    mix = Counter(t.level if t.achievable else "unachievable" for t in tasks)
    verified = "not verified" if args.no_verify else "each solved by the optimal policy in the sim"
    print(f"wrote {len(tasks)} tasks to {out} ({verified})")
    for key in ("L1", "L2", "L3", "unachievable"):
        label = "L3 unachievable" if key == "unachievable" else f"{key} achievable"
        print(f"  {label}: {mix.get(key, 0)}")
    return 0
