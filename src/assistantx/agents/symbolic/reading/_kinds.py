"""What a clause asks for: its tasks, from its cues and the kinds of its objects.

A clause that names one document-like job (sign, seal, heat, print, copy) is one task; the
first rule of ``KIND_RULES`` that applies decides which, so "print and sign" reads as the
signature the print is for. Otherwise every object of the verb is a task of its own
("a stapler and a coffee"), its kind following from the item's kind (a product is made, a
file is sent, a belonging is brought).
"""

from __future__ import annotations

import dataclasses
import itertools
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading import at_hand, shared_object
from assistantx.agents.symbolic.reading._parties import Clause, Roles, recipient_of
from assistantx.agents.symbolic.reading.asking_forms import asking_forms
from assistantx.agents.symbolic.reading.cued_tool import cued_tool_owner
from assistantx.agents.symbolic.reading.doer_nouns import is_doer_noun
from assistantx.agents.symbolic.reading.file_had import colleagues_file, file_again
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.made_from import input_of_product
from assistantx.agents.symbolic.reading.one_from_source import one_of_the_previous
from assistantx.agents.symbolic.reading.own_recipients import own_for_of_one, roles_of_parts
from assistantx.agents.symbolic.reading.stated_source import says_has_some
from assistantx.agents.symbolic.reading.unlisted_thing import unlisted_thing
from assistantx.agents.symbolic.reading.where_it_lives import lives_there
from assistantx.core import english, language, task_kinds
from assistantx.core.office import Office, OperationShape
from assistantx.core.task_schema import FILE_KIND, SHAPE_KIND, Task

_SEND_WORDS = english.words("send_words")
# The prepositions that take an item to a facility ("on the charging shelf", "into the oven").
_TO_FACILITY = english.words("to_facility_prepositions")
_FROM_FACILITY = english.words("from_facility_prepositions")
_THROUGH = english.words("through_prepositions")
_FACILITY_DOING = english.words("facility_doing_verbs")
_AT = frozenset({"at", "in", "by", "near"})
# The words that make a tool the instrument of a service on a paper ("stamped *with* the
# embosser", "the stamp *on* it"), and the participles that ask for the service itself.
_INSTRUMENT = english.words("instrument_prepositions")
_ONTO = english.words("onto_prepositions")
_SERVICE_PARTICIPLES = english.words("service_participles")
_PLACE_WORDS = english.words("place_words") | english.words("surface_words")
_LEAD_IN = english.words("lead_in")
_COMMON = english.words("common")
_NEED_WORDS = english.words("need_verbs")
# The cue kinds that only pass something on ("send me", "get me"), not ask for other work.
_PASSING_ON = frozenset({"send", "give", FILE_KIND})
# The task kinds that act on the requester's file.
FILE_KINDS = frozenset({"print", FILE_KIND})


@dataclass
class Scene:
    """One clause, sorted: its cues, its objects by item kind, who is who."""

    clause: Clause
    roles: Roles
    requester: str
    previous: Task | None
    cues: set[str]
    items: list[Mention]
    files: list[Mention]
    personal: list[Mention]
    products: list[Mention]
    physical: list[Mention]
    facilities: list[str]
    doc: Mention | None  # the document-like item the clause is about
    refers: bool  # "it", "them": the clause points back
    seal_tool: str | None = None  # the office's item type that stamps (ItemType.seals)
    file_type: str | None = None  # the office's electronic file type
    treat_asked: bool = False  # a treat service's verb, or an item put at its facility
    signable: str | None = None  # the office's paper a person signs or stamps (signable)
    tool_owners: frozenset[str] = frozenset()  # who owns the office's stamping tool

    @property
    def recipient(self) -> str:
        return self.roles.recipient[-1] if self.roles.recipient else self.requester

    def owner(self, m: Mention | None) -> str | None:
        if m is None:
            return None
        return self.roles.owners.get(m.start) or self.roles.source_for(m.start)


@dataclass(frozen=True)
class KindRule:
    name: str
    applies: Callable[[Scene], bool]
    task: Callable[[Scene], Task]


def person_work(cues: set[str]) -> str | None:
    """The kind of work a named person does that the cues ask for: a signature, or a kind
    added to the table with its words ("endorse"); kinds whose doer needs a tool (the seal)
    are read by their own rule."""
    return next(
        (k for k in task_kinds.person_kinds() if k in cues and not task_kinds.needs_tool(k)),
        None,
    )


def _work_of(s: Scene) -> str | None:
    """ "Wang's signature": the one whose work the clause names by a possessive right before
    the work's word is its doer."""
    ms = s.clause.mentions
    for a, b in itertools.pairwise(ms):
        if a.kind == "person" and a.possessive and len(a.ids) == 1 and b.start == a.end:
            if b.kind == "cue" and person_work(set(b.ids)) is not None:
                return a.ids[0]
    return None


def _sign(s: Scene) -> Task:
    # "take it to Wang to sign": whom it goes to signs, never the requester it comes back to
    to = [p for p in s.roles.recipient if p != s.requester]
    actor = next(iter(s.roles.actor + s.roles.bare + to), None) or _work_of(s)
    # the signed paper comes back to the requester, unless someone else is named to get it
    # after the signer ("to Wang for a signature and then on to Hal": Hal)
    onward = [p for p in to if p != actor]
    back = s.requester if actor in s.roles.recipient else s.recipient
    return Task(
        kind=person_work(s.cues) or "sign",
        item=s.doc.id if s.doc else None,
        owner=s.owner(s.doc) or s.requester,
        recipient=onward[-1] if onward and actor in s.roles.recipient else back,
        actor=actor,
    )


