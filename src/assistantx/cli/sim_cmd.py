"""``assistantx sim``: drive the simulated office by hand, one action per line.

Actions are typed as JSON (``{"type": "inquire", "contact": "zhang", "question": "..."}``) or
as ``TYPE key=value ...`` (``inquire contact=zhang question="Do you have a stapler?"``).
``:goal {"holds": ["lee", "stapler:zhang"]}`` checks a milestone, ``:world`` prints the truth,
``help`` lists all this, ``:quit`` ends. Reads stdin, so a script can be piped in. ``--as`` and
``--unavailable`` take names, matched like any name a person types.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import shlex
import sys
from typing import Any

from pydantic import ValidationError

from assistantx.cli._people import resolve_people
from assistantx.core.actions import parse_action
from assistantx.core.errors import GroundingError, OfficeError
from assistantx.core.office import load_office
from assistantx.sim.session import SimSession


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = sub.add_parser(
        "sim",
        help="drive the simulated office by hand",
        description="Drive the simulated office by hand: one action per line on stdin.",
        epilog=HELP,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--as", dest="requester", default="lee", help="the requester's name")
    parser.add_argument("--unavailable", default="", help="comma-separated names of absent people")
    parser.add_argument("--office", default=None, help="office YAML")
    parser.set_defaults(func=_run)


HELP = """\
actions (one per line):
  inform contact=zhang content="The robot is on its way"
  inquire contact=zhang question="Do you have a stapler?"
  forward_file source=lee target=zhang
  send_qr contact=zhang item=stapler:zhang
  wait timeout_s=60
  move place=zhang            (a person's desk, a facility or a location)
  wait_in_place person=zhang
  stop outcome=done summary="..."
  or as JSON: {"type": "inquire", "contact": "zhang", "question": "..."}
commands:
  :goal {"holds": ["lee", "stapler:zhang"]}   check a milestone
  :world                                      the simulated truth
  help                                        this text
  :quit                                       end"""


def parse_line(line: str) -> dict[str, Any]:
    line = line.strip()
    if line.startswith("{"):
        data = json.loads(line)
        if not isinstance(data, dict):
            raise ValueError("an action is a JSON object")
        return data
    words = shlex.split(line)
    action: dict[str, Any] = {"type": words[0]}
    for word in words[1:]:
        key, sep, value = word.partition("=")
        if not sep:
            raise ValueError(f"expected key=value, got {word!r}")
        action[key] = value
    return action


def _run(args: argparse.Namespace) -> int:
    try:
        office = load_office(args.office)
        requester, unavailable = resolve_people(office, args.requester, args.unavailable)
    except (OfficeError, GroundingError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return asyncio.run(_session(office, requester, unavailable))


async def _session(office: Any, requester: str, unavailable: tuple[str, ...]) -> int:
    async with SimSession(office, requester=requester, unavailable=unavailable) as s:
        print(f"simulated office; requester {s.stm.requester}; type actions, help, :quit to end")
        for raw in sys.stdin:
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            if line in (":quit", ":q"):
                break
            if line in ("help", ":help", "?"):
                print(HELP)
                continue
            if line == ":world":
                w = s.sim.world
                print(
                    f"t={s.sim.clock.now():.0f}s locker={w.locker_contents()} "
                    f"robot={s.sim.robot.place} printed={sorted(w.printed)}"
                )
                continue
            if line.startswith(":goal"):
                milestone = json.loads(line[len(":goal") :])
                print(f"goal {json.dumps(milestone)}: {s.sim.world.check(milestone)}")
                continue
            seen = len(s.stm.dialogue)
            try:
                action = parse_action(parse_line(line))
                result = await s.do(action)
            except (ValueError, ValidationError, GroundingError) as exc:
                print(f"error: {exc}")
                continue
            status = "ok" if result.ok else "FAILED"
            print(f"t={s.sim.clock.now():.0f}s {status}: {result.observation}")
            for turn in s.stm.dialogue[seen:]:
                if turn.direction == "in":
                    print(f"  {turn.person}: {turn.text}")
    return 0
