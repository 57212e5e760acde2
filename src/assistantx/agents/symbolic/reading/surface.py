"""The message said again in the forms the later stages read: the reader's first stage after the
lexicon, before the screen.

People say one thing many ways ("Pat ok'd me using her stamp", "I'd murder a coffee", "Wang's
gone to lunch"); the screen, the readings and the frames read a few. Each step of ``STEPS``
rewrites one such way into the form they read ("Pat said I could use her stamp", "I need a
coffee", "Wang has gone to lunch"), or leaves the text as it is. The steps run in the table's
order, each on the text the one before it left: a later step reads the earlier ones' forms
(the round trip's heating before the approved uses; the sign-on taken off before the seating).
Adding a rewrite is one entry in the table, where its form is first needed.

Three steps may end the reading here (``Said.stop``): a placeholder ("bring me the thing from
the fridge": which thing is asked) and a placement beside a colleague's thing (declined); the
third, a colleague's paper asked to be emailed, is kept (``Said.emailed``) and asked only if
the screen leaves the message a request.

The per-office parts of the steps (the office's lent verbs, its rooms' round trips, its
keepers, ...) are built once per office (``Surface``); a parser that reads a name as the
requester answered gets the same parts with its own lexicon (``Surface.reading_with``).

Two steps are the screen's and a third leans on the frames' stage, run here, before the
screen: the colleagues' names are the screen's terms (``Terms.is_person_word``), "Sue on
reception needs a pen" is the screen's ``without_seating``, and the placeholder's question
uses the parts' question markers (``parts``, which reads with the readings). The reader's
layers contract names these imports (pyproject.toml, ``reader-passes-forward``).
"""

from __future__ import annotations

import copy
from collections.abc import Callable
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.abbreviations import undotted
from assistantx.agents.symbolic.reading.accepted_owner import accepted_owners
from assistantx.agents.symbolic.reading.also_sent import also_sent, paper_makers
from assistantx.agents.symbolic.reading.announced_borrowing import announced_borrowings
from assistantx.agents.symbolic.reading.approved_use import approved_uses
from assistantx.agents.symbolic.reading.asides import announced_list
from assistantx.agents.symbolic.reading.attributive_work import without_attributive_work
from assistantx.agents.symbolic.reading.authored import authored_things
from assistantx.agents.symbolic.reading.bare_room import BareRoom
from assistantx.agents.symbolic.reading.beside_a_thing import beside_a_thing
from assistantx.agents.symbolic.reading.booked_means import booked_means, send_out_means
from assistantx.agents.symbolic.reading.carrying_particles import carrying_particles
from assistantx.agents.symbolic.reading.caused_reason import caused_then_told
from assistantx.agents.symbolic.reading.chat_copula import spelled_are
from assistantx.agents.symbolic.reading.chat_shorthand import spelled_shorthand
from assistantx.agents.symbolic.reading.cleft_need import cleft_needs
from assistantx.agents.symbolic.reading.consequence_boundary import consequence_boundaries
from assistantx.agents.symbolic.reading.contracted_has_is import spelled_has_is
from assistantx.agents.symbolic.reading.described_items import (
    named_later,
    without_hyphened_description,
)
from assistantx.agents.symbolic.reading.due_service import DueService
from assistantx.agents.symbolic.reading.emailed_paper import (
    BRING,
    FORWARD,
    EmailedPaper,
    emailed_paper,
)
from assistantx.agents.symbolic.reading.excluded_owner import excluded_owners
from assistantx.agents.symbolic.reading.fallback import fallback
from assistantx.agents.symbolic.reading.file_subject import without_file_subject
from assistantx.agents.symbolic.reading.form_said_after import with_form_said_after
from assistantx.agents.symbolic.reading.format_reason import without_format_reasons
from assistantx.agents.symbolic.reading.group_member import group_member
from assistantx.agents.symbolic.reading.hedged_leave import hedged_leaves
from assistantx.agents.symbolic.reading.held_by_clause import held_by_clauses
from assistantx.agents.symbolic.reading.hurried_errand import hurried_errands
from assistantx.agents.symbolic.reading.hyphened_nouns import hyphened_nouns
from assistantx.agents.symbolic.reading.idioms import signature_put
from assistantx.agents.symbolic.reading.joined_gerunds import joined_gerunds
from assistantx.agents.symbolic.reading.joining_signs import signs_as_and
from assistantx.agents.symbolic.reading.kept_copies import kept_copies
from assistantx.agents.symbolic.reading.lacked_purpose import lacked_purposes
from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.material_work import material_work
from assistantx.agents.symbolic.reading.named_want import named_lacks, named_wants
from assistantx.agents.symbolic.reading.namesake_surnames import NamesakeSurnames
from assistantx.agents.symbolic.reading.near_possessive import near_possessives
from assistantx.agents.symbolic.reading.needed_done import needed_done
from assistantx.agents.symbolic.reading.numeral_one import numeral_ones
from assistantx.agents.symbolic.reading.obligation import PERSON_WORK
from assistantx.agents.symbolic.reading.outsider_pronoun import outsider_pronouns
from assistantx.agents.symbolic.reading.paper_parts_cut import without_paper_parts
from assistantx.agents.symbolic.reading.picked_form import PickedForm
from assistantx.agents.symbolic.reading.pictographs import without_pictographs
from assistantx.agents.symbolic.reading.place_doer import PlaceDoers
from assistantx.agents.symbolic.reading.placed_thing import placed_things
from assistantx.agents.symbolic.reading.placeholder_thing import (
    placeholder_question,
    says_a_placeholder,
)
from assistantx.agents.symbolic.reading.possessive_corrections import possessive_corrections
from assistantx.agents.symbolic.reading.possessive_place import possessive_places
from assistantx.agents.symbolic.reading.possessive_pronouns import possessive_pronouns
from assistantx.agents.symbolic.reading.poured_vessel import PouredVessel
from assistantx.agents.symbolic.reading.problem_remedy import ProblemRemedies
from assistantx.agents.symbolic.reading.products_listed import ProductsListed
from assistantx.agents.symbolic.reading.purpose import contracted_needs, wanting_idioms
from assistantx.agents.symbolic.reading.purpose_modifier import without_purpose_modifier
from assistantx.agents.symbolic.reading.question_preface import without_question_preface
from assistantx.agents.symbolic.reading.reported_request import reported_requests
from assistantx.agents.symbolic.reading.restored_pauses import restored_pauses
from assistantx.agents.symbolic.reading.role_appositive import without_role_appositives
from assistantx.agents.symbolic.reading.round_trip_work import RoundTripWork
from assistantx.agents.symbolic.reading.routed_work import RoutedWork
from assistantx.agents.symbolic.reading.run_off import RunOff
from assistantx.agents.symbolic.reading.screen.seated_where import without_seating
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.seated_subject import SeatedSubject
from assistantx.agents.symbolic.reading.sent_file import sent_files
from assistantx.agents.symbolic.reading.sent_for_service import sent_for_service
from assistantx.agents.symbolic.reading.signed_off import without_sign_off
from assistantx.agents.symbolic.reading.signed_on import initials, signed_on
from assistantx.agents.symbolic.reading.something_from import SomethingFrom
from assistantx.agents.symbolic.reading.speaker_lack import given_thing, speaker_lacks
from assistantx.agents.symbolic.reading.speech import content
from assistantx.agents.symbolic.reading.taken_for_keeper import kept_services, taken_for_keeper
from assistantx.agents.symbolic.reading.taken_for_service import taken_for_service
from assistantx.agents.symbolic.reading.thing_for_thing import ThingForThing
from assistantx.agents.symbolic.reading.thing_wants import without_thing_wants
from assistantx.agents.symbolic.reading.told_then_asked import told_then_asked
from assistantx.agents.symbolic.reading.tool_verbs import LentVerbs
from assistantx.agents.symbolic.reading.undone_service import UndoneService
from assistantx.agents.symbolic.reading.unmarked_possessive import marked_possessives
from assistantx.agents.symbolic.reading.verbless_conjunct import with_gapped_verbs
from assistantx.agents.symbolic.reading.when_clause import paused_when_clause
from assistantx.agents.symbolic.reading.withdrawn_thing import withdrawn_thing
from assistantx.agents.symbolic.reading.work_in_hand import work_as_purpose
from assistantx.agents.symbolic.reading.work_said_as_product import WorkSaidAsProduct
from assistantx.agents.symbolic.reading.worked_room import WorkedRoom
from assistantx.core import language, task_kinds
from assistantx.core.office import Office
from assistantx.core.task_schema import Evidence, TaskFrame

