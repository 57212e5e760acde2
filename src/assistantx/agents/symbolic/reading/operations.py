"""After the frames: the office's operation named where several share a task's shape ("scan"
or "copy" a contract), asked about when the words do not say which, declined when none fits
the item ("charge my radio" where only headlamps are charged), and a send-out service's place
outside taken from the readings ("send out my drawing to the client") or asked for."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.asking_forms import done_forms
from assistantx.agents.symbolic.reading.bare_place import bare_common_noun, needs_address
from assistantx.agents.symbolic.reading.destination import (
    Outside,
    means_words,
    named_after,
    names_no_place,
    only_describes,
)
from assistantx.agents.symbolic.reading.destination_detail import detail_in_message, naming_words
from assistantx.agents.symbolic.reading.lexicon import (
    COMMON,
    Lexed,
    describing_participles,
    inflections,
)
from assistantx.agents.symbolic.reading.made_into import made_products
from assistantx.agents.symbolic.reading.role_destination import names_only_a_role
from assistantx.agents.symbolic.reading.size_words import facility_sizes, sized_facility
from assistantx.agents.symbolic.reading.tokens import gaps
from assistantx.agents.symbolic.reading.verb_phrases import VerbPhrases
from assistantx.core import english, language
from assistantx.core.office import Office, Operation
from assistantx.core.task_schema import SHAPE_KIND, Task, TaskFrame
from assistantx.core.wording import a_thing, by_means, verb_alone, verb_it
from assistantx.memory.names import normalize

_KIND_SHAPE = {kind: shape for shape, kind in SHAPE_KIND.items()}
WHERE_TO = "Where should I "  # the question for a send-out service's place outside
# The question when a send-out service's destination is a colleague's name.
OUT_OR_IN = "Should I send it out "


# The words before what an item is made into ("print it *as* labels", "*into* a PDF").
_INTO_PRODUCT = frozenset({"as", "into"})
# The words between a making verb and what it makes: "print *me some new* labels".
_BETWEEN_VERB_AND_PRODUCT = english.words("determiners") | {"us", "new", "more", "fresh", "extra"}


def _head_asks(phrase: str) -> bool:
    """Whether a declared phrase's first word alone asks for it: a one-word verb, or the
    verb heading a phrase ("seal in plastic"); not a modifier ("3d" of "3d print")."""
    words = phrase.split()
    return len(words) == 1 or "VERB" in language.lemmas(words[0])


def _verbs_of_another(by_verb: list[Operation], task: Task, tasks: list[Task]) -> bool:
    """Whether the operations said by verb work on the item of another of ``tasks``, not
    on ``task``'s: the verb belongs to that other clause."""
    return any(op.input == u.item != task.item for op in by_verb for u in tasks)


def _means_of(op: Operation) -> tuple[str, ...]:
    """The means a send-out service's name says it sends by ("courier"); none for others."""
    return means_words(op.name) if op.sends_out else ()


def _filler(word: str) -> bool:
    return word in _BETWEEN_VERB_AND_PRODUCT or word.isdigit()


