"""The metrics of DESIGN §5, as pure functions of an Episode.

- **SR** (success): for an achievable task every goal milestone holds, the method stopped
  with ``done`` (the requester was told, and told the truth) and nothing was handed to the
  wrong person. For an unachievable task the method stopped with ``unachievable`` (the stop
  message tells the requester why), made no false claim (a ``done`` fails) and handed nothing
  to the wrong person. In both, nothing was sent outside the office (faxed, couriered) with
  words that do not name where the requester wanted it to go.
- **CR** (completion): milestones reached / milestones in the goal. The ``informed``
  milestone of an unachievable task counts only when the requester was told ``unachievable``;
  that of the requester in an achievable task only when they were told ``done``: being told
  of a failure is no progress toward the goal.
- **RR** (redundancy): redundant actions / ``optimal_actions``. An action is redundant when it
  repeats an earlier action with no new information in between, is aimed at a person already
  known to be unavailable, or reaches nobody and nothing relevant to the goal.
- **CTA / RTA**: correct cyber / real-world actions over all cyber / real-world actions;
  correct = valid (executed, and not rejected for its arguments or the state), grounded in
  memory (not refused by grounding) and not redundant. ``None`` when there were none.

*New information* is anything the assistant could observe: a reply (a wait that got one), a
failure or timeout, the robot arriving somewhere, a hand-over at the locker, a memory update
that changed something. *Known unavailable*: memory was updated to say so, or the assistant
asked the person directly and a later wait timed out with no word from them.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from fnmatch import fnmatchcase

from assistantx.core import english
from assistantx.core.actions import Inquire, Move, Stop
from assistantx.core.goals import parse_milestone
from assistantx.core.language import fold
from assistantx.core.trace import ActionResult
from assistantx.evaluation.episode import Episode
from assistantx.memory.updates import AvailabilityUpdate

CYBER = frozenset({"inform", "inquire", "forward_file", "send_qr", "wait"})
REAL = frozenset({"move", "wait_in_place"})
# a failure of these is news about the world, not a mistake of the action
_FAILURE_IS_NEWS = frozenset({"wait", "wait_in_place"})


@dataclass
class ActionVerdict:
    result: ActionResult
    redundant: bool = False
    why: list[str] = field(default_factory=list)
    valid: bool = True

    @property
    def correct(self) -> bool:
        return self.valid and not self.redundant


@dataclass(frozen=True)
class Scores:
    sr: float
    cr: float
    rr: float
    cta: float | None
    rta: float | None
    actions: int
    redundant: int
    wrong_handover: bool
    steps: int
    llm_calls: int
    prompt_tokens: int
    completion_tokens: int
    wall_s: float

    def as_dict(self) -> dict[str, float | int | bool | None]:
        return dict(self.__dict__)


def outcome(episode: Episode) -> str | None:
    return episode.trace.outcome


def requester_told(episode: Episode) -> bool:
    """A stop was executed: its message went to the requester."""
    return any(
        isinstance(r.action, Stop) and r.ok and not r.refused for r in episode.trace.actions()
    )


def _holds_goal(episode: Episode) -> list[tuple[str, str]]:
    """(person, item pattern) pairs someone is meant to end up with, also in what was asked
    for an unachievable task (a part that could be done may be done)."""
    pairs = []
    for milestone in [*episode.goal, *episode.requested_goal]:
        name, args = parse_milestone(milestone)
        if name == "holds":
            pairs.append((args[0], args[1]))
    return pairs


def wrong_handovers(episode: Episode) -> list[str]:
    """Items that ended with a person who neither owns them nor is meant to get them."""
    wanted = _holds_goal(episode)
    wrong = []
    for h in episode.handovers:
        owner = h.item.partition(":")[2]
        if h.to == owner:
            continue
        if any(person == h.to and fnmatchcase(h.item, pattern) for person, pattern in wanted):
            continue
        wrong.append(f"{h.item} → {h.to}")
    return wrong


def _words(text: str) -> frozenset[str]:
    # one key for case, accents, curly apostrophes and punctuation, and for an address word's
    # short form ("dept", "Rd"): both sides are read alike, so "housing dept" tells
    # "housing department"
    found = re.findall(r"[^\W_]+(?:'[^\W_]+)?", fold(text))
    return frozenset(_ADDRESS_WORDS.get(w, w) for w in found)


_ADDRESS_WORDS = english.wording("address_abbreviations")


def wrong_sends(episode: Episode) -> list[str]:
    """Items sent outside the office whose sender was not told where the requester wanted
    them to go: every word of one of the task's destinations must be in their code's words
    ("Dublin customer relations" is told by "to Dublin, attention Customer Relations"; "to
    Broadcast Centre" does not tell "Broadcast Centre, White City")."""
    wanted = [_words(d) for d in episode.destinations]
    return [s.item for s in episode.sent_out if not any(w <= _words(s.told) for w in wanted)]


def success(episode: Episode) -> bool:
    if episode.error is not None or wrong_handovers(episode) or wrong_sends(episode):
        return False
    if episode.achievable:
        return outcome(episode) == "done" and all(episode.milestones)
    return outcome(episode) == "unachievable" and requester_told(episode)


def completion(episode: Episode) -> float:
    if not episode.goal:
        return 0.0
    reached = 0
    for milestone, holds in zip(episode.goal, episode.milestones, strict=True):
        name, args = parse_milestone(milestone)
        if name == "informed" and not episode.achievable:
            holds = holds and outcome(episode) == "unachievable" and requester_told(episode)
        elif name == "informed" and episode.requester in args:
            holds = holds and outcome(episode) == "done"
        reached += bool(holds)
    return reached / len(episode.goal)


def judge_actions(episode: Episode) -> list[ActionVerdict]:
    """Every action of the trace (executed or refused), judged in order."""
    relevant = set(episode.relevant_people)
    places = set(episode.relevant_places)
    info = 0  # bumped on every piece of new information
    seen: dict[str, int] = {}  # action signature → info version when last done
    known_away: set[str] = set()
    asked_since: dict[str, bool] = {}  # person → asked directly, no word from them since
    verdicts: list[ActionVerdict] = []
    for step in episode.trace.steps:
        for r in step.results:
            v = ActionVerdict(r)
            action = r.action
            signature = action.signature()
            if r.refused or (
                not r.ok and action.type not in _FAILURE_IS_NEWS and action.type != "stop"
            ):
                v.valid = False
            if not isinstance(action, Stop) and seen.get(signature) == info:
                v.redundant = True
                v.why.append("repeats an earlier action with no new information")
            targets = [t for t in action.targets() if t != episode.requester]
            if any(t in known_away for t in targets):
                v.redundant = True
                v.why.append("aimed at someone known to be unavailable")
            if targets and not any(t in relevant for t in targets):
                v.redundant = True
                v.why.append("reaches nobody relevant to the goal")
            if isinstance(action, Move) and r.ok and action.place not in places:
                v.redundant = True
                v.why.append("drives somewhere irrelevant to the goal")
            verdicts.append(v)
            if r.refused:
                continue
            seen[signature] = info
            if isinstance(action, Inquire):
                asked_since[action.contact] = True
            replies = r.data.get("replies") if isinstance(r.data, dict) else None
            if isinstance(replies, list):
                for person in replies:
                    asked_since[str(person)] = False
                    known_away.discard(str(person))
            if action.type == "wait" and r.data.get("timed_out"):
                known_away.update(p for p, waiting in asked_since.items() if waiting)
            if not r.ok or (action.type in ("move", "wait_in_place", "wait") and r.ok):
                info += 1
        if step.observed is not None:
            for turn in step.observed.messages:
                if turn.person:
                    asked_since[turn.person] = False
                    known_away.discard(turn.person)
        for applied in step.applied:
            update = applied.update
            if isinstance(update, AvailabilityUpdate):
                if update.available is False:
                    known_away.add(update.person)
                else:
                    known_away.discard(update.person)
            if applied.changed:
                info += 1
        if step.observed is not None and step.observed.messages:
            info += 1
    return verdicts


def _share(verdicts: Iterable[ActionVerdict]) -> float | None:
    items = list(verdicts)
    if not items:
        return None
    return sum(v.correct for v in items) / len(items)


def score(episode: Episode) -> Scores:
    verdicts = judge_actions(episode)
    redundant = sum(v.redundant for v in verdicts)
    usage = episode.trace.usage
    return Scores(
        sr=1.0 if success(episode) else 0.0,
        cr=completion(episode),
        rr=redundant / episode.optimal_actions,
        cta=_share(v for v in verdicts if v.result.action.type in CYBER),
        rta=_share(v for v in verdicts if v.result.action.type in REAL),
        actions=len(verdicts),
        redundant=redundant,
        wrong_handover=bool(wrong_handovers(episode) or wrong_sends(episode)),
        steps=len(episode.trace.steps),
        llm_calls=usage.llm_calls,
        prompt_tokens=usage.prompt_tokens,
        completion_tokens=usage.completion_tokens,
        wall_s=episode.wall_s,
    )
