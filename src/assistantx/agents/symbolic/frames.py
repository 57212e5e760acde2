"""Instruction understanding: free text → a typed task frame, or a clarifying question.

The frame says what to do (the task kinds of docs/task-semantics.md), with which item, whose,
for whom and by whom. Parsing is rule-based over the office's vocabulary (``_lexicon``):

1. the text is split into clauses at sentence ends and at "and"/"then"/commas that start a
   new request ("print my file and take it to Wang" is a print and a hand-on);
2. each clause's mentions (people, items, facilities, task cues, "me"/"my") get roles from
   the words around them by the priority rule table of ``_parties``: "to/for X" →
   recipient, "from X"/"X's" → owner, "by X"/"get X to" → actor;
3. only the objects of the request count (``_objects``): not time phrases ("over lunch"),
   purpose clauses ("to read"), modifiers after the object ("a mug for my coffee"), nor
   container words ("a cup of coffee"); every coordinated object ("a stapler and a coffee")
   is a task of its own, with the recipient named next to it;
4. the clause's kind follows from its cues and item kinds (``_kinds``: a rule table for the
   one-task clauses, then a task per object); a clause with no task of its own
   ("and bring it to me", or the answer "Dr. Zhang") fills in the previous task;
5. anything missing, unknown or ambiguous becomes a question for the requester, never a guess,
   and so does an object no task acts on: part of a request is never dropped silently.

Competing readings are kept with their evidence and asked about when they lead to different
physical actions (the idea of KnowNo, "Robots That Ask For Help"): a name that is also an
ordinary word ("Grace Huang, or the grace period talk?"), a request that may be only a
question ("... Shall I bring you one?"), a third person's need said as a fact ("Shall I bring
Gao Min scissors?"). The answer settles the reading (``parse_with_answers``). A thing the
office does not have ("bring me a tape measure") ends unachievable, with a sentence that says so.
"""

from __future__ import annotations

from assistantx.agents.symbolic._kinds import FILE_KINDS, TaskReader
from assistantx.agents.symbolic._lexicon import (
    COMMON,
    PRONOUNS,
    Lexicon,
    Mention,
    Reading,
    Token,
    inflections,
)
from assistantx.agents.symbolic._objects import modifiers, verb_uses
from assistantx.agents.symbolic._parties import (
    Clause,
    Roles,
    UnresolvedPronoun,
    clause_roles,
    prev_word,
)
from assistantx.agents.symbolic.answers import offer_stance
from assistantx.agents.symbolic.planning import describe
from assistantx.agents.symbolic.screen import RequestScreen
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.core.task_schema import SEAL_TOOL as SEAL
from assistantx.core.task_schema import SHAPE_KIND, Evidence, Task, TaskFrame, TaskKind
from assistantx.memory.names import normalize

_KIND_SHAPE = {kind: shape for shape, kind in SHAPE_KIND.items()}

__all__ = ["InstructionParser", "Task", "TaskFrame", "TaskKind"]


_BREAK_WORDS = english.words("clause_breaks")
_JOIN_WORDS = english.words("clause_joins")
_SKIP_AFTER_JOIN = english.words("skip_after_join")


NOT_UNDERSTOOD = (
    "Sorry, I'm not sure what you need. What should I do, with which item, and for whom?"
)
"""The question for a text in which no request was found (not an unclear request)."""


