"""The reader: free text → a typed task frame, or a clarifying question, by stages that pass
forward.

The frame says what to do (the task kinds of docs/task-semantics.md), with which item, whose,
for whom and by whom. Each stage takes the previous stage's immutable output and returns its
own; none reaches back into an earlier one:

0. ``screen``: the speech acts and sanity checks of the raw text, piece by piece (a
   withdrawal, a thanks, a wish, a question, a fact, something destructive or not offered is
   answered or declined here, before any task is read); what is left is the request;
1. ``tokens``: the request's words (Unicode), with their punctuation;
2. ``lexicon``: typos corrected against the office's words, and the mentions of its people,
   items, facilities, places and task words (``Lexed``);
3. ``readings``: the mentions read in their sentences, and the first doubt left (a name that
   may be a word, a name several people share) (``Readings``);
4. ``frames``: clauses, roles and task kinds → the tasks, or the question still open;
5. here: the office's operation named where several share a shape, an unknown item said as
   such, a third person's need restated and asked ("Shall I ...?").

Competing readings are kept with their evidence and asked about when they lead to different
physical actions (the idea of KnowNo, "Robots That Ask For Help"): a name that is also an
ordinary word ("Grace Huang, or the grace period talk?"), a request that may be only a
question ("... Shall I bring you one?"), a third person's need said as a fact ("Shall I bring
Gao Min scissors?"). The answer settles the reading (``parse_with_answers``). A thing the
office does not have ("bring me a tape measure") ends unachievable, with a sentence that says so.
"""

from __future__ import annotations

import copy
import dataclasses
import re
from collections.abc import Sequence

from assistantx.agents.symbolic.answers import offer_stance
from assistantx.agents.symbolic.planning import describe
from assistantx.agents.symbolic.reading._objects import REASON_CONJUNCTIONS, modifiers
from assistantx.agents.symbolic.reading.destination import Outside
from assistantx.agents.symbolic.reading.frames import (
    NOT_UNDERSTOOD,
    FrameReader,
    holder,
    named_items,
)
from assistantx.agents.symbolic.reading.lexicon import (
    COMMON,
    Lexed,
    Lexicon,
    Mention,
    Reading,
    inflections,
)
from assistantx.agents.symbolic.reading.readings import MentionReader
from assistantx.agents.symbolic.reading.screen import RequestScreen
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office, Operation
from assistantx.core.task_schema import SHAPE_KIND, Evidence, Task, TaskFrame, TaskKind
from assistantx.memory.names import normalize

_KIND_SHAPE = {kind: shape for shape, kind in SHAPE_KIND.items()}
_WHERE_TO = "Where should I "  # the question for a send-out service's place outside
# The question when a send-out service's destination is a colleague's name.
_OUT_OR_IN = "Should I send it out by "
# The words of an answer to it that choose the hand-over inside the office.
_INSIDE_WORDS = frozenset(
    {"bring", "hand", "give", "take", "deliver", "desk", "him", "her", "them", "here", "inside"}
)
# The words of the phrases that point back to an item named before ("another", "a few more").
_BACK_WORDS = english.words("another_one")
# Words that end the name of a thing asked for: a reason, a courtesy ("a dispatcher please").
_THING_ENDS = REASON_CONJUNCTIONS | english.words("polite") | {"as"}

__all__ = ["NOT_UNDERSTOOD", "InstructionParser", "Task", "TaskFrame", "TaskKind"]