__all__ = ["STEPS", "Asked", "Said", "Step", "Surface"]

# A finite verb put after a phrase to read it in a subject's place ("frank needs").
_SUBJECT_PROBE = "needs"
# the cues of errands, sendings and buyings: a purpose said with one ("for the take") is none
# of the services a purpose's modifier names
_NOT_SERVICE_CUES = frozenset({"give", "send", "make", "produce"})


# the words before a supply said used up ("out of *any* paper")
_SUPPLY_ARTICLES = frozenset(
    {"a", "an", "any", "some", "the", "more", "all", "their", "his", "her"}
)


@dataclass(frozen=True, slots=True)
class Said:
    """The message said again: its text in the forms the later stages read; ``stop``: the
    reader's answer where a step ended the reading (a question, or a decline); ``emailed``:
    a colleague's paper asked to be emailed, where the office cannot make it electronic and
    the requester has not said yes to its being brought (asked once the screen is done)."""

    text: str
    stop: TaskFrame | None = None
    emailed: EmailedPaper | None = None
    # what a step took out and why, for the reading's evidence (a fallback kept back)
    notes: tuple[Evidence, ...] = ()


@dataclass(frozen=True, slots=True)
class Asked:
    """Who asks, and whether they already said yes to the restated reading."""

    requester: str
    confirmed: bool = False


# A step: the text as the steps before it left it → the text it leaves, or a ``Said`` where it
# ends the reading (``stop``) or keeps what is asked later (``emailed``).
Rewrite = Callable[["Surface", str, Asked], "str | Said"]


@dataclass(frozen=True, slots=True)
class Step:
    """One rewrite of the surface stage: its name and how (its example, a message it changes,
    is in the comment above it, and the tests run each on it)."""

    name: str
    rewrite: Rewrite


