"""Decision: the next action(s) for the first unmet sub-goal.

- An unclear request: ask the requester and wait (at most ``MAX_CLARIFICATIONS`` times).
- Confirm: ask the best candidate and wait; wait on a pending answer; ask the group chat when
  every known candidate is out.
- Forward: pass the file on.
- Handover: tell the person first if they were never told why the robot comes, drive there,
  send each missing one-time code (a code is never sent twice), then wait in place.
- Nothing left: stop, telling the requester what was done and what could not be done, why.
"""

from __future__ import annotations

from assistantx.agents.symbolic.evidence import Evidence
from assistantx.agents.symbolic.owner_notice import owner_notice, told
from assistantx.agents.symbolic.planning import (
    Agenda,
    Confirm,
    Forward,
    Handover,
    PhaseView,
    TaskView,
    describe,
    role_text,
)
from assistantx.agents.symbolic.roles import Role, Roles, RoleState
from assistantx.core import task_kinds
from assistantx.core.actions import (
    Action,
    ForwardFile,
    Inform,
    Inquire,
    Move,
    SendQR,
    Stop,
    Wait,
    WaitInPlace,
)
from assistantx.core.office import Office
from assistantx.core.task_schema import FALLBACK_MEANING, operation_of
from assistantx.core.wording import (
    done_words,
    file_noun,
    is_are,
    item_phrase,
    person_name,
    place_name,
)

MAX_ACTIONS = 4
MAX_CLARIFICATIONS = 3  # questions to the requester in all (one re-ask of each)
REPLY_TIMEOUT_S = 60.0
CLARIFY_TIMEOUT_S = 300.0
HANDOVER_TIMEOUT_S = 300.0