class InstructionParser:
    """Parses instructions against one office."""

    def __init__(self, office: Office) -> None:
        self.office = office
        self.lex = Lexicon.from_office(office)
        self.screen = RequestScreen(office, self.lex)
        self.reader = TaskReader(office)
        self._kinds = self.reader.kinds
        self._printout = self.reader.printout
        self._copy = self.reader.copy
        self._sourced = self.reader.sourced
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
    def parse(self, text: str, requester: str, *, confirmed: bool = False) -> TaskFrame:
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
        frame = self._parse(screened.text, requester)
        if frame.understood:
            frame = self._with_operations(frame, screened.text)
        if frame.question == NOT_UNDERSTOOD:
            unknown = self._unknown_item(screened.text)
            if unknown is not None:
                frame = TaskFrame(requester=requester, decline=unknown)
        said = screened.text.strip()
        evidence = [*screened.evidence, *(self._evidence(t, said) for t in frame.tasks)]
        if frame.understood and screened.confirm and not confirmed:
            what = " and ".join(describe(t, self.office, requester) for t in frame.tasks)
            frame = TaskFrame(requester=requester, question=f"Shall I {what}?")
        return frame.model_copy(update={"hints": screened.hints, "evidence": evidence})

    def _unknown_item(self, text: str) -> str | None:
        """ "bring me a tape measure": a fetch of a thing no one here has, said in words."""
        tokens = self.lex.tokens(text)
        mentions = self.lex.scan(tokens)
        cue = next((m for m in mentions if m.kind == "cue" and set(m.ids) & {"give", "make"}), None)
        if cue is None or any(m.kind in ("item", "facility") for m in mentions):
            return None
        words = [t.word for t in tokens[cue.end :]]
        thing = self.screen._unknown_thing(words)
        if not thing or not all(language.lemmas(w) or language.zipf(w) > 0 for w in thing.split()):
            return None
        return (
            f"Sorry, there is no {thing} in this office that I know of, so I can't get you "
            f"one. {self.screen.capabilities()}"
        )

    def _with_operations(self, frame: TaskFrame, text: str) -> TaskFrame:
        """Name the operation where the office has several of a task's shape ("scan" or
        "copy" a contract); ask which when the words do not say."""
        words = {t.word for t in self.lex.tokens(text)}
        tasks: list[Task] = []
        for t in frame.tasks:
            shape = _KIND_SHAPE.get(t.kind)
            ops = self.office.with_shape(shape) if shape and t.kind != "produce" else []
            if len(ops) > 1 and t.operation is None:
                said = [op for op in ops if self._op_words[op.id] & words]
                if len(said) != 1:
                    names = " or ".join(op.name for op in ops)
                    return TaskFrame(
                        requester=frame.requester, question=f"Which do you mean: {names}?"
                    )
                t = t.model_copy(update={"operation": said[0].id})
            tasks.append(t)
        return frame.model_copy(update={"tasks": tasks})

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

    def _parse(self, text: str, requester: str) -> TaskFrame:
        tokens = self.lex.tokens(text)
        mentions = verb_uses(tokens, self._owned_cue_items(self.lex.scan(tokens), tokens))
        mentions = _settled_by_later_sentence(mentions, _gaps(text, tokens))
        problems = self._problems(tokens, mentions)
        if problems:
            return TaskFrame(requester=requester, question=problems[0])
        tasks: list[Task] = []
        last_person: list[str] = []
        objects: list[Mention] = []
        previous_cues = True
        clauses = self._clauses(tokens, text, mentions)
        answered: set[int] = set()  # clauses that only named whom a pronoun meant
        for k, clause in enumerate(clauses):
            if k in answered:
                continue
            try:
                roles = clause_roles(tokens, clause, requester, last_person)
            except UnresolvedPronoun as exc:
                later = _named_later(clauses, k + 1)
                if later is None:
                    unclear = f"Who do you mean by {exc.args[0]!r}? Please tell me their name."
                    return TaskFrame(requester=requester, question=unclear)
                # "bring me his stapler. Zhang Wei": the answer names him
                answered.add(later[0])
                roles = clause_roles(tokens, clause, requester, [*last_person, later[1]])
            objects += clause.objects()
            made = self.reader.tasks(clause, roles, requester, tasks[-1] if tasks else None)
            made = _to_each(made, roles)
            if made and tasks and not previous_cues and self._refers_back(clause):
                tasks.pop()  # "my lunch is in the fridge, please heat it up": context only
            previous_cues = bool(clause.cues)
            if made:
                tasks = [*_without_subsumed(tasks, made), *made]
            elif tasks:
                tasks[-1] = self.reader.fill(tasks[-1], roles, requester)
        question = self._uncovered(objects, tasks) or self._check(tasks, requester)
        return TaskFrame(
            requester=requester, tasks=tasks if question is None else [], question=question
        )

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
            chosen = self._chosen_reading(text, answer)
            if chosen:
                self.lex.chosen = chosen
                try:
                    frame = self.parse(text, requester)
                finally:
                    self.lex.chosen = {}
                continue
            asked_everything = frame.question == NOT_UNDERSTOOD
            combined = self.parse(f"{text}. {answer}", requester)
            if combined.understood or not asked_everything:
                frame = combined
                continue
            alone = self.parse(answer, requester)
            frame = alone if alone.understood else combined
        return frame

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

    @staticmethod
    def _refers_back(clause: Clause) -> bool:
        return any(m.kind == "pronoun" and not m.possessive for m in clause.mentions) and not any(
            m.kind == "item" for m in clause.mentions
        )

    def _owned_cue_items(self, mentions: list[Mention], tokens: list[Token]) -> list[Mention]:
        """ "Fang's seal", "my stamp": a task word after a possessive names an item."""
        out = list(mentions)
        for n in range(1, len(out)):
            m, before = out[n], out[n - 1]
            word = tokens[m.start].word
            if m.kind == "cue" and word in self.lex.items and before.possessive:
                out[n] = Mention("item", m.start, m.end, (self.lex.items[word],), False, m.text)
        return out

    # -- clauses -------------------------------------------------------------------------
    def _clauses(self, tokens: list[Token], text: str, mentions: list[Mention]) -> list[Clause]:
        gaps = _gaps(text, tokens)
        clauses: list[Clause] = [Clause([])]
        for n, m in enumerate(mentions):
            word = tokens[m.start].word
            gap = gaps[m.start]
            spaced_dash = gap.strip() in ("-", "–", "—", "--") and gap != gap.strip()
            hard = (any(c in gap for c in ".!?;") or spaced_dash) and bool(clauses[-1].mentions)
            soft = (word in _BREAK_WORDS or word in _JOIN_WORDS or "," in gaps[m.start]) and (
                self._starts_request(
                    mentions, n + (1 if word in _JOIN_WORDS | _BREAK_WORDS else 0), tokens
                )
            )
            if (hard or soft) and clauses[-1].mentions:
                clauses.append(Clause([]))
            if m.kind == "word" and (word in _JOIN_WORDS or word in _BREAK_WORDS):
                continue
            clauses[-1].mentions.append(m)
        for c in clauses:
            c.modifiers = modifiers(tokens, c.mentions, self._sourced)
            c.cues = {
                k
                for m in c.mentions
                if m.kind == "cue" and m.start not in c.modifiers
                for k in m.ids
            }
        return [c for c in clauses if c.mentions]

    @staticmethod
    def _starts_request(mentions: list[Mention], n: int, tokens: list[Token]) -> bool:
        while n < len(mentions) and tokens[mentions[n].start].word in _SKIP_AFTER_JOIN:
            n += 1
        return n < len(mentions) and mentions[n].kind == "cue"

    def _unsupported_facility(self, facility_id: str) -> bool:
        """A facility whose operations are none the assistant can run (a meeting room)."""
        ops = self.office.facility(facility_id).operations
        return bool(ops) and not any(self.office.runnable(op) for op in ops)

    # -- checks --------------------------------------------------------------------------
    def _problems(self, tokens: list[Token], mentions: list[Mention]) -> list[str]:
        out: list[str] = []
        for n, m in enumerate(mentions):
            if m.kind == "person" and m.alternative and len(m.ids) == 1:
                name = self.office.person(m.id).name
                out.append(f"Do you mean {name}, or {m.alternative}?")
            if m.kind == "person" and len(m.ids) > 1:
                names = " or ".join(self.office.person(i).name for i in m.ids)
                said = m.text.replace("’", "'").removesuffix("'s").removesuffix("'")
                out.append(f"Who do you mean by {said!r}: {names}?")
            if m.kind == "word" and self._unknown_name(tokens, mentions, n):
                name = m.text.replace("’", "'").removesuffix("'s").removesuffix("'")
                out.append(f"I don't know anyone called {name!r} in this office. Who do you mean?")
            if m.kind == "facility" and self._unsupported_facility(m.id):
                f = self.office.facility(m.id)
                out.append(
                    f"Sorry, I can't help with the {f.name}. I can fetch and deliver things, "
                    "pass on files, and run errands at the office machines. What would you "
                    "like me to do?"
                )
        return out

    def _unknown_name(self, tokens: list[Token], mentions: list[Mention], n: int) -> bool:
        m = mentions[n]
        word = tokens[m.start].word
        if word in COMMON or word in PRONOUNS or word.isdigit() or len(word) < 2:
            return False
        if language.is_month(word) or language.is_weekday(word):
            return False  # "from March", "by Friday": a date
        following = mentions[n + 1] if n + 1 < len(mentions) else None
        if m.possessive and following is not None and following.kind == "item":
            return True  # "Smith's stapler"
        prev = prev_word(tokens, m.start, skip_titles=False)
        capital = m.text[:1].isupper() and m.start > 0
        titled = prev in ("dr", "mr", "mrs", "ms", "prof", "professor", "doctor")
        return capital and (titled or prev in ("to", "for", "from", "by", "ask"))

    def _uncovered(self, objects: list[Mention], tasks: list[Task]) -> str | None:
        """An object of the request that no task acts on: ask, never drop part of a request."""
        if not tasks:
            return None  # ``_check`` asks what is needed at all
        for m in objects:
            if not any(self._covers(t, m.id) for t in tasks):
                return (
                    f"Sorry, I'm not sure what you want me to do with the "
                    f"{self._item_name(m.id)}. Could you tell me?"
                )
        return None

    def _covers(self, task: Task, type_id: str) -> bool:
        """Whether ``task`` acts on an item of ``type_id`` (as its item, source or product)."""
        if task.item == type_id:
            return True
        if task.kind in FILE_KINDS and self._kinds[type_id] in ("electronic", "personal"):
            return True  # "print my report", "email my contract"
        return (task.kind, type_id) in {
            ("print", self._printout),
            ("copy", self._copy),
            ("seal", SEAL),
        }

    def _check(self, tasks: list[Task], requester: str) -> str | None:
        if not tasks:
            return NOT_UNDERSTOOD
        for t in tasks:
            name = self._item_name(t.item) if t.item else "item"
            if t.item is None:
                return f"Which item do you mean for the {t.kind.replace('_', ' ')} request?"
            if t.kind in ("sign",) and (t.actor is None or t.actor == requester):
                return f"Who should do that with your {name}? Please tell me their name."
            if t.kind == "transfer":
                if t.owner is None and self._kinds[t.item] == "personal":
                    return f"Whose {name} do you mean?"
                kept = t.owner is not None and self.office.keeper(t.owner, t.item) is not None
                if t.owner is not None and t.owner == t.recipient and not kept:
                    who = "you" if t.owner == requester else self.office.person(t.owner).name
                    return (
                        f"Who should get {who}r {name}?"
                        if who == "you"
                        else (f"{who} already has their {name}; who should get it?")
                    )
            if t.kind == "send_file" and t.owner == t.recipient:
                return "Who should I pass your file on to?"
        return None

    def _item_name(self, type_id: str) -> str:
        return self.office.item_type(type_id).name