class Surface:
    """The surface stage of one office: ``STEPS`` with the office's parts they use."""

    def __init__(self, office: Office, lex: Lexicon, terms: Terms) -> None:
        self.office = office
        # the one-word names of the office's paper ("contract", "form"): what an outsider's
        # "their" may own, in the speaker's hand
        paper = office.signable_type()
        self.paper_words = frozenset(
            name for name, type_id in lex.items.items() if type_id == paper and " " not in name
        )
        self.lex = lex
        self.terms = terms
        self.is_person = terms.is_person_word  # whether a word names a colleague
        # the words of the names of the office's machines and places, and of its work, and
        # the one-word names of its things ("storybook"; never "register" of "finds register")
        self.machine_words = frozenset(
            w for name in (*lex.facilities, *lex.places, *lex.cue_words) for w in name.split()
        ) | frozenset(name for name in lex.items if " " not in name)
        self.steps = STEPS
        self.something_from = SomethingFrom(office)  # "something from the vending machine"
        # "a mug from the coffee machine": a listed vessel of what the machine pours
        self.poured_vessel = PouredVessel(office, frozenset(lex.items))
        self.products_listed = ProductsListed(office)  # "copy my document and a printout"
        self.work_as_product = WorkSaidAsProduct(office)  # "print it and take the print-out"
        self.picked_form = PickedForm(office)  # "Wang's file, the paper one": the paper
        # "my document is due a print": it needs one
        work = {w for k in task_kinds.person_kinds() for w in lex.cues.get(k, ())}
        self.due_service = DueService(office, {*lex.operation_nouns, *work})
        # "my forceps need a go in the autoclave": the autoclave's work on them
        self.routed_work = RoutedWork(office, lex.facilities, self.item_types)
        self.namesake_surnames = NamesakeSurnames(office)  # "Rosa - Álvarez, not Lindqvist"
        # "get it notarised" where the seal is a notary stamp: the seal's work, said as such
        self.lent_verbs = LentVerbs.from_office(
            office, {*lex.cue_words, *lex.items, *lex.name_words, *lex.people}
        )
        self.means = send_out_means(office)  # "courier": what the send-outs send by
        # "down to wrapping": a room said by the first word of its name
        self.bare_room = BareRoom(
            (loc.name for loc in office.locations),
            {*terms.thing_words, *(w for name in lex.facilities for w in name.split())},
        )
        # "get that done in the centrifuge room": the room's one machine that works on things
        self.worked_room = WorkedRoom(office)
        # "my badge isnt laminated, can you get it done": the work the participle names
        self.undone_service = UndoneService(office)
        # the forms of the office's services and colleagues' work ("photocopied", "signed")
        self.work_forms = terms.service_verbs | {
            f for w in PERSON_WORK for f in language.verb_forms(w)
        }
        self.run_off = RunOff(office)  # "run me off two copies": making copies
        self.round_trip = RoundTripWork(office)  # "take it to the kitchen and bring it back"
        # what the office's things are declared for ("measure"), for a lack of one
        self.purposes = frozenset(p.lower() for t in office.item_types for p in t.purposes)
        # the verbs whose -ing form before a noun only describes it ("his printing budget")
        self.work_lemmas = frozenset(
            w for op in office.operations for v in op.verbs for w in v.lower().split()[:1]
        ) | frozenset(w for words in lex.cues.values() for w in words if " " not in w)
        self.office_phrases = frozenset({*lex.items, *lex.facilities, *lex.places})
        # the words of the services and colleagues' work, any form, a purpose's modifier
        # ("for the signature comparisons"); not an errand's, a sending's or a buying's
        self.service_words = (
            frozenset(
                w
                for kind, words in lex.cues.items()
                if kind not in _NOT_SERVICE_CUES
                for w in words
                if " " not in w
            )
            | frozenset(
                form
                for op in office.operations
                for v in op.verbs
                for w in v.lower().split()[:1]
                for form in language.verb_forms(w)
            )
            | frozenset(lex.operation_nouns)
        )
        # "the carver on bench 3 needs ...": a colleague described by their workstation
        self.seated_subject = SeatedSubject.of_names(office, (*lex.items, *lex.facilities))
        # "the printer needs paper, grab some": the paper, for the printer
        self.thing_for_thing = ThingForThing(self.item_types, self.names_item)
        self.place_doers = PlaceDoers(office)  # "can laundry stitch it up?"
        self.remedies = ProblemRemedies(office)  # "... dog hair, got anything to sort it out?"
        self.keepers = kept_services(office)  # each keeper's services, by their verbs
        self.paper_makers = paper_makers(office)  # "print": a paper made from a file
        # the initials colleagues sign on with ("JL: ...")
        self.signs = initials(p.name for p in office.people)
        # the words of the colleagues' names and aliases, as written ("Ta", "Cheers")
        self.name_words = frozenset(
            w for p in office.people for n in (p.name, *p.aliases) for w in n.lower().split()
        )

    def reading_with(self, lex: Lexicon, terms: Terms) -> Surface:
        """The same steps and office parts, read with ``lex`` (a name read as the requester
        answered) and the screen's ``terms`` of it; nothing of this one changes."""
        other = copy.copy(self)
        other.lex = lex
        other.terms = terms
        other.is_person = terms.is_person_word
        return other

    def __call__(self, text: str, requester: str, *, confirmed: bool = False) -> Said:
        """``text`` through the steps, in order; at the first step that ends the reading, what
        it says."""
        asked = Asked(requester, confirmed)
        emailed: EmailedPaper | None = None
        notes: tuple[Evidence, ...] = ()
        for step in self.steps:
            out = step.rewrite(self, text, asked)
            if isinstance(out, str):
                text = out
            elif out.stop is not None:
                return Said(out.text, out.stop, emailed, notes)
            else:
                text, emailed = out.text, out.emailed or emailed
                notes += out.notes
        return Said(text, None, emailed, notes)

    # -- what the steps ask of the office's words ----------------------------------------
    def item_types(self, phrase: str) -> set[str]:
        """The item types ``phrase`` names."""
        return {i for m in self.lex.read(phrase).mentions if m.kind == "item" for i in m.ids}

    def names_something(self, phrase: str) -> bool:
        """Whether ``phrase`` names an item, a person or a place of the office."""
        named = ("item", "person", "place", "facility")
        return any(m.kind in named for m in self.lex.read(phrase).mentions)

    def opens_name(self, phrase: str) -> bool:
        """Whether ``phrase``'s first word opens a name of the office's things, people or
        places ("charging lead", "printing paper")."""
        named = ("item", "person", "place", "facility")
        return any(m.kind in named and m.start == 0 for m in self.lex.read(phrase).mentions)

    def work_verb(self, word: str) -> bool:
        """A bare verb of the office's own services or of a colleague's work ("fix",
        "sign"), for a thing sent to someone to have it done."""
        return word in self.lex.operation_words or word in PERSON_WORK

    def lacks(self, clause: str) -> bool:
        """Whether ``clause`` opens with the speaker's lack of an item ("I've run out of
        wipes")."""
        words = content([t.word for t in self.lex.tokens(clause)])
        return speaker_lacks(words, given_thing(self.lex))

    def used_up_supply(self, phrase: str) -> bool:
        """Whether ``phrase`` opens with (after an article) a supply the office gives anyone
        and that is used up in use: a consumable, or one a facility keeps for anyone ("zip
        ties down at the bay", "any paper")."""
        words = [t.word for t in self.lex.tokens(phrase)]
        while words and words[0] in _SUPPLY_ARTICLES:
            words = words[1:]
        for size in (3, 2, 1):
            type_id = self.lex.items.get(" ".join(words[:size])) if len(words) >= size else None
            if type_id is None:
                continue
            kind = self.office.item_type(type_id)
            supplied = any(s.type == type_id for f in self.office.facilities for s in f.supplies)
            return kind.kind in ("belonging", "product") and (kind.consumable or supplied)
        return False

    def kept_name(self, phrase: str) -> int:
        """How many words at ``phrase``'s start name a thing some facility keeps for anyone
        (a cupboard's handbooks), no file and no stuff; 0 where they name none."""
        raw = phrase.split()
        for size in (3, 2, 1):
            if len(raw) < size:
                continue
            words = [t.word for t in self.lex.tokens(" ".join(raw[:size]))]
            type_id = self.lex.items.get(" ".join(words))
            if type_id is None:
                continue
            kind = self.office.item_type(type_id)
            kept = any(f.supply(type_id) is not None for f in self.office.facilities)
            return size if kept and kind.physical and not kind.mass else 0
        return 0

    def names_item(self, phrase: str) -> bool:
        """Whether ``phrase`` is one of the office's items the office can give and nothing
        else ("pen")."""
        return given_thing(self.lex)([t.word for t in self.lex.tokens(phrase)])

    def as_file(self, phrase: str) -> str | None:
        """``phrase`` said as one of the office's electronic files: as it is where it ends in
        a name of one ("invoice spreadsheet", "deck"); with the file's name after it where it
        names nothing the office knows ("budget workbook": "budget workbook electronic file",
        a thing sent to the robot that is no item of the office is a file); None where it
        names another item, a person or a place ("the form I sent")."""
        lexed = self.lex.read(phrase)
        named = [m for m in lexed.mentions if m.kind != "word"]
        if not named:
            kind = self.office.file_type()
            return None if kind is None else f"{phrase} {self.office.item_type(kind).name}"
        last = named[-1]
        if last.kind != "item" or last.end != len(lexed.tokens):
            return None
        if not all(self.office.item_type(i).kind == "electronic" for i in last.ids):
            return None
        return phrase

    def authored(self, phrase: str) -> bool:
        """Whether ``phrase`` ends in a name of the office's files or papers (a personal thing
        one signs) and names nothing else ("sales slides", "report"): a thing a colleague
        makes and owns ("the lunch Wang made" is no such thing)."""
        lexed = self.lex.read(phrase)
        named = [m for m in lexed.mentions if m.kind != "word"]
        if len(named) != 1 or named[0].kind != "item" or named[0].end != len(lexed.tokens):
            return False
        types = [self.office.item_type(i) for i in named[0].ids]
        return all(t.kind == "electronic" or (t.kind == "personal" and t.signable) for t in types)

    def names_only(self, phrase: str, person: str) -> bool:
        """Whether ``phrase`` is a name of ``person`` and nothing else ("Jean-Luc")."""
        return self.people_of(phrase) == (person,)

    def people_of(self, phrase: str) -> tuple[str, ...]:
        """Every colleague ``phrase`` may name, where it names people and nothing else
        ("Frank": the Frank by his given name and the one by her surname)."""
        mentions = self.lex.scan(self.lex.tokens(phrase))
        if len(mentions) != 1 or mentions[0].kind != "person":
            return ()
        return tuple(mentions[0].ids)

    def name_of(self, person: str) -> str:
        """The colleague's name as the office spells it."""
        return self.office.person(person).name

    def one_name(self, phrase: str) -> bool:
        """Whether ``phrase`` is one colleague's name and nothing else ("Professor Zhang",
        "Ana"; not "yesterday Ana")."""
        return bool(self.people_of(phrase))

    def subject_name(self, phrase: str) -> bool:
        """Whether ``phrase`` is one colleague's name when a verb follows it: "frank" alone
        is the English word, "frank needs" is Frank (``name_reading``'s subject slot)."""
        tokens = self.lex.tokens(f"{phrase} {_SUBJECT_PROBE}")
        mentions = self.lex.scan(tokens)
        people = [m for m in mentions if m.kind == "person"]
        return (
            len(people) == 1
            and (people[0].start, people[0].end) == (0, len(tokens) - 1)
            and len(people[0].ids) == 1
        )