class Decider:
    def __init__(self, office: Office, roles: Roles) -> None:
        self.office = office
        self.roles = roles

    def _name(self, person: str) -> str:
        return self.office.person(person).name

    # -- clarification -------------------------------------------------------------------
    def clarify(self, question: str, ev: Evidence, request: str) -> tuple[str, list[Action]]:
        """Ask the requester what is unclear; re-ask once (in other words) after an answer that
        did not settle it; then stop ``failed``, telling them what could not be understood."""
        asked = [q for q in ev.questions if q.contact == ev.requester and not q.group]
        if asked and ev.pending(asked[-1]):
            return "waiting for the requester's answer", [
                Wait(reason="waiting for the requester to clarify", timeout_s=CLARIFY_TIMEOUT_S)
            ]
        same = [q for q in asked if q.text == question or q.text.endswith(_plain(question))]
        if len(same) >= 2 or len(asked) >= MAX_CLARIFICATIONS or (asked and ev.expired(asked[-1])):
            return "the request stays unclear", [
                Stop(outcome="failed", summary=self._not_understood(request, question, ev)[:2000])
            ]
        text = f"Sorry, I still don't understand. {_plain(question)}" if same else question
        return "the request is unclear: ask the requester", [
            Inquire(contact=ev.requester, question=text),
            Wait(reason="waiting for the requester to clarify", timeout_s=CLARIFY_TIMEOUT_S),
        ]

    @staticmethod
    def _not_understood(request: str, question: str, ev: Evidence) -> str:
        asked = [q for q in ev.questions if q.contact == ev.requester and not q.group]
        answers = [t.text for q in asked for t in ev.answers(q) if t.person == ev.requester]
        heard = (
            f" Your answer {answers[-1][:200]!r} did not tell me."
            if answers
            else " I got no answer."
        )
        return (
            f"I could not understand your request {request[:300]!r}, so I did nothing. "
            f"What I could not work out: {_plain(question)}{heard} "
            "Please send the request again with that detail."
        )

    # -- the plan ------------------------------------------------------------------------
    def decide(self, agenda: Agenda, ev: Evidence) -> tuple[str, list[Action]]:
        task = agenda.active
        if task is None:
            return self._stop(agenda, ev)
        if task.ask is not None:
            return self._ask_requester(task.ask, ev)
        phase = task.current
        assert phase is not None  # an active task has an unmet phase
        if isinstance(phase.phase, Confirm):
            return self._confirm(task.states[phase.phase.role.key], ev)
        if isinstance(phase.phase, Forward):
            target = phase.person or phase.phase.target_role.fixed or ev.requester
            what = item_phrase(self.office, phase.phase.file)
            return f"forward {what} to {person_name(self.office, target)}", [
                ForwardFile(source=phase.phase.source, target=target, file=phase.phase.file)
            ]
        return self._handover(phase, phase.phase, ev)

    @staticmethod
    def _ask_requester(question: str, ev: Evidence) -> tuple[str, list[Action]]:
        """A question only the requester can settle before the task goes on (``stand_in``):
        asked once, then waited on."""
        wait = Wait(reason="waiting for the requester's answer", timeout_s=CLARIFY_TIMEOUT_S)
        if ev.asked(ev.requester, question) is not None:
            return "waiting for the requester's answer", [wait]
        return "ask the requester", [Inquire(contact=ev.requester, question=question), wait]

    def _confirm(self, state: RoleState, ev: Evidence) -> tuple[str, list[Action]]:
        role = state.role
        if state.status == "ask" and state.person is not None:
            who = state.person
            doing = role_text(role, self.office)
            # an owner asked for their own item: the requester hears so first, once
            notice = owner_notice(self.office, role, who)
            first: list[Action] = (
                [Inform(contact=ev.requester, content=notice)]
                if notice is not None and not told(ev, notice)
                else []
            )
            return f"ask {self._name(who)} (best candidate to {doing})", [
                *first,
                Inquire(contact=who, question=self.roles.question(role, who)),
                Wait(reason=f"waiting for {self._name(who)}'s answer", timeout_s=REPLY_TIMEOUT_S),
            ]
        if state.status == "waiting" and state.person is not None:
            return f"still waiting for {self._name(state.person)}", [
                Wait(
                    reason=f"waiting for {self._name(state.person)}'s answer",
                    timeout_s=REPLY_TIMEOUT_S,
                )
            ]
        if state.status == "group" and state.group is not None:
            doing = role_text(role, self.office)
            group = person_name(self.office, state.group)
            return f"nobody known can {doing}: ask the {group} group", [
                Inquire(contact=state.group, question=self.roles.group_question(role)),
                Wait(reason="waiting for a helper in the group chat", timeout_s=REPLY_TIMEOUT_S),
            ]
        return "waiting for a helper in the group chat", [
            Wait(reason="waiting for a helper in the group chat", timeout_s=REPLY_TIMEOUT_S)
        ]

    def _handover(self, view: PhaseView, phase: Handover, ev: Evidence) -> tuple[str, list[Action]]:
        person, place = view.person, view.place
        # its Confirm phase came first, so the role has a person and a place
        assert person is not None
        assert place is not None
        actions: list[Action] = []
        if not self._told_for(phase.role, person, ev):
            actions.append(Inform(contact=person, content=self.roles.inform(phase.role, person)))
        if ev.robot_place != place:
            actions.append(Move(place=place))
        # a work step names its operation: a facility may offer several (copy and scan)
        op = phase.role.operation if phase.role.operation and phase.role.facility else None
        for item, purpose in view.pending:
            if not ev.holds_code(person, item, purpose):
                work = op if purpose in task_kinds.work_purposes() else None
                dest = phase.role.destination if work else None
                to = phase.role.send_to if work else None
                actions.append(
                    SendQR(
                        contact=person,
                        item=item,
                        purpose=purpose,
                        operation=work,
                        destination=dest,
                        send_to=to,
                    )
                )
        thought = f"hand-over with {self._name(person)} at {place_name(self.office, place)}"
        if any(isinstance(a, Move) for a in actions) and any(q.group for q in ev.questions):
            # Late helpers in a group chat may still write while the robot drives; their
            # message would cut the wait at the locker short, so wait in the next step.
            return thought + "; wait there next step", actions[:MAX_ACTIONS]
        actions.append(WaitInPlace(person=person, timeout_s=HANDOVER_TIMEOUT_S))
        if ev.interrupted_handover(person) and len(actions) == 1:
            thought += " (the last wait was cut short by a message: wait again)"
        return thought, actions[:MAX_ACTIONS]

    def _told_for(self, role: Role, person: str, ev: Evidence) -> bool:
        """Whether ``person`` knows why the robot comes: asked for this role, or informed."""
        if person == ev.requester:
            return True
        if ev.asked(person, self.roles.question(role, person)) is not None:
            return True
        group_text = self.roles.group_question(role)
        for q in ev.questions:
            if q.group and q.text == group_text and any(t.person == person for t in ev.answers(q)):
                return True
        return any(
            t.direction == "out"
            and t.person == person
            and t.text == self.roles.inform(role, person)
            for t in ev.outbound
        )

    # -- the end -------------------------------------------------------------------------
    def _stop(self, agenda: Agenda, ev: Evidence) -> tuple[str, list[Action]]:
        """The end: ``done`` only when every task of the frame is done; otherwise ``failed``
        (something went wrong part-way) or ``unachievable`` (nobody could help), and the
        summary says what was done and what was not, and why."""
        requester = agenda.frame.requester
        done = [t for t in agenda.tasks if t.status == "done"]
        not_done = [t for t in agenda.tasks if t.status != "done"]
        parts: list[str] = []
        if done:
            parts.append("Done: " + "; ".join(self._result(t, agenda) for t in done) + ".")
        if not_done:
            missed = "; ".join(
                f"{describe(t.compiled.task, self.office, requester)} ({t.reason or t.status})"
                for t in not_done
            )
            parts.append(f"Not done: I could not {missed}.")
            if ev.locker:
                kept = ", ".join(self._item_words(i, requester) for i in ev.locker)
                parts.append(f"Still in the robot's locker: {kept}.")
        # a fallback the reading kept back ("..., or if there isn't one, scissors"): never
        # fetched with the first, so the requester is told it was not used
        for said in (
            e.words for e in agenda.frame.evidence if e.meaning.startswith(FALLBACK_MEANING)
        ):
            if not_done:
                parts.append(f'Your fallback ("{said}") was not used; ask me if you want it.')
            else:
                parts.append(f'Your fallback ("{said}") was not needed.')
        summary = " ".join(parts)[:2000] or "Nothing to do."
        if not not_done:
            return "every task is done", [Stop(outcome="done", summary=summary)]
        if all(t.status == "unachievable" for t in not_done):
            why = "nobody could help with part of it" if done else "nobody could help"
            return why, [Stop(outcome="unachievable", summary=summary)]
        return "a task failed part-way", [Stop(outcome="failed", summary=summary)]

    def _item_words(self, item: str, requester: str) -> str:
        """``stapler:wang`` → "Wang Fang's stapler" ("your stapler" for the requester)."""
        type_id, _, owner = item.partition(":")
        name = self.office.item_type(type_id).name
        if owner == requester:
            return f"your {name}"
        if self.office.is_supply(item):
            return item_phrase(self.office, item)
        return f"{self._name(owner)}'s {name}" if owner else name

    def _result(self, view: TaskView, agenda: Agenda) -> str:
        """What is now true, in words, naming who holds what."""
        task = view.compiled.task
        requester = agenda.frame.requester

        def who(person: str | None) -> str:
            if person is None:
                return "someone"
            return "you" if person == requester else person_name(self.office, person)

        def whose(person: str | None) -> str:
            return "your" if person == requester else f"{who(person)}'s"

        kind_of = self.office.item_type(task.item) if task.item else None
        item = kind_of.name if kind_of else "item"
        # "your clippers were sharpened", "your tape was cut": the verb agrees with the item
        was = "was" if kind_of is None or is_are(item, mass=kind_of.mass) == "is" else "were"

        def whose_item(person: str | None) -> str:
            if person is not None and task.item and self.office.is_supply(f"{task.item}:{person}"):
                return item_phrase(self.office, f"{task.item}:{person}")  # owned by nobody
            return f"{whose(person)} {item}"

        helpers = [
            s.person
            for s in view.states.values()
            if s.bound and s.person != requester and s.role.kind != "receive"
        ]
        by = (
            f" (thanks to {', '.join(who(p) for p in dict.fromkeys(helpers) if p)})"
            if helpers
            else ""
        )
        collected = [i for p in view.phases for i, purpose in p.items if purpose == "collect"]
        owner = collected[0].split(":", 1)[1] if collected else task.owner
        if task.kind != "transfer":
            owner = task.owner
        # what was made: the collected thing that is not the item worked on (a copy handed to
        # a colleague after the original went back to the requester)
        made = next(
            (
                t
                for i in collected
                if (t := i.partition(":")[0]) != task.item and i.partition(":")[2]
            ),
            "",
        )
        op_id = operation_of(self.office, task)
        op = self.office.operation(op_id) if op_id else None
        spec = task_kinds.kind(task.kind)
        template = spec.done
        if spec.done_elsewhere and task.recipient not in (None, requester):
            template = spec.done_elsewhere  # the copy to a colleague, the original back
        product = op.product if op is not None else None
        if product and self.office.item_type(product).electronic and spec.done_file:
            template, made = spec.done_file, product  # scanned to PDF: the file was sent
        if op is not None and not op.returns_item and spec.done_consumed:
            template = spec.done_consumed  # nothing was handed back
            if op.sends_out and task.destination and spec.done_sent:
                template = spec.done_sent  # "your form was faxed to the tax office"
        said_whose = whose_item(owner)
        if task.kind == "transfer" and owner not in (None, requester) and owner == task.recipient:
            # a thing given back: "Wang Fang now has their stapler back", not "... has Wang
            # Fang's stapler"
            said_whose = f"their {item} back"
        text = template.format(
            to=who(task.recipient),
            have="have" if task.recipient == requester else "has",
            whose=said_whose,
            owner_s=whose(task.owner),
            file=file_noun(self.office),
            item=item,
            product=self.office.item_type(made).name if made else "result",
            by=who(task.actor),
            done=done_words(op) if op else task.kind,
            was=was,
            dest=task.destination or "",
            back=who(task.owner or requester),  # whoever put the original in gets it back
        )
        return text + by


def _plain(question: str) -> str:
    """The question without its opening apology, to quote it inside another sentence."""
    rest = question.removeprefix("Sorry, ")
    return rest[:1].upper() + rest[1:]