class InstructionParser:
    """Parses instructions against one office."""

    def __init__(self, office: Office) -> None:
        self.office = office
        self.lex = Lexicon.from_office(office)
        self.screen = RequestScreen(office, self.lex)
        self.readings = MentionReader(office, self.lex)
        self.frames = FrameReader(office)
        self._op_words = {
            op.id: {
                form
                for phrase in (*op.verbs, op.name)
                for verb in normalize(phrase).split()[:1]
                for form in inflections(verb)
            }
            for op in office.operations
        }

    # -- public --------------------------------------------------------------------------
    def parse(
        self, text: str, requester: str, *, confirmed: bool = False, sent_out: bool = False
    ) -> TaskFrame:
        """The frame of a request: screened first (speech acts, withdrawn, negated,
        destructive, facts, unsupported services; ``screen``), then the tasks read from what
        is left. ``confirmed``: the requester already said yes to the restated reading."""
        screened = self.screen.screen(text, requester)
        if screened.decline is not None:
            return TaskFrame(
                requester=requester,
                decline=screened.decline,
                decline_outcome=screened.outcome,
                hints=screened.hints,
                evidence=screened.evidence,
            )
        if screened.question is not None:
            return TaskFrame(
                requester=requester,
                question=screened.question,
                hints=screened.hints,
                evidence=screened.evidence,
            )
        lexed = self.lex.read(screened.text)  # stages 1 and 2, once; later ones get it
        # who has an item now is said anywhere, also in a statement the screen set aside
        # ("P lent me her ruler. Please return it to her; it's on my desk")
        whole = self.lex.read(text) if text != screened.text else lexed
        readings = self.readings.read(lexed)
        frame = self.frames.frame(
            readings, requester, holder(whole, requester), named_items(whole, requester)
        )
        if frame.understood:
            frame = self._with_operations(frame, lexed, readings.outside, sent_out=sent_out)
        if frame.question == NOT_UNDERSTOOD:
            unknown = self._unknown_item(readings.tokens, readings.mentions)
            if unknown is not None:
                frame = TaskFrame(requester=requester, decline=unknown)
        said = screened.text.strip()
        evidence = [*screened.evidence, *(self._evidence(t, said) for t in frame.tasks)]
        if frame.understood and screened.confirm and not confirmed:
            what = " and ".join(describe(t, self.office, requester) for t in frame.tasks)
            frame = TaskFrame(requester=requester, question=f"Shall I {what}?")
        return frame.model_copy(update={"hints": screened.hints, "evidence": evidence})

    def _unknown_item(self, tokens: Sequence[Token], mentions: Sequence[Mention]) -> str | None:
        """ "bring me a tape measure": a fetch of a thing no one here has, said in words."""
        cue = next((m for m in mentions if m.kind == "cue" and set(m.ids) & {"give", "make"}), None)
        context = modifiers(tokens, mentions)  # "... because my headlamp is dying"
        if cue is None or any(m.kind == "item" and m.start not in context for m in mentions):
            return None
        if any(m.kind == "facility" for m in mentions):
            return None
        words = [t.word for t in tokens[cue.end :]]
        # the thing ends where a reason starts: "a power bank as my headlamp is dying"
        ends = [n for n, w in enumerate(words) if w in _THING_ENDS]
        words = words[: ends[0]] if ends else words
        thing = self.screen.unknown_thing(words)
        if thing and set(thing.split()) <= _BACK_WORDS:
            return None  # "bring me a few": how many of something not named, so ask what
        if not thing or not all(language.lemmas(w) or language.zipf(w) > 0 for w in thing.split()):
            return None
        return (
            f"Sorry, there is no {thing} in this office that I know of, so I can't get you "
            f"one. {self.screen.capabilities()}"
        )

    def _with_operations(
        self, frame: TaskFrame, lexed: Lexed, outside: Outside | None, *, sent_out: bool = False
    ) -> TaskFrame:
        """Name the operation where the office has several of a task's shape ("scan" or
        "copy" a contract); ask which when the words do not say."""
        words = {t.word for t in lexed.tokens}
        facility_ops = {
            op
            for m in lexed.mentions
            if m.kind == "facility"
            for op in self.office.facility(m.ids[0]).operations
        }
        products = {i for m in lexed.mentions if m.kind == "item" for i in m.ids}
        tasks: list[Task] = []
        for t in frame.tasks:
            t, which = self._one_of_several(t, words, facility_ops, products)
            if which is not None:
                return TaskFrame(requester=frame.requester, question=which)
            shape = _KIND_SHAPE.get(t.kind)
            ops = self.office.with_shape(shape) if shape and t.kind != "produce" else []
            if shape == "treat" and ops and t.item is not None and t.operation is None:
                # the service asked for by its verb, else at the facility named, else any
                asked = [op for op in ops if self._op_words[op.id] & words] or [
                    op for op in ops if op.id in facility_ops
                ]
                asked = asked or ops
                fits = [op for op in asked if op.input == t.item]
                if not fits:  # "charge my radio" where only headlamps are charged
                    return TaskFrame(
                        requester=frame.requester, decline=self._cannot_treat(asked, t.item)
                    )
                if len(fits) == 1 and len(ops) > 1:  # named where several share the shape
                    t = t.model_copy(update={"operation": fits[0].id})
                ops = fits
            if len(ops) > 1 and t.operation is None:
                said = [op for op in ops if self._op_words[op.id] & words]
                if not said:  # "put my contract in the scanner": the facility's own service
                    said = [op for op in ops if op.id in facility_ops]
                if len(said) != 1:
                    names = " or ".join(op.name for op in ops)
                    return TaskFrame(
                        requester=frame.requester, question=f"Which do you mean: {names}?"
                    )
                t = t.model_copy(update={"operation": said[0].id})
            op_id = t.operation or (ops[0].id if len(ops) == 1 else None)
            op = self.office.operation(op_id) if op_id else None
            if op is not None and op.sends_out and t.destination is None:
                # a fax leaves the office: where to is the requester's to say, never a guess;
                # the readings stage found the words ("send out my drawing to the client")
                where = outside.phrase if outside is not None else None
                if where is None:
                    return TaskFrame(
                        requester=frame.requester,
                        question=f"{_WHERE_TO}{op.name} it to? Please give the number "
                        "or the name of the place.",
                    )
                colleague = self._colleague(where) if not sent_out else None
                if colleague is not None:
                    # "courier my plan to Bill" where Bill works here: sending it out of the
                    # office and handing it to him are different physical actions; ask
                    name = self.office.person(colleague).name
                    return TaskFrame(
                        requester=frame.requester,
                        question=f"{_OUT_OR_IN}{op.name} to {where} outside the office, "
                        f"or bring it to {name} here?",
                    )
                t = t.model_copy(update={"operation": op.id, "destination": where})
            tasks.append(t)
        return frame.model_copy(update={"tasks": tasks})

    def _one_of_several(
        self, task: Task, words: set[str], facility_ops: set[str], products: set[str]
    ) -> tuple[Task, str | None]:
        """The operation a task on an item runs, where a machine does several: the one whose
        verb or gerund is said ("needs binding", "through the copier to scan it"), whatever
        shape the rest of the clause suggested; with none said and the machine named doing
        several to this item, the question which ("Which do you mean: copy, scan or bind?")."""
        if task.item is None or task.operation is not None or task.kind not in _KIND_SHAPE:
            return task, None
        fits = [
            op
            for op in self.office.operations
            if op.input == task.item and self.office.runnable(op.id) and not op.sends_out
        ]
        said = [op for op in fits if self._op_words[op.id] & words]
        # "scan my contract to PDF", "send my plan to PDF": the product named says which
        said = said or [op for op in fits if op.product in products]
        if len(said) == 1:
            shape = said[0].shape(self.office)
            kind = SHAPE_KIND.get(shape)
            # only where the clause read another shape, or several share this one: a lone
            # operation of its shape is left to the plain reading
            if kind is not None and (kind != task.kind or len(self.office.with_shape(shape)) > 1):
                return task.model_copy(update={"kind": kind, "operation": said[0].id}), None
        at_machine = [op for op in fits if op.id in facility_ops]
        if not said and len(at_machine) > 1:
            names = [op.name for op in at_machine]
            listed = ", ".join(names[:-1]) + " or " + names[-1]
            return task, f"Which do you mean: {listed}?"
        return task, None

    def _cannot_treat(self, ops: list[Operation], item: str) -> str:
        """Why a service the office offers cannot be run on this item, with what it is for."""
        asked = " or ".join(dict.fromkeys(op.name for op in ops))
        thing = self._item_name(item)
        fits = [
            f"{op.name} {language.plural(self._item_name(op.input))}"
            for op in ops
            if op.input is not None
        ]
        return (
            f"Sorry, I can't {asked} {_article(thing)} {thing} here: I can only "
            f"{' and '.join(fits)}."
        )

    def _evidence(self, task: Task, said: str) -> Evidence:
        """A task in words: what it does, with whose item, for whom."""
        name = self._item_name(task.item) if task.item else "item"
        whose = (
            f"{self.office.person(task.owner).name}'s {name}"
            if task.owner
            else f"anyone's {name}"
            if task.kind == "transfer"
            else name
        )
        parts = [f"{task.kind.replace('_', ' ')}: {whose}"]
        if task.actor:
            parts.append(f"by {self.office.person(task.actor).name}")
        parts.append(f"for {self.office.person(task.recipient).name}")
        return Evidence(words=said[:300], meaning=" ".join(parts))

    def parse_with_answers(self, text: str, requester: str, answers: list[str]) -> TaskFrame:
        """Re-parse after clarifying answers: a yes or no to "Shall I ...?", the reading the
        answer chose, else the original with the answers; the answer alone only when the
        question asked for the whole request. A reply answers the question asked: it never
        starts a request of its own ("Yes, I have a stapler" to "Shall I bring you one?" is
        a no, not a yes nor a new request for a stapler)."""
        frame = self.parse(text, requester)
        for answer in answers:
            if frame.understood or frame.decline is not None:
                break
            if frame.question is not None and frame.question.startswith(_OUT_OR_IN):
                frame = self._out_or_in(text, requester, answer, frame)
                continue
            if frame.question is not None and "Shall I" in frame.question:
                yes_no = offer_stance(answer)
                if yes_no == "yes":
                    offer = self.screen.screen(text, requester).offer
                    frame = self.parse(offer or text, requester, confirmed=True)
                    continue
                if yes_no == "no":
                    return TaskFrame(
                        requester=requester,
                        decline="OK, I won't do anything, then.",
                        decline_outcome="done",
                    )
            if frame.question is not None and frame.question.startswith(_WHERE_TO):
                # the answer is the place outside ("the client", "to our lawyers"): read as
                # the request's own "to ...", by the same stage, not as a new request
                place = re.sub(r"^\s*to\s+", "", answer.strip(), flags=re.IGNORECASE)
                frame = self.parse(f"{text.rstrip(' .!?')} to {place}", requester)
                continue
            chosen = self._chosen_reading(text, answer)
            if chosen:
                frame = self._choosing(chosen).parse(text, requester)
                continue
            asked_everything = frame.question == NOT_UNDERSTOOD
            combined = self.parse(f"{text}. {answer}", requester)
            if combined.understood or not asked_everything:
                frame = combined
                continue
            alone = self.parse(answer, requester)
            frame = alone if alone.understood else combined
        return frame

    def _colleague(self, where: str) -> str | None:
        """The one colleague a send-out destination names and nothing else ("Bill", "Bill
        Osei"), None for a place outside ("the county land registry")."""
        tokens = self.lex.tokens(where)
        mentions = [m for m in self.lex.scan(tokens) if m.kind != "word"]
        if len(mentions) != 1 or mentions[0].kind != "person" or len(mentions[0].ids) != 1:
            return None
        rest = [t.word for t in tokens[: mentions[0].start]] + [
            t.word for t in tokens[mentions[0].end :]
        ]
        return mentions[0].ids[0] if set(rest) <= COMMON else None

    def _out_or_in(self, text: str, requester: str, answer: str, asked: TaskFrame) -> TaskFrame:
        """The answer to "send it out by courier to Bill, or bring it to Bill here?": the
        operation's verb or "out" sends it out as written; a hand-over word or the colleague's
        name brings it to them instead; anything else leaves the question open."""
        out = self.parse(text, requester, sent_out=True)
        words = {t.word for t in self.lex.tokens(answer)}
        verbs = {w for op in self.office.operations if op.sends_out for w in self._op_words[op.id]}
        if words & (verbs | {"out", "outside"}):
            return out
        named = {i for m in self.lex.scan(self.lex.tokens(answer)) for i in m.ids}
        sent = [t for t in out.tasks if t.destination is not None]
        if not sent:
            return asked
        colleague = self._colleague(sent[0].destination or "")
        if colleague is None or not (words & _INSIDE_WORDS or colleague in named):
            return asked
        inside = [
            t.model_copy(
                update={
                    "kind": "transfer",
                    "operation": None,
                    "destination": None,
                    "recipient": colleague,
                }
            )
            if t.destination is not None
            else t
            for t in out.tasks
        ]
        return out.model_copy(update={"tasks": inside})

    def _choosing(self, chosen: dict[str, Reading]) -> InstructionParser:
        """The same stages, with a lexicon that reads the name words the requester was asked
        about as they answered (nothing of this parser changes)."""
        other = copy.copy(self)
        other.lex = dataclasses.replace(self.lex, chosen=chosen)
        other.screen = RequestScreen(self.office, other.lex)
        other.readings = MentionReader(self.office, other.lex)
        return other

    def _chosen_reading(self, text: str, answer: str) -> dict[str, Reading]:
        """Which reading an answer chose for a name that may be a word: it names the person,
        or it repeats the word's phrase ("the talk", "the grace period one")."""
        tokens = self.lex.tokens(text)
        said = self.lex.tokens(answer)
        named = {i for m in self.lex.scan(said) if m.kind == "person" for i in m.ids}
        answer_words = {t.word for t in said} - COMMON
        chosen: dict[str, Reading] = {}
        for m in self.lex.scan(tokens):
            if m.kind != "person" or not m.alternative:
                continue
            word = tokens[m.start].word
            full = {language.fold(w) for i in m.ids for w in self.office.person(i).name.split()}
            if set(m.ids) & named and (answer_words & full) - {word}:
                chosen[word] = "person"  # "Grace Huang"
            elif answer_words & {language.fold(w) for w in m.alternative.split()}:
                chosen[word] = "word"  # "the grace period talk", "the talk"
            elif set(m.ids) & named:
                chosen[word] = "person"
        return chosen

    def _item_name(self, type_id: str) -> str:
        return self.office.item_type(type_id).name


def _article(noun: str) -> str:
    return "an" if noun[:1].lower() in "aeiou" else "a"