# -- the steps that end the reading, or keep what is asked later ------------------------------
def _fallback(s: Surface, text: str) -> str | Said:
    rest, notes = fallback(s.office, s.lex, text)
    return Said(rest, notes=tuple(notes)) if notes else text


def _placeholder(s: Surface, text: str, asked: Asked) -> str | Said:
    """Which thing is asked, where a placeholder is taken from a place of the office."""
    if says_a_placeholder(text):
        question = placeholder_question(s.office, s.lex.read(text))
        if question is not None:
            return Said(text, TaskFrame(requester=asked.requester, question=question))
    return text


def _emailed_paper(s: Surface, text: str, asked: Asked) -> str | Said:
    """A copy the office makes electronic ("scan it"), else the paper's electronic file where
    the office keeps one ("forward it"), else asked whether the paper is brought once the
    screen is done (a yes: brought)."""
    emailed = emailed_paper(s.lex, text, asked.requester)
    if emailed is None:
        return text
    if emailed.as_file:
        return emailed.with_verb(text, FORWARD)
    if emailed.operation_verb is not None or asked.confirmed:
        return emailed.with_verb(text, emailed.operation_verb or BRING)
    return Said(text, None, emailed)


def _remedy(s: Surface, text: str, asked: Asked) -> str | Said:
    """The remedy asked for a problem said before it: the one thing that fits, else which
    (ends the reading)."""
    remedy = s.remedies(text, s.item_types)
    if remedy.question is not None:
        return Said(text, TaskFrame(requester=asked.requester, question=remedy.question))
    # "got anything for my cut finger?": the complaint's remedy, the same way
    remedy = s.remedies.for_complaint(remedy.text, s.names_something)
    if remedy.none_fits:
        nothing = f"As far as I know, nothing here is for that. {s.terms.capabilities()}"
        return Said(text, TaskFrame(requester=asked.requester, decline=nothing))
    if remedy.question is not None:
        return Said(text, TaskFrame(requester=asked.requester, question=remedy.question))
    return remedy.text