def _seal_items(s: Scene) -> list[Mention]:
    return [m for m in s.clause.mentions if m.kind == "item" and m.id == s.seal_tool]


def _tool_used(s: Scene) -> bool:
    """Whether the clause uses the stamping tool on a paper rather than asking for the tool:
    "stamped with the embosser", "needs the stamp on it", "get it stamped". The tool is the
    instrument after "with"/"using", or what goes "on" the paper; a participle of the
    service ("stamped", "sealed") asks for the service itself. An owned tool read this way
    is never an object to hand over, whatever paper noun the office failed to list."""
    if s.seal_tool is None:
        return False
    mentions = s.clause.mentions
    for n, m in enumerate(mentions):
        tool = (m.kind == "item" and m.id == s.seal_tool) or (m.kind == "cue" and "seal" in m.ids)
        if not tool:
            continue
        k = n - 1
        while k >= 0 and mentions[k].possessive:  # "with *his* embosser"
            k -= 1
        before = mentions[k] if k >= 0 else None
        j = n + 1
        while j < min(len(mentions), n + 3) and _verb_word(mentions[j]):
            j += 1  # "the embosser *go* on my lease", "the seal *put* on it"
        after = mentions[j] if j < len(mentions) else None
        if before is not None and before.kind == "word" and before.ids[0] in _INSTRUMENT:
            return True
        if m.kind == "cue" and before is not None and before.kind == "word":
            if before.ids[0] == "to":  # "get Tobias to stamp my lease": the service
                return True
        if after is not None and after.kind == "word" and after.ids[0] in _ONTO:
            if _onto_paper(mentions[j + 1 :]):
                return True
        if m.kind == "cue" and m.text.lower() in _SERVICE_PARTICIPLES:
            return True
        if m.kind == "cue" and _verb_position(mentions, n):
            return True  # "please emboss my lease": the service is the clause's verb
        if _needed_by_paper(mentions, n):
            return True  # "my lease needs Tobias's embosser": a paper needs the tool
        if after is not None and after.kind == "word" and after.ids[0] == "for":
            if _for_paper(mentions[j + 1 :]):
                return True  # "I need the embosser for my lease": used on the lease
    return False


def _tool_handed(s: Scene) -> bool:
    """Whether the stamping tool itself is what the clause hands to a colleague who does not
    own it ("take my seal to Sun Li, she needs to stamp the agreements", "lend Sun my seal"):
    the tool is lent for that person's own work, so it is moved, and no paper of the
    requester's is stamped. It is the object of a verb of passing on (only possessives or the
    one it goes to between them), and that person is among the clause's recipients."""
    if s.seal_tool is None:
        return False
    mentions = s.clause.mentions
    for n, m in enumerate(mentions):
        if m.kind != "item" or m.id != s.seal_tool:
            continue
        k = n - 1
        while k >= 0 and (
            mentions[k].possessive or (mentions[k].kind == "person" and len(mentions[k].ids) == 1)
        ):
            k -= 1  # "lend *Sun Li* *my* seal"
        if k < 0 or mentions[k].kind != "cue" or "give" not in mentions[k].ids:
            continue
        owner = s.owner(m) or s.requester
        if any(p != owner and p != s.requester for p in s.roles.recipient):
            return True
    return False


def _verb_position(mentions: list[Mention], n: int) -> bool:
    """Whether a service word is the clause's verb, with its object after it ("stamp my
    lease", "please emboss it", "have Ines stamp my lease"), not a noun ("bring me the
    stamp", "Ines's stamp")."""
    nxt = mentions[n + 1] if n + 1 < len(mentions) else None
    if nxt is None or not (nxt.possessive or nxt.kind in ("pronoun", "item")):
        return False
    before = mentions[n - 1] if n else None
    if before is not None and before.kind == "person" and not before.possessive:
        return True  # "have Ines stamp my lease": she does it
    return all(m.kind == "word" and m.ids[0] in _LEAD_IN for m in mentions[:n])


def _for_paper(rest: list[Mention]) -> bool:
    """Whether what follows "for" is someone's paper the tool is used on ("for my lease",
    "for Noor's deed"), not a time, a place or a person ("for tomorrow", "for Noor", "for the
    site visit"): only a possessed noun is read so."""
    k = 0
    while k < len(rest) and rest[k].possessive:
        k += 1
    if k == 0 or k >= len(rest):
        return False
    m = rest[k]
    if m.kind == "item":
        return True
    word = m.ids[0] if m.ids else ""
    return (
        m.kind == "word"
        and word not in _PLACE_WORDS
        and word not in _COMMON
        and not language.is_weekday(word)
        and not language.is_month(word)
        and language.is_noun(word)
    )


def _needed_by_paper(mentions: list[Mention], n: int) -> bool:
    """ "my lease needs Tobias's embosser", "the affidavit needs the practice seal": the tool
    is the object of a need whose subject is a thing (a noun, "it"), not a person or "I"."""
    k = n - 1
    while k >= 0 and mentions[k].possessive:
        k -= 1
    if k < 0 or mentions[k].kind != "cue" or mentions[k].text.lower() not in _NEED_WORDS:
        return False
    subject = [m for m in mentions[:k] if not m.possessive]
    if any(m.kind in ("person", "self") for m in subject):
        return False
    return any(
        m.kind == "pronoun"
        or m.kind == "item"
        or (m.kind == "word" and m.ids[0] not in _LEAD_IN and language.is_noun(m.ids[0]))
        for m in subject
    )