def _settled_by_later_sentence(mentions: list[Mention], gaps: list[str]) -> list[Mention]:
    """ "Bring me Zhnag's stapler. Zhang Wei": a later sentence that names one of the people
    an ambiguous name may mean settles it (the answer to "who do you mean?"), and is used up."""
    out = list(mentions)
    used: set[int] = set()
    for n, m in enumerate(out):
        if m.kind != "person" or len(m.ids) < 2:
            continue
        for k in range(n + 1, len(out)):
            later = out[k]
            new_sentence = any(c in gap for gap in gaps[m.end : later.start + 1] for c in ".!?;")
            if later.kind == "person" and len(later.ids) == 1 and later.id in m.ids:
                if new_sentence:
                    out[n] = Mention("person", m.start, m.end, later.ids, m.possessive, m.text)
                    used.add(k)
                break
    return [m for k, m in enumerate(out) if k not in used]


def _named_later(clauses: list[Clause], first: int) -> tuple[int, str] | None:
    """A clause from ``first`` on that only names one person (an answer like "Zhang Wei" or
    "I mean Wang"): its index and the person."""
    for k in range(first, len(clauses)):
        clause = clauses[k]
        people = {m.ids for m in clause.mentions if m.kind == "person"}
        if clause.cues or any(m.kind in ("item", "facility") for m in clause.mentions):
            continue
        if len(people) == 1 and len(next(iter(people))) == 1:
            return k, next(iter(people))[0]
    return None