def _undone_service(s: Surface, text: str, asked: Asked) -> str | Said:
    """The work a participle said before "get it done" names, else which is asked (ends the
    reading)."""
    text, question = s.undone_service(text)
    if question is not None:
        return Said(text, TaskFrame(requester=asked.requester, question=question))
    return text


def _beside_a_thing(s: Surface, text: str, asked: Asked) -> str | Said:
    """A placement beside a colleague's thing: one the robot cannot make, declined."""
    out_of_reach = beside_a_thing(text, s.is_person)
    if out_of_reach is not None:
        return Said(text, TaskFrame(requester=asked.requester, decline=out_of_reach))
    return text


# The surface stage, in the order its steps run.
STEPS: tuple[Step, ...] = (
    # the face is tone only
    # e.g. "bring me a pen and no marker 😩"
    Step("pictographs", lambda s, t, a: without_pictographs(t)),
    # a chat sign-off after a request only closes it: no thanks, no word of the request
    # e.g. "heat my lunch cheers"
    Step(
        "signed_off",
        lambda s, t, a: without_sign_off(t, s.lex.cue_words, s.name_words.__contains__),
    ),
    # an abbreviation's stop ends no sentence
    # e.g. "bring the book to Dr. Grace Huang"
    Step("undotted", lambda s, t, a: undotted(t)),
    # a pause left out between two clauses: put back
    # e.g. "my phone's on 3% can i borrow zhou's charger cable"
    Step("restored_pauses", lambda s, t, a: restored_pauses(t, s.lex.cue_words)),
    # an outsider's pronoun of whose: that outsider's, no colleague to ask about
    # e.g. "customer at counter 1 wants a copy of their contract, photocopy the one on my desk"
    Step("outsider_pronoun", lambda s, t, a: outsider_pronouns(t, s.one_name, s.paper_words)),
    # a clause of when run into its command: the comma put back
    # e.g. "when Wang is at the printer give him my file"
    Step("when_clause", lambda s, t, a: paused_when_clause(t, s.lex.cue_words)),
    # a second thing wanted only where the first cannot be had: kept back, never fetched too
    # e.g. "bring me a stapler, or if there isn't one, scissors"
    Step("fallback", lambda s, t, a: _fallback(s, t)),
    # a possessive pronoun for a thing named before: "her one", of whoever she is
    # e.g. "Wang and Zhou both sent slides. print hers and bring it to me"
    Step("possessive_pronouns", lambda s, t, a: possessive_pronouns(t)),
    # a preface that announces a question names nobody and asks nothing
    # e.g. "frank question: who's got a stapler I could use tomorrow?"
    Step("question_preface", lambda s, t, a: without_question_preface(t)),
    # a verb and its particle hyphened before a noun: one noun, no work asked
    # e.g. "could you bring me a pen for the warm-up drill?"
    Step("hyphened_nouns", lambda s, t, a: hyphened_nouns(t, s.terms.office_words)),
    # one of a group as a clause's subject: that one person, told of
    # e.g. "bring me a cup please, one of the interns took mine"
    Step("group_member", lambda s, t, a: group_member(t, s.terms.office_words)),
    # any owner's but one colleague's: that colleague's ruled out
    # e.g. "could u bring me a stapler? anyone's but Wang's", "can anyone but Wang lend me a pen"
    Step("excluded_owners", lambda s, t, a: excluded_owners(t, s.one_name)),
    # a colleague described by their workstation, as a need's subject: that colleague
    # e.g. "the carver on bench 3 needs a set square, could you bring him mine"
    Step("seated_subject", lambda s, t, a: s.seated_subject(t)),
    # a thing that needs another, asked for by "one": only the other is wanted
    # e.g. "the DI needs a fresh 9V battery, could you fetch me one?"
    Step("thing_for_thing", lambda s, t, a: s.thing_for_thing(t)),
    # an unknown paper needed with work done to it: the work asked, as with "get"
    # e.g. "need my certificate photocopied, the auditors want one"
    Step("needed_done", lambda s, t, a: needed_done(t, s.work_forms, s.names_something)),
    # a room said bare by the first word of its name, after "to": the room
    # e.g. "take the parcel down to meeting"
    Step("bare_rooms", lambda s, t, a: s.bare_room(t)),
    # a room named where work already spoken of is done: the room's one working machine
    # e.g. "my badge isnt laminated, can you get it done in the badge office"
    Step("worked_rooms", lambda s, t, a: s.worked_room(t)),
    # work said not done, then asked by a pro-form: the one operation the participle names,
    # else which (ends the reading)
    # e.g. "my badge hasn't been laminated yet, can you get it done"
    Step("undone_services", _undone_service),
    # which thing is asked, nothing picked (ends the reading)
    # e.g. "bring me the thing from the fridge"
    Step("placeholder", _placeholder),
    # the place does the work: the office's service there
    # e.g. "tore my apron, can laundry stitch it up?"
    Step(
        "place_doers",
        lambda s, t, a: s.place_doers(t),
    ),
    # a copy of a thing kept for anyone: one of those things
    # e.g. "could I get a copy of the staff handbook", "2 copies of the timetable pls"
    Step("kept_copies", lambda s, t, a: kept_copies(t, s.kept_name)),
    # copies made
    # e.g. "can you run off my report", "run a printout off my file"
    Step("run_off", lambda s, t, a: s.run_off(t)),
    # the tool's work said as the office's verb ("notarised" of a notary stamp: "sealed")
    # e.g. "get my contract notarized"
    Step("lent_verbs", lambda s, t, a: s.lent_verbs.read(t)),
    # a colleague's possessive typed without its apostrophe
    # e.g. "Grants off today, can you get Amaras spreadsheet"
    Step("unmarked_possessive", lambda s, t, a: marked_possessives(t, s.name_words, s.one_name)),
    # chat's shorthand of a function word ("hav", "frm")
    # e.g. "grab me some pliers, mine hav gone walkabout"
    Step("chat_shorthand", lambda s, t, a: spelled_shorthand(t, s.terms.office_words)),
    # chat's "r" for "are"
    # e.g. "mine r blunt, bring me a pen"
    Step("spelled_are", lambda s, t, a: spelled_are(t)),
    # heated: the room's work on it
    # e.g. "take my lunch to the kitchenette and bring it back"
    Step(
        "round_trip",
        lambda s, t, a: s.round_trip.read(t, s.item_types),
    ),
    # "Pat said I could use her stamp": a transfer
    # e.g. "Pat ok'd me using her stamp, bring it"
    Step("approved_uses", lambda s, t, a: approved_uses(t)),
    # the hope is politeness; what follows "if I" is asked
    # e.g. "i hope mark won't mind if i borrow his ruler"
    Step("hedged_leaves", lambda s, t, a: hedged_leaves(t)),
    # two requests
    # e.g. "would you mind laminating my badge, and getting my document signed"
    Step(
        "joined_gerunds",
        lambda s, t, a: joined_gerunds(t),
    ),
    # the content's form said next: Wang's file
    # e.g. "get me the rota numbers from Wang? She keeps them in a spreadsheet"
    Step(
        "form_said_after",
        lambda s, t, a: with_form_said_after(t, s.as_file, s.one_name),
    ),
    # my spreadsheet, Wang's file
    # e.g. "print the spreadsheet I sent"
    Step(
        "sent_files",
        lambda s, t, a: sent_files(t, s.is_person, s.as_file),
    ),
    # Zhang's slides, Wang's report
    # e.g. "can you send me the report Wang wrote"
    Step(
        "authored_things",
        lambda s, t, a: authored_things(t, s.is_person, s.authored),
    ),
    # Wang's file, Zhang's stapler
    # e.g. "I need the stapler Zhang's got"
    Step(
        "held_by_clauses",
        lambda s, t, a: held_by_clauses(t, s.is_person),
    ),
    # signed by Wang, back to me
    # e.g. "take my document to Wang to get it signed? need it back"
    Step(
        "taken_for_service",
        lambda s, t, a: taken_for_service(t, s.is_person),
    ),
    # why it is asked, not a second errand
    # e.g. "scan my document, customs want a pdf"
    Step(
        "format_reasons",
        lambda s, t, a: without_format_reasons(t, s.is_person),
    ),
    # what a record wants, why it is asked: no one to hand anything to
    # e.g. "bring me a stapler, the register wants everything bagged"
    Step(
        "thing_wants",
        lambda s, t, a: without_thing_wants(t, s.is_person, s.machine_words),
    ),
    # Wang does the work
    # e.g. "can my document go to Wang to be signed?"
    Step(
        "sent_for_service",
        lambda s, t, a: sent_for_service(t, s.is_person, s.work_verb),
    ),
    # sent by it
    # e.g. "book a courier for my parcel"
    Step("booked_means", lambda s, t, a: booked_means(t, s.means)),
    # Frank rehairs it, kept back
    # e.g. "my bow needs rehairing, take it to the store for Frank"
    Step(
        "taken_for_keeper",
        lambda s, t, a: taken_for_keeper(t, s.keepers, s.people_of, s.name_of),
    ),
    # "+" and "&" join as "and"
    # e.g. "print my file + a coffee"
    Step("signs_as_and", lambda s, t, a: signs_as_and(t)),
    # one listed thing withdrawn: the request without it
    # e.g. "bring me a stapler and a pen. actually forget the stapler"
    Step("withdrawn_thing", lambda s, t, a: withdrawn_thing(t, s.lex, s.item_types)),
    # the role only describes him
    # e.g. "get the duty manager, Wang, to sign my document"
    Step(
        "role_appositives",
        lambda s, t, a: without_role_appositives(s.lex, t),
    ),
    # the file passed on, a second errand
    # e.g. "print my report and also send it to Wang"
    Step(
        "also_sent",
        lambda s, t, a: also_sent(t, s.paper_makers),
    ),
    # a subject's "has"/"is", no owner
    # e.g. "Wang's gone to lunch"
    Step(
        "spelled_has_is",
        lambda s, t, a: spelled_has_is(t, lambda p: bool(s.item_types(p)), s.opens_name),
    ),
    # the "so" starts the ask, as after a comma
    # e.g. "my stapler's broken so can I borrow Wang's"
    Step(
        "consequence_boundaries",
        lambda s, t, a: consequence_boundaries(t),
    ),
    # the ask opens a sentence of its own, as after a stop
    # e.g. "my phone is on 2% pls get me a charging lead"
    Step(
        "told_then_asked",
        lambda s, t, a: told_then_asked(t),
    ),
    # the reason after a causative is a clause of its own, as after a comma
    # e.g. "get my swab tested the reading looked off on my kit"
    Step("caused_then_told", lambda s, t, a: caused_then_told(t)),
    # one more, Wang's
    # e.g. "coffee for me and 1 for Wang"
    Step("numeral_ones", lambda s, t, a: numeral_ones(t)),
    # the speaker's taking, asked of Wang
    # e.g. "I'm borrowing Wang's stapler for the afternoon"
    Step(
        "announced_borrowings",
        lambda s, t, a: announced_borrowings(t, s.is_person),
    ),
    # "and get a coffee for me"
    # e.g. "get Wang to sign my contract, and a coffee for me"
    Step(
        "gapped_verbs",
        lambda s, t, a: with_gapped_verbs(s.lex, t),
    ),
    # the plan is Wang's file
    # e.g. "Wang's budget plan? just send me the file"
    Step(
        "named_later",
        lambda s, t, a: named_later(s.lex, t),
    ),
    # the service's word only describes the thing: Wang's file
    # e.g. "get Wang to send me his printing budget"
    Step(
        "attributive_work",
        lambda s, t, a: without_attributive_work(t, s.work_lemmas, s.office_phrases),
    ),
    # the service's word only says what the purpose is; no signing asked
    # e.g. "Wang needs my stapler for the signature pages, can you take it to him"
    Step(
        "purpose_modifier",
        lambda s, t, a: without_purpose_modifier(t, s.service_words, s.office_phrases),
    ),
    # the description is no owner or part; Wang's file
    # e.g. "Wang's setting-out file"
    Step(
        "hyphened_description",
        lambda s, t, a: without_hyphened_description(s.lex, t),
    ),
    # the pages are the contract
    # e.g. "My contract pages need stamping"
    Step(
        "paper_parts",
        lambda s, t, a: without_paper_parts(s.lex, t),
    ),
    # what a colleague's file is about is no second thing
    # e.g. "Wang's pdf of the stapler"
    Step(
        "file_subject",
        lambda s, t, a: without_file_subject(s.lex, s.office, t),
    ),
    # a copy the office makes electronic, else asked later (kept: ``Said.emailed``)
    # e.g. "could I have Wang's report? just email it to me"
    Step("emailed_paper", _emailed_paper),
    # the form picks the office's file or paper
    # e.g. "Wang's document, the pdf one"
    Step("picked_form", lambda s, t, a: s.picked_form(t)),
    # to reception
    # e.g. "bring some up to reception"
    Step("carrying_particles", lambda s, t, a: carrying_particles(t)),
    # the hurrying verb's carrying idiom: a giving verb
    # e.g. "Wang needs a stapler, can you run mine over to her"
    Step("hurried_errands", lambda s, t, a: hurried_errands(t)),
    # the namesake the later words name
    # e.g. "with Yang - Lei, not Liu"
    Step(
        "namesake_surnames",
        lambda s, t, a: s.namesake_surnames(t),
    ),
    # the print-out of the printing just asked: its product, one printout
    # e.g. "print my file and take the print-out to Mao"
    Step(
        "work_as_product",
        lambda s, t, a: s.work_as_product(t),
    ),
    # the printout is printing's, a task of its own
    # e.g. "copy my document and a printout"
    Step(
        "products_listed",
        lambda s, t, a: s.products_listed(t),
    ),
    # the one kind of thing it makes
    # e.g. "something from the vending machine"
    Step(
        "something_from",
        lambda s, t, a: s.something_from(t),
    ),
    # a listed vessel of or from a machine of one poured thing: that thing in it
    # e.g. "a mug from the coffee machine please"
    Step("poured_vessels", lambda s, t, a: s.poured_vessel(t)),
    # the speaker's sign-on, no party to the request
    # e.g. "Lee here - bring me a pen"
    Step(
        "signed_on",
        lambda s, t, a: signed_on(
            t,
            s.one_name,
            signs=s.signs,
            is_speaker=lambda said: s.names_only(said, a.requester),
        ),
    ),
    # where Sue is, no part of the request (before the readings of "<name> would like",
    # which take the name next to the verb)
    # e.g. "Sue on reception needs a pen"
    Step(
        "seating",
        lambda s, t, a: without_seating(s.terms, t)[0],
    ),
    # a need of the thing for the work said, where the material is none of the office's
    # e.g. "need to cut some string for the parcel, got anything?"
    Step(
        "material_work",
        lambda s, t, a: material_work(
            t, s.purposes, s.lex.operation_words, s.names_something, s.item_types
        ),
    ),
    # a need of the thing the office keeps for that use
    # e.g. "Hal has nothing to write with"
    Step(
        "lacked_purposes",
        lambda s, t, a: lacked_purposes(t, s.purposes),
    ),
    # the thing that puts the problem said right, or which is asked (ends the reading)
    # e.g. "my coat is covered in dog hair, got anything to sort it out?"
    Step(
        "problem_remedy",
        _remedy,
    ),
    # the forms are why the pen is wanted
    # e.g. "I've got 40 forms to sign and no pen"
    Step(
        "work_as_purpose",
        lambda s, t, a: work_as_purpose(t, s.lacks, s.names_item, s.is_person),
    ),
    # Kit is after one
    # e.g. "Kit's after a torch"
    Step("contracted_needs", lambda s, t, a: contracted_needs(t)),
    # it needs one
    # e.g. "my document is due a print"
    Step("due_service", lambda s, t, a: s.due_service(t)),
    # put my forceps through the autoclave
    # e.g. "my forceps need a go in the autoclave"
    Step("routed_work", lambda s, t, a: s.routed_work(t)),
    # Zhang wants one
    # e.g. "Zhang would like a stapler"
    Step(
        "named_wants",
        lambda s, t, a: named_wants(t, s.one_name, s.subject_name),
    ),
    # Zhang needs some
    # e.g. "Wang has run out of paper"
    Step(
        "named_lacks",
        lambda s, t, a: named_lacks(t, s.one_name, s.subject_name, s.used_up_supply),
    ),
    # the count names nothing
    # e.g. "Two things: a pen and a stapler"
    Step("announced_list", lambda s, t, a: announced_list(t)),
    # I need a coffee
    # e.g. "I'd murder a coffee"
    Step("wanting_idioms", lambda s, t, a: wanting_idioms(t)),
    # I need a stapler
    # e.g. "it's a stapler I need", "what I need is a stapler"
    Step("cleft_needs", lambda s, t, a: cleft_needs(t)),
    # Mo signs it
    # e.g. "could Mo put her signature on it"
    Step("signature_put", lambda s, t, a: signature_put(t)),
    # a coffee for Zhang
    # e.g. "Zhang asked if someone could bring him a coffee"
    Step(
        "reported_requests",
        lambda s, t, a: reported_requests(t, s.one_name),
    ),
    # Wang's desk, so Wang gets it
    # e.g. "take this book to Wang's if he's in"
    Step(
        "possessive_places",
        lambda s, t, a: possessive_places(t, s.is_person),
    ),
    # which ruler, where it lies; Mark's, to me
    # e.g. "bring me the ruler at Mark's desk"
    Step(
        "placed_things",
        lambda s, t, a: placed_things(t, s.is_person),
    ),
    # at Mark's desk, not Mark's ruler fetched too
    # e.g. "put the ruler next to Mark's"
    Step(
        "near_possessives",
        lambda s, t, a: near_possessives(t, s.is_person),
    ),
    # a placement the robot cannot make (ends the reading)
    # e.g. "leave the calculator beside Will's lamp"
    Step("beside_a_thing", _beside_a_thing),
    # one stapler, Zhang's
    # e.g. "a stapler, not Wang's, Zhang's"
    Step(
        "possessive_corrections",
        lambda s, t, a: possessive_corrections(t, s.is_person, s.terms.is_one_person),
    ),
    # Lee's pen, asked of Lee
    # e.g. "i need a pen. Lee's is fine"
    Step(
        "accepted_owners",
        lambda s, t, a: accepted_owners(t, s.is_person),
    ),
)