def _verb_word(m: Mention) -> bool:
    """A plain word that is a verb ("go", "put", "be"), not a preposition like "on"."""
    word = m.ids[0] if m.ids else ""
    return m.kind == "word" and word not in _ONTO and bool(language.verb_lemmas(word))


def _onto_paper(rest: list[Mention]) -> bool:
    """Whether what follows "on" is the paper ("on it", "on my lease", "on the contract"),
    not a place the tool is put ("on my desk", "on the table")."""
    k = 0
    while k < len(rest) and rest[k].possessive:
        k += 1
    if k >= len(rest):
        return False
    m = rest[k]
    if m.kind == "pronoun":
        return True
    if m.kind == "item":
        return True
    return m.kind == "word" and m.ids[0] not in _PLACE_WORDS and language.is_noun(m.ids[0])


def _seal(s: Scene) -> Task:
    sealer = next((s.roles.owners.get(m.start) for m in _seal_items(s)), None)
    sealer = sealer or next(iter(s.roles.actor + s.roles.bare), None)
    # "take my lease to Ines to be stamped": the one it goes to who owns a stamp stamps it,
    # and it comes back to the requester, as a signer named so would sign it
    to_sealer = next((p for p in s.roles.recipient if p in s.tool_owners), None)
    if sealer is None and to_sealer is not None:
        sealer = to_sealer
        s = dataclasses.replace(
            s,
            roles=dataclasses.replace(
                s.roles, recipient=[p for p in s.roles.recipient if p != to_sealer]
            ),
        )
    if s.doc is None:
        # "get my lease stamped with the embosser": a paper the office does not list by
        # that word is its signable paper, the requester's unless the clause says whose
        return Task(
            kind="seal",
            item=s.signable,
            owner=s.requester,
            recipient=s.recipient,
            actor=sealer,
        )
    return Task(
        kind="seal",
        item=s.doc.id,
        owner=s.owner(s.doc) or s.requester,
        recipient=s.recipient,
        actor=sealer,
    )


def _heat(s: Scene) -> Task:
    # an office's treat service may work on any belonging ("charge my headlamp"), not only
    # on a personal one: the clause's first physical object, when the service is asked for
    # by its verb or by taking the item to the facility that offers it
    thing = s.doc or (s.physical[0] if s.physical and s.treat_asked else None)
    return Task(
        kind="heat",
        item=thing.id if thing else None,
        owner=s.owner(thing) or s.requester,
        recipient=s.recipient,
    )


def _print(s: Scene) -> Task:
    source = (s.files or s.personal)[0] if s.files or s.personal else None
    return Task(
        kind="print",
        item=s.file_type,
        owner=s.owner(source) or s.requester,
        recipient=s.recipient,
    )


def _copy(s: Scene) -> Task:
    assert s.doc is not None
    return Task(
        kind="copy", item=s.doc.id, owner=s.owner(s.doc) or s.requester, recipient=s.recipient
    )


# One task for the whole clause: highest priority first.
KIND_RULES: tuple[KindRule, ...] = (
    KindRule(
        "a person's work (a signature, a kind of the table), whatever else is said",
        lambda s: person_work(s.cues) is not None,
        _sign,
    ),
    KindRule(
        "a seal on a document (the seal named or asked for), unless the tool itself is "
        "handed to a colleague for their own work",
        lambda s: (
            ("seal" in s.cues or bool(_seal_items(s)))
            and (s.doc is not None or (s.signable is not None and _tool_used(s)))
            and not _tool_handed(s)
        ),
        _seal,
    ),
    KindRule(
        "heating, unless a product is asked for",
        lambda s: "heat" in s.cues and not s.products,
        _heat,
    ),
    KindRule(
        "printing the requester's file, unless the object is a thing the office makes from "
        "nothing ('get me a visitor pass printed': the pass's own operation makes it)",
        lambda s: "print" in s.cues and not (s.products and not s.files and not s.personal),
        _print,
    ),
    KindRule(
        "copying a document (not a file)",
        lambda s: "copy" in s.cues and s.doc is not None and not s.files,
        _copy,
    ),
)