class OperationChooser:
    """Names the operations of one office's tasks from the words that asked for them."""

    def __init__(self, office: Office) -> None:
        self.office = office
        # an operation is asked for by its verbs; its display name is a label ("print spine
        # labels" names the label run, its "print" is the printer's verb), read as a verb
        # only where the office declares none
        # a declared phrase of several words is one token ("3d print"): its forms, and its
        # first word only where that is a verb of its own ("seal" of "seal in plastic"), never
        # a modifier ("3d" of "3d print" is in "the 3D printer", no request to 3D print)
        phrases = VerbPhrases.from_office(office)
        self._op_words = {
            op.id: {
                form
                for phrase in op.request_phrases
                for verb in normalize(phrase).split()[:1]
                if _head_asks(normalize(phrase))
                for form in inflections(verb)
            }
            | phrases.of_operation(op.id)
            | done_forms(op, office)
            # a send-out service is also named by the means its name says ("send by
            # courier": "courier my form", "by courier"): that service, never another
            # that happens to take the item
            | {form for means in _means_of(op) for form in inflections(means)}
            for op in office.operations
        }
        # the size each facility's own words say it works to ("A3 printer", "large-format")
        self._sizes = facility_sizes(office)
        # the operation the requester chose when asked which ("Which do you mean: print or
        # large-format plot?"), for the re-read of the request with that answer
        self.chosen: str | None = None

    def choose(
        self,
        frame: TaskFrame,
        lexed: Lexed,
        outside: Outside | None,
        *,
        sent_out: bool = False,
        destination: str | None = None,
        errands: frozenset[int] = frozenset(),
        whole: Lexed | None = None,
    ) -> TaskFrame:
        """Name the operation where the office has several of a task's shape ("scan" or
        "copy" a contract); ask which when the words do not say. ``sent_out``: the requester
        already said a send-out to a colleague's name is meant to leave the office;
        ``destination``: the requester's answer to "Where should I courier it to?", the place
        outside in their words where the request's own words named none.
        ``errands``: the tokens of hurrying verbs of an errand ("*run* it over to Will"),
        never a service's verb; ``whole``: the whole message, whose products named beside the
        request (in a statement the screen set aside) say which service makes one."""
        # the words said as verbs: not those inside a thing's name ("an A1 print" names the
        # plot, its "print" is no print asked for), nor an errand's hurrying verb
        inside = {n for m in lexed.mentions if m.kind == "item" for n in range(m.start, m.end)}
        inside |= errands
        # nor the words of a send-out's place outside ("courier it to the *print* works"):
        # a place's name asks for no service of this office
        inside |= _place_words(lexed, outside)
        # nor a participle that only describes the item ("courier my *printed* contract")
        inside |= describing_participles(lexed.tokens, lexed.mentions)
        in_order = [t.word for n, t in enumerate(lexed.tokens) if n not in inside]
        words = set(in_order)
        facility_ops = {
            op
            for m in lexed.mentions
            if m.kind == "facility" and not (outside is not None and outside.holds(m.start))
            for op in self.office.facility(m.ids[0]).operations
        }
        if not facility_ops:
            # "printed big, A1 if poss": the one facility whose own words say that size is
            # named by it, as by its name
            sized = sized_facility(self._sizes, in_order)
            if sized is not None:
                facility_ops = set(self.office.facility(sized).operations)
        products = {i for m in lexed.mentions if m.kind == "item" for i in m.ids}
        named_products = {i for m in (whole or lexed).mentions if m.kind == "item" for i in m.ids}
        # "as label sheets", "into a PDF": the products the item is to be made into
        made = made_products(lexed)  # "as a pull-up banner", "on a poster" too
        named: list[Task] = []
        for n, t in enumerate(frame.tasks):
            # the other tasks on the same item: "scan my plan and then bind it" is two
            # clauses, one operation each, not both operations twice
            peers = [
                k
                for k, u in enumerate(frame.tasks)
                if u.item == t.item and u.kind in _KIND_SHAPE and u.operation is None
            ]
            place = (peers.index(n), len(peers)) if n in peers else (0, 1)
            split, which = self._one_of_several(
                t, lexed, in_order, facility_ops, products, place, made
            )
            if which is not None:
                return TaskFrame(requester=frame.requester, question=which)
            named += split
        tasks: list[Task] = []
        for t in named:
            shape = _KIND_SHAPE.get(t.kind)
            ops = self.office.with_shape(shape) if shape and t.kind != "produce" else []
            if shape == "treat" and ops and t.item is not None and t.operation is None:
                # the service asked for by its verb, else at the facility named, else any
                by_verb = [op for op in ops if self._op_words[op.id] & words]
                at_named = [op for op in ops if op.id in facility_ops]
                asked = by_verb or at_named or ops
                fits = [op for op in asked if op.input == t.item]
                if not fits and _verbs_of_another(by_verb, t, named):
                    # "vac my prep then send my trimmings to the digester": the verb said
                    # is the other clause's, on its item; the machine named takes this one
                    fits = [op for op in at_named if op.input == t.item]
                    asked = at_named if fits else asked
                if not fits:  # "charge my radio" where only headlamps are charged
                    return TaskFrame(
                        requester=frame.requester, decline=self._cannot_treat(asked, t.item)
                    )
                if len(fits) == 1 and len(ops) > 1:  # named where several share the shape
                    t = t.model_copy(update={"operation": fits[0].id})
                ops = fits
            elif ops and t.item is not None and not _takes(ops, t):
                # "scan my badge" where the scanner takes documents: a service runs only on
                # the item types it takes (the office's own inputs), whatever its shape;
                # never run on the wrong thing
                by_verb = [op for op in ops if self._op_words[op.id] & words]
                return TaskFrame(
                    requester=frame.requester,
                    decline=self._cannot_treat(by_verb or ops, t.item),
                )
            if len(ops) > 1 and t.operation is None:
                said = [op for op in ops if self._op_words[op.id] & words]
                if not said:  # "put my contract in the scanner": the facility's own service
                    said = [op for op in ops if op.id in facility_ops]
                if not said:
                    # "a client wants a certified copy of her order, can you get one done?":
                    # the product the message named (its longest name, as the lexicon reads
                    # it: "certified copy", never its "copy") says which service makes it
                    said = [
                        op for op in ops if op.product is not None and op.product in named_products
                    ]
                if len(said) != 1:
                    said = [op for op in ops if op.id == self.chosen] or said  # as answered
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
                if where is not None and only_describes(where, op.destination_asked):
                    # "to the outside lab": no lab named; asked which, unless its name follows
                    where = named_after(lexed.text, where)
                    named_people = {m.text for m in lexed.mentions if m.kind == "person"}
                    if where is not None and any(n in where for n in named_people):
                        where = None  # "..., Ivy please": the colleague addressed, not a place
                if where is not None and names_no_place(where, (op.name, *op.verbs, op.done or "")):
                    where = None  # "off to the cleaners": which cleaner is still to ask
                if where is not None and where == (outside.phrase if outside else None):
                    where = self._with_detail(where, op, lexed, outside, whole)
                if where is not None and names_only_a_role(where):
                    # "to the supplier": whom, not where; the service asks where (after the
                    # detail: "the insurers, their fax number is ..." says where)
                    where = None
                if where is not None and needs_address(op.destination_asked):
                    if bare_common_noun(where):
                        # "to the factory" where the courier needs an address: which one, asked
                        where = None
                where = where or destination
                if where is None:
                    return TaskFrame(
                        requester=frame.requester,
                        question=f"{WHERE_TO}{verb_it(op, bare=True)} to? Please give me "
                        f"{op.destination_asked}.",
                    )
                colleague = _colleague(lexed, outside) if not sent_out else None
                if colleague is not None:
                    # "courier my plan to Bill" where Bill works here: sending it out of the
                    # office and handing it to him are different physical actions; ask
                    name = self.office.person(colleague).name
                    return TaskFrame(
                        requester=frame.requester,
                        question=f"{OUT_OR_IN}{by_means(op)}to {where} outside the office, "
                        f"or bring it to {name} here?",
                    )
                t = t.model_copy(update={"operation": op.id, "destination": where})
            tasks.append(t)
        return frame.model_copy(update={"tasks": tasks})

    def _with_detail(
        self,
        where: str,
        op: Operation,
        lexed: Lexed,
        outside: Outside | None,
        whole: Lexed | None,
    ) -> str:
        """The place with how to reach it, said in a clause after it that the screen set aside
        ("..., their number is 01632 960 123": a statement), so the operator is told it too."""
        if outside is None or outside.end is None or outside.detail_end is not None:
            return where  # none said, or already read with the place
        if whole is None:
            return where
        said = [t.word for t in lexed.tokens[outside.verb_start : outside.end]]
        detail = detail_in_message(
            whole.tokens,
            gaps(whole.text, whole.tokens),
            said,
            naming_words(op.destination_asked),
        )
        return where if detail is None else f"{where}, {detail.said}"

    def sending_words(self) -> frozenset[str]:
        """Every form of the verbs of the office's send-out services ("courier", "faxed")."""
        return frozenset(
            w for op in self.office.operations if op.sends_out for w in self._op_words[op.id]
        )

    def _one_of_several(
        self,
        task: Task,
        lexed: Lexed,
        words: list[str],
        facility_ops: set[str],
        products: set[str],
        place: tuple[int, int] = (0, 1),
        made: frozenset[str] | set[str] = frozenset(),
    ) -> tuple[list[Task], str | None]:
        """The operations a task on an item runs, where a machine does several: the one whose
        verb or gerund is said ("needs binding", "through the copier to scan it") or whose
        product is named ("to PDF"), whatever shape the rest of the clause suggested, and one
        task each when several are said ("photocopy and bind my plan"); with none said and
        the machine named doing several to this item, the question which ("Which do you
        mean: copy, scan or bind?"). ``place``: this task's index among the tasks on the same
        item, and their number (several tasks take the operations said in turn); ``made``: the
        products the item is to be made into ("as label sheets")."""
        if task.item is None or task.operation is not None or task.kind not in _KIND_SHAPE:
            return [task], None
        fits = [
            op
            for op in self.office.operations
            if op.input == task.item and self.office.runnable(op.id) and not op.sends_out
        ]
        chosen = [op for op in fits if op.id == self.chosen]
        if chosen:  # "Which do you mean: print or large-format plot?" "The plot."
            return [self._as(task, chosen[0])], None
        order = {w: n for n, w in reversed(list(enumerate(words)))}
        said = [op for op in fits if self._op_words[op.id] & set(words)]
        there = [op for op in said if op.id in facility_ops]
        if len(said) > 1 and len(there) == 1 and place[1] == 1:
            # "print my poster big" where the printer and the plotter both print: the one
            # the facility named (or its size, ``size_words``) offers
            said = there
        into = [op for op in fits if op.product in made]
        if len(into) == 1 and {op.shape(self.office) for op in [*said, *into]} == {
            into[0].shape(self.office)
        }:
            said = into  # "print my file as label sheets": the print verb is only the means
        # "print spine labels from my list", "get the labels printed": a product named as
        # the object of a generic verb of one shape is made by its own operation; the verb
        # (the printer's "print") is only the means
        # (only where one word named every service said: "print my artwork and make a plate
        # from it" says two services by two verbs, each its own task, never the plate only)
        objects = [op for op in fits if op.product in self._verb_objects(lexed, said)]
        if (
            len(objects) == 1
            and {op.shape(self.office) for op in [*said, *objects]}
            == {objects[0].shape(self.office)}
            and self._one_word_for_all(said, set(words))
        ):
            said = objects
        # "scan my contract to PDF", "send my plan to PDF": the product named says which
        said = said or [op for op in fits if op.product in products]
        at, peers = place
        sent = self._sent_out_said(task.item, set(words))
        # "get it past legal and then courier it": the facility named says the first
        at_named = [op for op in fits if op.id in facility_ops and op not in said]
        if sent and peers > 1 and len(said) + len(at_named) + len(sent) == peers:
            # one clause each, the send-out among them (never the other operation twice,
            # the sending left out), in the order they were said
            def said_at(op: Operation) -> int:
                spots = [order.get(w, len(order)) for w in self._op_words[op.id]]
                spots += [
                    m.start
                    for m in lexed.mentions
                    if m.kind == "facility" and op.id in self.office.facility(m.ids[0]).operations
                ]
                return min(spots, default=len(order))

            return [self._as(task, sorted([*said, *at_named, *sent], key=said_at)[at])], None
        if len(said) > 1:
            said = self._made_into(said, words)
        if len(said) > 1 and peers == 1 and self._one_word_for_all(said, set(words)):
            # "print my drawings" where the printer and the plotter both print: one verb said,
            # several services it names; which is meant is asked, never both run
            either = " or ".join(op.name for op in said)
            return [task], f"Which do you mean: {either}?"
        if len(said) > 1:
            # in the order they were said: "photocopy and bind" copies, then binds
            said.sort(key=lambda op: min(order.get(w, len(order)) for w in self._op_words[op.id]))
            if peers == len(said):  # one clause each: "scan my plan and then bind it"
                return [self._as(task, said[at])], None
            if peers == 1 and self._glued(said, lexed):
                # "laser print my file": two services' verbs side by side are one compound
                # the office does not declare, not two requests; which is meant is asked
                either = " or ".join(op.name for op in said)
                return [task], f"Which do you mean: {either}?"
            if peers == 1:
                return [self._as(task, op) for op in said], None
        said_shapes = {op.shape(self.office) for op in said}
        named_elsewhere = [op for op in at_named if op.shape(self.office) in said_shapes]
        if len(said) == 1 and named_elsewhere and said[0].id not in facility_ops:
            # "print my file on the 3D printer": the verb is the plotter's, the machine named
            # runs another operation of that shape; which is meant is the requester's to say
            either = " or ".join(op.name for op in [*said, *named_elsewhere])
            return [task], f"Which do you mean: {either}?"
        if len(said) == 1:
            shape = said[0].shape(self.office)
            own = _KIND_SHAPE.get(task.kind)
            own_said = own is not None and any(
                self._op_words[op.id] & set(words) for op in self.office.with_shape(own)
            )
            if peers > 1 and SHAPE_KIND.get(shape) != task.kind and own_said:
                # "my document scanned and laminated": the one service said that takes the
                # item is the other task's; this task's own verb ("laminated") asked for other
                # work (left to be run or refused as that work), never a second scan
                return [task], None
            # only where the clause read another shape, or several share this one: a lone
            # operation of its shape is left to the plain reading
            if SHAPE_KIND.get(shape) != task.kind or len(self.office.with_shape(shape)) > 1:
                return [self._as(task, said[0])], None
        at_machine = [op for op in fits if op.id in facility_ops]
        if not said and len(at_machine) > 1:
            names = [op.name for op in at_machine]
            listed = ", ".join(names[:-1]) + " or " + names[-1]
            return [task], f"Which do you mean: {listed}?"
        return [task], None

    def _one_word_for_all(self, said: list[Operation], words: set[str]) -> bool:
        """Whether the services ``said`` were all named by the same words only (one verb
        they share, "print"), none by a word of its own ("photocopy and bind")."""
        named = [self._op_words[op.id] & words for op in said]
        return all(n == named[0] for n in named)

    def _glued(self, said: list[Operation], lexed: Lexed) -> bool:
        """Whether the verbs of two of ``said`` stand side by side ("laser print")."""
        at = {
            n: op.id
            for n, t in enumerate(lexed.tokens)
            for op in said
            if t.word in self._op_words[op.id]
        }
        return any(n + 1 in at and at[n + 1] != op for n, op in at.items())

    def _sent_out_said(self, item: str, words: set[str]) -> list[Operation]:
        """The send-out services on ``item`` whose verb is said ("courier it")."""
        return [
            op
            for op in self.office.operations
            if op.input == item
            and op.sends_out
            and self.office.runnable(op.id)
            and self._op_words[op.id] & words
        ]

    def _verb_objects(self, lexed: Lexed, said: list[Operation]) -> set[str]:
        """The item types named right after a verb of ``said`` ("print *spine labels*",
        "print me some labels") or right before its participle ("get the labels
        *printed*"), with only determiners and quantity words between."""
        if not said:
            return set()
        verbs = {w for op in said for w in self._op_words[op.id]}
        words = [t.word for t in lexed.tokens]
        found: set[str] = set()
        for m in lexed.mentions:
            if m.kind != "item":
                continue
            k = m.start - 1
            while k >= 0 and _filler(words[k]):
                k -= 1
            j = m.end
            while j < len(words) and _filler(words[j]):
                j += 1
            after = words[j] if j < len(words) else ""
            if (k >= 0 and words[k] in verbs) or (
                after in verbs and language.is_past_participle(after)
            ):
                found.update(m.ids)
        return found

    def _made_into(self, said: list[Operation], words: list[str]) -> list[Operation]:
        """ "print my file *as labels*", "run it off *into* label sheets": of several
        operations of one shape said, the one named right after "as"/"into" is what the
        item is made into; the other's word is only the means ("print")."""
        into = [
            op
            for op in said
            if any(
                n and words[n - 1] in _INTO_PRODUCT and w in self._op_words[op.id]
                for n, w in enumerate(words)
            )
        ]
        shapes = {op.shape(self.office) for op in said}
        return into if len(into) == 1 and len(shapes) == 1 else said

    def _as(self, task: Task, op: Operation) -> Task:
        """``task`` as a run of ``op``: its kind is the one of the operation's shape."""
        kind = SHAPE_KIND.get(op.shape(self.office), task.kind)
        return task.model_copy(update={"kind": kind, "operation": op.id})

    def _cannot_treat(self, ops: list[Operation], item: str) -> str:
        """Why a service the office offers cannot be run on this item, with what it is for."""
        asked = " or ".join(dict.fromkeys(verb_alone(op) for op in ops))
        thing = self._item_name(item)
        fits = [
            verb_it(op, obj=language.plural(self._item_name(op.input)))
            for op in ops
            if op.input is not None
        ]
        return f"Sorry, I can't {asked} {a_thing(thing)} here: I can only {' and '.join(fits)}."

    def _item_name(self, type_id: str) -> str:
        return self.office.item_type(type_id).name


