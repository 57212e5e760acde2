"""``assistantx sim``: drive the simulated office by hand, one action per line.

Actions are typed as JSON (``{"type": "inquire", "contact": "zhang", "question": "..."}``) or
as ``TYPE key=value ...`` (``inquire contact=zhang question="Do you have a stapler?"``).
``:goal {"holds": ["lee", "stapler:zhang"]}`` checks a milestone, ``:world`` prints the truth
(who holds what included), ``:run TEXT`` runs a whole instruction, ``help`` lists all this,
``:quit`` ends. A plain sentence is offered to run as an instruction. Reads stdin, so a script
can be piped in; on a terminal it prompts. ``--as``, ``--unavailable`` and every name in an
action or a milestone are matched like any name a person types (``memory/resolve.py``).
"""

from __future__ import annotations

import argparse
import asyncio
import json
import shlex
import sys
from collections import defaultdict
from collections.abc import Iterator
from typing import Any

from pydantic import ValidationError

from assistantx.agents.registry import reasoner_factory
from assistantx.cli._people import resolve_people
from assistantx.cli.run_cmd import print_trace
from assistantx.core import task_kinds
from assistantx.core.actions import ACTION_TYPES, parse_action
from assistantx.core.errors import AssistantXError, GroundingError, OfficeError
from assistantx.core.office import Office, PersonId, load_office
from assistantx.core.settings import Settings
from assistantx.memory.graph import LOCKER
from assistantx.sim.run import run_in_sim
from assistantx.sim.session import SimSession

PROMPT = "sim> "
ACTION_NAMES = tuple(t.model_fields["type"].default for t in ACTION_TYPES)


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


# The example is a whole fetch, in order, so that typing it line by line works: Zhang's code
# puts the stapler in (deposit) and Lee's takes it out (collect).
EXAMPLE = """\
  inquire contact=zhang question="Do you have a stapler?"
  wait timeout_s=60
  move place=zhang
  send_qr contact=zhang item=stapler:zhang purpose=deposit
  wait_in_place person=zhang
  move place=lee
  send_qr contact=lee item=stapler:zhang purpose=collect
  wait_in_place person=lee
  :goal {"holds": ["Lee", "stapler:Zhang"]}
  stop outcome=done summary="Zhang's stapler is with you\""""

HELP = f"""\
an example, as Lee (--as lee): fetch Zhang's stapler, one line at a time
{EXAMPLE}
other actions:
  inform contact=zhang content="The robot is on its way"
  forward_file source=lee target=zhang
  move place="print room"     (a person's desk, a facility or a location)
  send_qr purposes: {", ".join(task_kinds.purposes())}
  or as JSON: {{"type": "inquire", "contact": "zhang", "question": "..."}}
commands:
  :goal {{"holds": ["lee", "stapler:zhang"]}}   check a milestone (names as you type them)
  :world                                      the simulated truth: who holds what, locker, robot
  :run bring me a stapler                     run a whole instruction (a fresh office)
  help                                        this text
  :quit                                       end"""


class NotAnActionError(ValueError):
    """A line that is no action: it starts with a word that names none."""


def parse_line(line: str) -> dict[str, Any]:
    line = line.strip()
    if line.startswith("{"):
        data = json.loads(line)
        if not isinstance(data, dict):
            raise ValueError("an action is a JSON object")
        return data
    words = shlex.split(line)
    if words[0] not in ACTION_NAMES:
        raise NotAnActionError(f"{words[0]!r} is not an action ({', '.join(ACTION_NAMES)})")
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


def _lines() -> Iterator[str]:
    """Input lines; with a prompt when a person types them."""
    if not sys.stdin.isatty():
        yield from sys.stdin
        return
    while True:
        try:
            yield input(PROMPT)
        except EOFError:
            print()
            return


async def _session(office: Office, requester: PersonId, unavailable: tuple[str, ...]) -> int:
    async with SimSession(office, requester=requester, unavailable=unavailable) as s:
        who = office.person(requester).name
        print(f"simulated office; requester {who}; type actions, help, :quit to end")
        offered: str | None = None  # a sentence we offered to run as an instruction
        for raw in _lines():
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            if offered is not None:
                sentence, offered = offered, None
                if line.lower() in ("y", "yes"):
                    await _instruction(office, requester, unavailable, sentence)
                    continue
                if line.lower() in ("n", "no"):
                    continue
            if line in (":quit", ":q"):
                break
            if line in ("help", ":help", "?"):
                print(HELP)
            elif line == ":world":
                print(_world(s))
            elif line.startswith(":goal"):
                print(_goal(s, line[len(":goal") :]))
            elif line.startswith(":run"):
                text = line[len(":run") :].strip()
                if text:
                    await _instruction(office, requester, unavailable, text)
                else:
                    print("error: say the instruction after :run, e.g. :run bring me a stapler")
            else:
                offered = await _action(s, line, who)
    return 0


async def _action(s: SimSession, line: str, who: str) -> str | None:
    """Do one action line and print the result; returns the line when it was a sentence we
    offered to run as an instruction."""
    seen = len(s.stm.dialogue)
    try:
        action = parse_action(parse_line(line))
        result = await s.do(action)
    except NotAnActionError:
        print(
            f"{line!r} is not an action. Run it as an instruction from {who} "
            "(in a fresh simulated office)? [y/N]"
        )
        return line
    except (ValueError, ValidationError, GroundingError) as exc:
        print(f"error: {exc}")
        return None
    status = "ok" if result.ok else "FAILED"
    print(f"t={s.sim.clock.now():.0f}s {status}: {result.observation}")
    for turn in s.stm.dialogue[seen:]:
        if turn.direction == "in":
            print(f"  {turn.person}: {turn.text}")
    return None


def _goal(s: SimSession, text: str) -> str:
    try:
        milestone = s.resolver.ground_milestone(json.loads(text))
    except json.JSONDecodeError:
        return 'error: a goal is JSON after :goal, e.g. :goal {"holds": ["lee", "stapler:zhang"]}'
    except (ValueError, GroundingError) as exc:
        return f"error: {exc}"
    return f"goal {json.dumps(milestone)}: {s.sim.world.check(milestone)}"


def _world(s: SimSession) -> str:
    """The truth in a few lines: clock, robot, locker, who holds which item, what was done."""
    world, office = s.sim.world, s.office
    held: defaultdict[str, list[str]] = defaultdict(list)
    for item, holder in sorted(world.holder.items()):
        held[holder].append(item)
    lines = [f"t={s.sim.clock.now():.0f}s robot at {s.sim.robot.place}"]
    lines.append("locker: " + (", ".join(held.pop(LOCKER, [])) or "empty"))
    people = {p.id: p.name for p in office.people}
    for holder in sorted(held, key=lambda h: (h not in people, people.get(h, h))):
        lines.append(f"{people.get(holder, holder)} holds: {', '.join(held[holder])}")
    if world.printed:
        lines.append(f"printed: {', '.join(sorted(world.printed))}")
    return "\n".join(lines)


async def _instruction(
    office: Office, requester: PersonId, unavailable: tuple[str, ...], text: str
) -> None:
    """Run ``text`` as a whole instruction, as ``assistantx run`` does, and print its trace."""
    settings = Settings()
    kind = settings.effective_reasoner
    try:
        run = await run_in_sim(
            office,
            requester,
            text,
            reasoner_factory(kind, office, settings),
            unavailable=unavailable,
            reasoner_name=kind,
        )
    except AssistantXError as exc:
        print(f"error: {exc}")
        return
    print_trace(run.trace)