class TaskReader:
    """Reads the tasks of a clause against one office."""

    def __init__(self, office: Office) -> None:
        self.office = office
        self.kinds = {t.id: t.kind for t in office.item_types}
        # the products that name their task: "a printout" is a print, "a copy" a copy
        self.printout = product_of_shape(office, "render")
        self.copy = product_of_shape(office, "transform")
        # every product made from an item or a file names its task ("a PDF of my plan" is
        # the scan, as "a printout" is the print), not only each shape's first
        self.made: dict[str, str] = {
            o.product: SHAPE_KIND[o.shape(office)]
            for o in office.operations
            if o.product and o.shape(office) in ("render", "transform")
        }
        self.sourced = frozenset(p for p in (self.printout, self.copy, *self.made) if p)
        # the operation that makes each product of a paper ("a PDF": the scan)
        self.copy_ops = {
            o.product: o.id
            for o in office.operations
            if o.product and o.shape(office) == "transform"
        }
        # the things (papers or not) an operation makes something from
        self.transformed = frozenset(
            o.input for o in office.operations if o.input and o.shape(office) == "transform"
        )
        self.product_words = {
            language.fold(name): t.id
            for t in office.item_types
            if t.id in self.copy_ops
            for name in (t.name, *t.synonyms)
        }
        # the file types, which may name the format of what a service makes ("to PDF")
        self.formats = frozenset(t.id for t in office.item_types if t.electronic)
        self.file = office.file_type() or ""  # what is forwarded
        # the words of each item type's names of several words ("master" of "master file")
        self._name_words = {
            t.id: frozenset(
                w
                for n in (t.name, *t.synonyms)
                if len(language.words(n)) > 1
                for w in language.words(n)
            )
            for t in office.item_types
        }
        seal = office.seal_tool()
        self.tool_owners = frozenset(office.owners_of(seal) if seal else ())
        # each form of a verb that asks for exactly one operation making something from
        # nothing → its product ("brew" → tea where brewing is the kettle's one operation)
        makers: dict[str, set[str]] = {}
        for o in office.operations:
            for verb in o.verbs:
                for form in language.verb_forms(language.fold(verb)):
                    makers.setdefault(form, set()).add(
                        o.product if o.product and o.input is None else ""
                    )
        self.verb_products = {
            form: next(iter(made))
            for form, made in makers.items()
            if len(made) == 1 and "" not in made
        }

    def made_from_nothing(self, item: str) -> bool:
        """Whether ``item`` is what a service makes from nothing (a coffee, a tea)."""
        return any(o.product == item and o.input is None for o in self.office.operations)

    def product_of(self, kind: str) -> str | None:
        return {"print": self.printout, "copy": self.copy}.get(kind)

    def _file_had(
        self, m: Mention, clause: Clause, roles: Roles, requester: str, previous: Task | None
    ) -> bool:
        """Whether ``m`` is a file someone has although the office also makes its type
        (``file_had``): a colleague's, or the one a task before was on."""
        if self.kinds.get(m.id) != "electronic" or m.id not in self.made:
            return False
        owner = roles.owners.get(m.start) or roles.source_for(m.start)
        before = previous.item if previous is not None else None
        return colleagues_file(owner, requester) or file_again(m, clause.mentions, before)

    def products_of(self, kind: str) -> frozenset[str]:
        """Every product a task of ``kind`` may hand over (a copy, a PDF)."""
        return frozenset(p for p, k in self.made.items() if k == kind)

    def scene(self, clause: Clause, roles: Roles, requester: str, previous: Task | None) -> Scene:
        items = clause.objects()
        cues = set(clause.cues)
        # "Wang's budget file" where a scan also makes files: the colleague's own file
        owned = {m.start for m in items if self._file_had(m, clause, roles, requester, previous)}
        for m in items:  # products of the printer are cues: "a printout", "a copy"
            if m.start in owned:
                continue
            if m.id == self.printout:
                cues.add("print")
            if m.id == self.copy:
                cues.add("copy")
            if m.id in self.made:
                cues.add(self.made[m.id])
        facilities = [m.id for m in clause.mentions if m.kind == "facility"]
        facilities_said = [m for m in clause.mentions if m.kind == "facility"]
        treating = [
            m
            for m in facilities_said
            if any(
                self.office.operation(op).shape(self.office) == "treat"
                for op in self.office.facility(m.id).operations
            )
        ]
        before = {b.start: a for a, b in zip(clause.mentions, clause.mentions[1:], strict=False)}

        def word_before(m: Mention) -> str:
            w = before.get(m.start)
            return w.ids[0] if w is not None and w.kind == "word" else ""

        def persons_place(m: Mention) -> bool:
            """ "Dot at dispatch": the facility is where a colleague is, not its service."""
            w = before.get(m.start)
            if w is None or w.kind != "word" or not w.ids or w.ids[0] not in _AT:
                return False
            return before.get(w.start, w).kind == "person"

        def has_some(m: Mention) -> bool:
            """ "need cable ties, art room has some": where the thing is, not its service."""
            after = itertools.takewhile(
                lambda a: a.kind == "word", (a for a in clause.mentions if a.start >= m.end)
            )
            return says_has_some([a.ids[0] for a in after], m.possessive)

        def what_it_is_for(m: Mention) -> bool:
            """ "need a cold pack for the van": a thing wanted for a facility whose
            services take no such thing is for using there, no service asked of it."""
            inputs = {
                self.office.operation(op).input for op in self.office.facility(m.id).operations
            }
            return word_before(m) == "for" and bool(items) and not inputs & {i.id for i in items}

        # "bring me Bram's headlamp from the charging shelf": the facility is where it is
        treating = [
            m
            for m in treating
            if not persons_place(m)
            and not has_some(m)
            and not what_it_is_for(m)
            and m.start not in clause.modifiers  # "a meter to check the compressor's wiring"
            and not lives_there(m, before)  # "the meter that lives in the drying cabinet"
        ]
        if any(word_before(m) not in _FROM_FACILITY for m in treating):
            cues.add("heat")

        # "put my contract in the scanner": a physical item taken to a facility that makes
        # something from it asks for that (one that also prints leaves it open: ask)
        def shapes(m: Mention) -> set[OperationShape]:
            return {
                self.office.operation(op).shape(self.office)
                for op in self.office.facility(m.id).operations
            }

        if any(
            word_before(m) in _TO_FACILITY | _THROUGH
            and "transform" in shapes(m)
            and "render" not in shapes(m)
            and not persons_place(m)  # "to Frank in the edit": where he is, not its service
            for m in facilities_said
        ):
            cues.add("copy")
        # "run this through the copier" where the printer also prints: the name said for the
        # machine is the doer noun of its copying verb, so its copying is asked (doer_nouns)
        if any(
            word_before(m) in _TO_FACILITY | _THROUGH
            and not persons_place(m)
            and self._names_transform(m)
            for m in facilities_said
        ):
            cues.add("copy")
        # "run my drawing through the plotter", "put my file on the printer": a file taken
        # to a facility that renders files asks for that rendering (which of the office's
        # renderings, the facility's own: operations.py)
        rendered = any(
            word_before(m) in _TO_FACILITY | _THROUGH
            and "render" in shapes(m)
            and not persons_place(m)  # "to Hattie in repro": where she is, not its service
            for m in facilities_said
        )
        if rendered and not items and self.file:
            # "run my poster through the plotter": a thing of mine the office has no word
            # for, taken to a machine that renders files, is my file
            items = [
                Mention("item", m.start, m.end, (self.file,), False, m.text)
                for a, m in itertools.pairwise(clause.mentions)
                if a.kind == "self"
                and a.possessive
                and a.text.lower() != "mine"  # "mine down to ...": no noun follows "mine"
                and a.end == m.start
                and m.kind == "word"
                and language.is_noun(m.ids[0] if m.ids else "")
            ][:1]
        if rendered and any(self.kinds[m.id] == "electronic" for m in items):
            cues.add("print")
        # "could the reel reader do my slide?": a facility as the doer of its own work
        doing = self._facility_doing(clause, items, roles)
        cues |= doing
        # "can you scanner my document": a facility's name said as the verb, its own work
        cues |= self._facility_as_verb(clause, items)
        if doing:
            cues.discard("give")  # its "take" is the machine's work, not a fetch
        # "put my headlamp on the charging shelf": the item goes *to* the facility
        treat_asked = (
            "heat" in clause.cues
            or "heat" in doing
            or any(word_before(m) in _TO_FACILITY for m in treating)
        )
        items = [m for m in items if m.id not in self.sourced or m.start in owned]
        files = [m for m in items if self.kinds[m.id] == "electronic"]
        personal = [m for m in items if self.kinds[m.id] == "personal"]
        products = [m for m in items if self.kinds[m.id] == "product"]
        physical = [m for m in items if self.kinds[m.id] in ("belonging", "personal")]
        # "my report file": a document word naming a file
        if files and personal and personal[-1].end == files[0].start:
            dropped = personal.pop()
            physical = [m for m in physical if m is not dropped]
        doc: Mention | None = personal[0] if personal else None
        if doc is None and "copy" in cues:
            # "get a spare key cut for my car": what the product is made from, unsaid
            made_from = input_of_product(
                self.office, clause.objects(), clause.mentions, self.copy_ops, requester
            )
            if made_from is not None:
                doc, own = made_from
                if own:
                    roles.owners[-1] = requester
        if doc is None and "copy" in cues:
            # "can you assay my job bag": a thing (no paper) one of the office's operations
            # makes something from is that operation's object
            doc = next((m for m in physical if m.id in self.transformed), None)
        refers = any(m.kind == "pronoun" and not m.possessive for m in clause.mentions)
        if doc is None and refers and previous is not None and previous.item is not None:
            if self.kinds[previous.item] == "personal":  # "... and get Zhang to sign it"
                doc = Mention("item", -1, -1, (previous.item,))
                roles.owners[-1] = previous.owner or requester
        if (
            doc is None
            and not items
            and previous is not None
            and previous.item is not None
            and self.kinds.get(previous.item) == "personal"
            and shared_object.opens_with_participle(clause.mentions)
        ):
            # "I need this photocopied and signed by Mark": the second participle's object
            # is the first one's
            doc = Mention("item", -1, -1, (previous.item,))
            roles.owners[-1] = previous.owner or requester
        if (
            doc is None
            and not items
            and previous is None
            and at_hand.points_at_hand(clause.mentions, bool(facilities))
        ):
            # "copy this please", "run it through the laminator": the thing held out is the
            # requester's own item of the type the service works on
            doer = [*roles.actor, *roles.bare, *(p for p in roles.recipient if p != requester)]
            held = at_hand.held_type(
                self.office, clause.mentions, cues, facilities, requester, bool(doer)
            )
            if held is not None:
                doc = Mention("item", -1, -1, (held,))
                roles.owners[-1] = requester
        return Scene(
            clause,
            roles,
            requester,
            previous,
            cues,
            items,
            files,
            personal,
            products,
            physical,
            facilities,
            doc,
            refers,
            self.office.seal_tool(),
            self.office.file_type(),
            treat_asked,
            self.office.signable_type(),
            self.tool_owners,
        )

    def _names_transform(self, m: Mention) -> bool:
        """Whether the facility's name as said is the doer noun of a verb of one of its
        operations that makes something from an item ("copier" of "copy")."""
        said = language.words(m.text)
        if not said:
            return False
        for op_id in self.office.facility(m.id).operations:
            op = self.office.operation(op_id)
            if op.shape(self.office) == "transform" and any(
                is_doer_noun(said[-1], v.split()[0]) for v in op.verbs
            ):
                return True
        return False

    def _facility_doing(self, clause: Clause, items: list[Mention], roles: Roles) -> set[str]:
        """ "could the reel reader do my slide?", "can the sealer take my chart?": a facility
        as the subject of a doing verb, with someone's item one of its operations works on,
        asks for that operation; the cue of its shape's task kind (none: not said so). An
        item of nobody's ("can the reader do slides?") asks what it can do, not for work."""
        ms = clause.mentions
        for a, b in itertools.pairwise(ms):
            if a.kind != "facility" or b.kind not in ("word", "cue") or b.start != a.end:
                continue
            if not language.verb_lemmas(b.text.lower()) & _FACILITY_DOING:
                continue
            later = [m for m in items if m.start > b.start and m.start in roles.owners]
            kinds = {
                kind
                for op_id in self.office.facility(a.ids[0]).operations
                for op in [self.office.operation(op_id)]
                if any(m.id == op.input for m in later)
                and (kind := SHAPE_KIND.get(op.shape(self.office))) is not None
            }
            if len(kinds) == 1:
                return kinds
        return set()

    def _facility_as_verb(self, clause: Clause, items: list[Mention]) -> set[str]:
        """ "can you scanner my document", "pls laminator my badge", "can you xrf my job bag"
        (the word also the XRF's name): a facility's name said in the verb's place, its
        object after it, asks for that facility's own work on the object; never another
        service of the thing. Where the word said is also one of its operations' verbs, that
        operation; the cue of its shape's task kind, none where they are several."""
        ms = clause.mentions
        for n, m in enumerate(ms):
            if m.kind != "facility" or not _verb_position(ms, n):
                continue
            objects = {i.id for i in items if i.start >= m.end}
            ops = [
                op
                for op_id in self.office.facility(m.id).operations
                for op in [self.office.operation(op_id)]
                if op.input is not None and op.input in objects
            ]
            said = m.text.lower()
            named = [op for op in ops if any(said in asking_forms(v.lower()) for v in op.verbs)]
            kinds = {
                kind
                for op in named or ops
                if (kind := SHAPE_KIND.get(op.shape(self.office))) is not None
            }
            if len(kinds) == 1:
                return kinds
        return set()

    def tasks(
        self, clause: Clause, roles: Roles, requester: str, previous: Task | None
    ) -> list[Task]:
        cues = set(clause.cues)
        if (
            previous is not None
            and not cues & {"print", "copy"}
            and any(m.id in self.products_of(previous.kind) for m in clause.objects())
        ):
            return []  # "print my draft and take the printout to Sue": the same task, on
        if previous is not None and self._sends_made_file(clause, roles, previous):
            return []  # "scan my reel and send me the PDF": the scan's file, to whom it goes
        clause = self._product_of_the_verb(clause)
        apart = self._made_of_apart(clause)
        if apart is not None:
            # "bring me a tea and a printout of my rota": the print of the rota, and the tea
            # "a latte for me and a copy of my contract for Fang": each part's own "for X"
            parts_roles = roles_of_parts(roles, apart)
            return [
                t
                for part, own in zip(apart, parts_roles, strict=True)
                for t in self.tasks(part, own, requester, previous)
            ]
        # "a tea for Will and a stapler for me" (no stapler here): the tea's own "for Will"
        roles = own_for_of_one(roles, clause)
        s = self.scene(clause, roles, requester, previous)
        each = self._each_product(s)
        if each:
            return each
        rule = next((r for r in KIND_RULES if r.applies(s)), None)
        if rule is not None:
            return [rule.task(s)]
        return self._objects(s)

    def _made_of_apart(self, clause: Clause) -> tuple[Clause, Clause] | None:
        """ "a tea and a printout of my rota": a product named with what it is made of ("a
        <product> of <input>", made by an operation of the office from that input) beside
        other things the clause asks for, which are neither that input nor another product
        of it: the product's words and the rest as two clauses, in the order said, each
        read as it would be alone. None for any other clause ("a copy of my plan for Noor
        and a PDF for Bill" stays one paper's two products)."""
        objects = clause.objects()
        if len(objects) < 2:
            return None
        by_start = {m.start: m for m in clause.mentions}
        for product in objects:
            of = by_start.get(product.end)
            if of is None or of.kind != "word" or of.ids[:1] != ("of",):
                continue
            k = of.end
            while k in by_start and by_start[k].kind in ("self", "person", "word"):
                if by_start[k].kind == "word" and not by_start[k].possessive:
                    break
                k = by_start[k].end
            source = by_start.get(k)
            if source is None or source.kind not in ("item", "word") or not source.ids:
                continue
            # the input named, or a word of its name ("of my master": the master file)
            inputs = {
                o.input
                for o in self.office.operations
                if o.product == product.id
                and o.input is not None
                and (
                    o.input == source.ids[0]
                    or (source.kind == "word" and source.ids[0] in self._name_words[o.input])
                    or (  # "a printout of my report": the report's file is printed
                        source.kind == "item"
                        and o.shape(self.office) == "render"
                        and self.kinds[source.ids[0]] in ("electronic", "personal")
                    )
                )
            }
            if len(inputs) != 1:
                continue
            made_of = {o.product for o in self.office.operations if o.input in inputs and o.product}
            others = [m for m in objects if not product.start <= m.start < source.end]
            if not others or any(m.id in made_of or m.id in inputs for m in others):
                return None
            span = range(product.start, source.end)
            made = dataclasses.replace(
                clause, mentions=[m for m in clause.mentions if m not in others]
            )
            rest = dataclasses.replace(
                clause, mentions=[m for m in clause.mentions if m.start not in span]
            )
            return (made, rest) if product.start < others[0].start else (rest, made)
        return None

    def _product_of_the_verb(self, clause: Clause) -> Clause:
        """ "brew for me and one for Bron": an operation's verb said as the whole request,
        with no thing named, names what it makes, where the office has exactly one operation
        asked for with it (and that one makes something from nothing): the verb is read as
        that product."""
        if any(m.kind in ("item", "pronoun", "facility") for m in clause.mentions):
            return clause
        verbs = [
            m
            for m in clause.mentions
            if m.kind == "cue" and m.start not in clause.modifiers and m.end - m.start == 1
        ]
        if len(verbs) != 1:
            return clause
        verb = verbs[0]
        product = self.verb_products.get(language.fold(verb.text))
        if product is None:
            return clause
        read = Mention("item", verb.start, verb.end, (product,), False, verb.text)
        mentions = [read if m is verb else m for m in clause.mentions]
        return dataclasses.replace(clause, mentions=mentions, cues=set())

    def _sends_made_file(self, clause: Clause, roles: Roles, previous: Task) -> bool:
        """Whether ``clause`` only sends on the electronic file the previous task's operation
        makes ("scan my reel and send me the PDF", "... PDF to me is fine"): a file named
        without an owner ("the PDF", never "my PDF"), after work on an item that an operation
        of the office turns into a file; the clause then says whom the product goes to."""
        if previous.item is None or set(clause.cues) - _PASSING_ON:
            return False
        objects = clause.objects()
        if not objects or any(
            self.kinds[m.id] != "electronic" or m.start in roles.owners or roles.source
            for m in objects
        ):
            return False
        return self.makes_file(previous)

    def makes_file(self, task: Task) -> bool:
        """Whether ``task`` (its operation, else every operation of its kind on its item)
        makes an electronic file ("digitise" a reel into a scan), which is then sent, not
        carried. Where a paper copy could also be meant ("copy my contract and send the
        file to Wang"), "the file" is not read as the product: the old reading stands."""
        runs = [
            o
            for o in self.office.operations
            if o.input == task.item
            and SHAPE_KIND.get(o.shape(self.office)) == task.kind
            and task.operation in (None, o.id)
        ]
        return bool(runs) and all(
            o.product is not None and self.kinds[o.product] == "electronic" for o in runs
        )

    def _each_product(self, s: Scene) -> list[Task]:
        """ "a copy of my plan for Noor and a PDF for Bill": two products made from one
        paper, each named with whom it is for, are a task each, run by the operation that
        makes it (none: a clause of one product, read by the rules)."""
        if s.doc is None:
            return []
        named = [
            m
            for m in s.clause.mentions
            if self._product(m) is not None and m.start not in s.clause.modifiers
        ]
        if len({self._product(m) for m in named}) < 2:
            return []
        owner = s.owner(s.doc) or s.requester
        return [
            Task(
                kind="copy",
                item=s.doc.id,
                owner=owner,
                recipient=recipient_of(named, k, s.roles, s.recipient),
                operation=self.copy_ops[self._product(m) or ""],
            )
            for k, m in enumerate(named)
        ]

    def _product(self, m: Mention) -> str | None:
        """The product of a paper a mention names: an item ("a PDF"), or a task word that is
        also the product's name ("a copy")."""
        if m.kind == "item":
            return m.id if m.id in self.copy_ops else None
        if m.kind == "cue":
            return self.product_words.get(language.fold(m.text))
        return None

    def _objects(self, s: Scene) -> list[Task]:
        """No one-task rule applied: a task per object of the verb."""
        clause, roles, requester, previous = s.clause, s.roles, s.requester, s.previous
        items, physical = s.items, s.physical
        cued: dict[int, str | None] = {}  # the tool said by its work's word → whose
        sends = any(
            m.kind == "cue" and m.text.lower() in _SEND_WORDS and m.start not in clause.modifiers
            for m in clause.mentions
        )
        if not items:
            if s.refers and sends and previous is not None and previous.kind in FILE_KINDS:
                # "print my slides and forward them to Zhou": the same file, passed on
                file_owner = previous.owner or requester
                return [
                    Task(kind=FILE_KIND, item=self.file, owner=file_owner, recipient=s.recipient)
                ]
            made = [
                p
                for f in s.facilities
                for p in self.office.facility(f).products[:1]
                if p not in (self.printout, self.copy) and ("give" in s.cues or "make" in s.cues)
            ]
            if one_of_the_previous(clause.mentions, previous):
                # "Sue needs a highlighter, take one down from the cupboard": that "one" is
                # the highlighter just asked for, and the cupboard where it comes from; never
                # a second thing, the cupboard's own product, for the requester
                made = []
            if made and unlisted_thing(clause.mentions) is None:
                # "50 ml of chloroform from the chem store": never what the store makes instead
                return [Task(kind="produce", item=p, recipient=s.recipient) for p in made]
            if "seal" in s.cues and s.seal_tool:  # "bring me the stamp": the seal as an item
                words = [m for m in clause.mentions if m.kind == "cue" and "seal" in m.ids][:1]
                items = physical = [
                    Mention("item", m.start, m.end, (s.seal_tool,), m.possessive, m.text)
                    for m in words
                ]
                # "bring me Siobhan's stamp": whose, said before the work's word
                cued = {m.start: cued_tool_owner(clause.mentions, m, requester) for m in words}
        # every object of the verb is a task of its own: "a stapler and a coffee"
        objects = [m for m in items if m in s.files or m in physical or m in s.products]
        objects = _ones_again(s, objects)
        tasks: list[Task] = []
        for k, m in enumerate(objects):
            to = s.recipient if len(objects) == 1 else recipient_of(objects, k, roles, s.recipient)
            kind = self.kinds[m.id]
            helper = next(iter(roles.actor + roles.bare + roles.returned_to), None)
            if kind == "product":
                tasks.append(Task(kind="produce", item=m.id, recipient=to))
            elif kind == "electronic" or (
                kind == "personal"
                and (sends or said_as_a_file(clause.mentions, m))
                and not roles.source
            ):
                file_owner = s.owner(m) or helper or requester
                # the office's own electronic type the words named ("my slides" where slides
                # are a type beside the generic file) is the file sent; a paper said as a
                # file is the office's file
                sent = m.id if kind == "electronic" else self.file
                tasks.append(Task(kind=FILE_KIND, item=sent, owner=file_owner, recipient=to))
            else:
                owner = s.owner(m) or cued.get(m.start) or helper
                tasks.append(Task(kind="transfer", item=m.id, owner=owner, recipient=to))
        return list(dict.fromkeys(tasks))

    def fill(self, task: Task, roles: Roles, requester: str) -> Task:
        """A clause with no task of its own completes the previous one."""
        update: dict[str, str] = {}
        by_person = task_kinds.kind_of(task.kind) and task_kinds.kind(task.kind).by_person
        # "P needs to sign my form. Take it to her": the way to the signer already named, not
        # whom the signed paper goes to (it comes back, unless someone else is named)
        onward = [p for p in roles.recipient if not (by_person and p == task.actor)]
        if onward:
            update["recipient"] = onward[-1]
        for who in roles.actor + roles.bare:
            if by_person and who == task.actor:
                continue  # "needs Wang's signature, get Wang to sign it": the signer again
            if by_person and task.actor is None and "actor" not in update:
                update["actor"] = who
            elif task.kind == "transfer" and task.owner is None and "owner" not in update:
                update["owner"] = who
            elif "recipient" not in update and task.recipient == requester:
                update["recipient"] = who
        return task.model_copy(update=update) if update else task