def _takes(ops: list[Operation], task: Task) -> bool:
    """Whether the service the task names, else any of ``ops`` (those of its shape), takes
    the task's item type; an operation with no input (a coffee made from nothing) takes any."""
    named = [op for op in ops if op.id == task.operation] if task.operation else ops
    return any(op.input is None or op.input == task.item for op in named or ops)


def colleague_named(lexed: Lexed, start: int = 0, end: int | None = None) -> str | None:
    """The one colleague the tokens ``start:end`` of ``lexed`` name and nothing else ("Bill",
    "Bill Osei"); None for a place outside ("the county land registry")."""
    stop = len(lexed.tokens) if end is None else end
    inside = [m for m in lexed.mentions if start <= m.start < stop and m.kind != "word"]
    if len(inside) != 1 or inside[0].kind != "person" or len(inside[0].ids) != 1:
        return None
    person = inside[0]
    rest = {
        t.word
        for k, t in enumerate(lexed.tokens[start:stop], start)
        if not person.start <= k < person.end
    }
    return person.ids[0] if rest <= COMMON else None


def _place_words(lexed: Lexed, outside: Outside | None) -> set[int]:
    """The tokens of a send-out's place outside, up to a join that opens a clause of other
    work ("to the head office *and vet it*": its verb still asks, and is asked about); a join
    inside a proper name ("the Print and Copy Centre") is the place's."""
    if outside is None or outside.start is None or outside.end is None:
        return set()
    out: set[int] = set()
    tokens = lexed.tokens
    for n in range(outside.start, outside.end):
        if tokens[n].word in ("and", "then") and n + 1 < outside.end:
            if not tokens[n + 1].text[:1].isupper():
                break
        out.add(n)
    return out


def _colleague(lexed: Lexed, outside: Outside | None) -> str | None:
    if outside is None or outside.start is None or outside.end is None:
        return None
    return colleague_named(lexed, outside.start, outside.end)