def _gaps(text: str, tokens: list[Token]) -> list[str]:
    """The characters between each token and the one before it (punctuation)."""
    from assistantx.memory.names import TITLES

    gaps: list[str] = []
    pos = 0
    prev_title = False
    flat = text.replace("’", "'")
    for t in tokens:
        at = flat.find(t.text, pos)
        gap = flat[pos:at] if at >= 0 else ""
        if gaps and prev_title:  # "Dr. Zhang": the title's full stop ends no sentence
            gap = gap.replace(".", "", 1)
        gaps.append(gap)
        pos = at + len(t.text) if at >= 0 else pos
        prev_title = t.word in TITLES
    return gaps


def _without_subsumed(earlier: list[Task], made: list[Task]) -> list[Task]:
    """ "Tomás needs a clipboard, give him Rich's": the need and the later request are one
    errand; an earlier clause's fetch of anyone's item is dropped when a later clause fetches
    the same kind of item for the same person and says whose."""
    specific = {(t.item, t.recipient) for t in made if t.kind == "transfer" and t.owner}
    return [
        t
        for t in earlier
        if not (t.kind == "transfer" and t.owner is None and (t.item, t.recipient) in specific)
    ]


def _to_each(made: list[Task], roles: Roles) -> list[Task]:
    """ "send my rota to Hal and to Dawn", "... to Hal and Dawn": a file goes to each person
    named as a recipient (a copy costs nothing; one physical item could not)."""
    if len(made) != 1 or made[0].kind != "send_file" or not roles.recipient:
        return made
    people = list(dict.fromkeys([*roles.recipient, *roles.bare]))
    if len(people) < 2:
        return made
    return [made[0].model_copy(update={"recipient": who}) for who in people]