# The words of an electronic format ("my invoice *pdf*", "the *scan* of my bill"), and the
# words that join one to the paper it is of ("the pdf *of* my invoice", "my invoice *as* a pdf").
_FORMATS = english.words("electronic_formats")


def said_as_a_file(mentions: Sequence[Mention], m: Mention) -> bool:
    """ "fwd my invoice pdf", "my pdf invoice", "the pdf of my invoice", "my invoice as a
    pdf": a paper said with a word of an electronic format is its electronic file, whatever
    the verb ("bring my invoice" alone is the paper)."""

    def said(j: int) -> bool:
        return (
            0 <= j < len(mentions)
            and mentions[j].kind == "word"
            and bool(mentions[j].ids)
            and mentions[j].ids[0] in _FORMATS
        )

    def word(j: int, w: str) -> bool:
        return 0 <= j < len(mentions) and mentions[j].kind == "word" and mentions[j].ids == (w,)

    k = next((j for j, x in enumerate(mentions) if x is m), -1)
    if k < 0:
        return False
    if said(k + 1) and mentions[k + 1].start == m.end:
        return True  # "my invoice pdf"
    if said(k - 1) and mentions[k - 1].end == m.start:
        return True  # "my pdf invoice"
    if word(k + 1, "as") and said(k + 2):
        return True  # "my invoice as a pdf"
    j = k - 1
    if 0 <= j < len(mentions) and mentions[j].possessive and mentions[j].kind in ("self", "person"):
        j -= 1
    return word(j, "of") and said(j - 1)  # "the pdf of my invoice"


# "one" or "another" standing for one more of the thing just named
_ANOTHER = frozenset({"one", "another"})


def _ones_again(s: Scene, objects: list[Mention]) -> list[Mention]:
    """ "a tea for me and one for Sun Li", "make me a tea and another for Kit": "one" after
    an object, with whom it is for said right after it, is another of that object, for that
    person; each is a task of its own. A "one" with nobody named after it is read as
    before."""
    out = list(objects)
    for m in s.clause.mentions:
        if m.kind != "word" or m.ids[0] not in _ANOTHER or m.start in s.clause.modifiers:
            continue
        before = [o for o in out if o.end <= m.start]
        after = min((o.start for o in out if o.start > m.start), default=1 << 30)
        if not before or s.roles.recipient_between(m.end, after) is None:
            continue
        out.append(Mention("item", m.start, m.end, before[-1].ids, False, m.text))
    return sorted(out, key=lambda o: o.start)


def product_of_shape(office: Office, shape: OperationShape) -> str | None:
    return next((o.product for o in office.with_shape(shape)), None)
