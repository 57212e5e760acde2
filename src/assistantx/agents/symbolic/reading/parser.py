"""The reader: free text → a typed task frame, or a clarifying question, by stages that pass
forward.

The frame says what to do (the task kinds of docs/task-semantics.md), with which item, whose,
for whom and by whom. Each stage takes the previous stage's immutable output and returns its
own; none reaches back into an earlier one:

0. ``surface``: the message said again in the forms the later stages read, by one ordered
   table of small named rewrites (``surface.STEPS``: "Pat ok'd me using her stamp" → "Pat
   said I could use her stamp"), reading phrases with the lexicon; a placeholder asked about
   or a placement beside a colleague's thing ends the reading there, and a colleague's paper
   asked to be emailed is kept to be asked once the screen is done (``Said``);
1. ``tokens``: the words (Unicode), with their punctuation;
2. ``lexicon``: typos corrected against the office's words, and the mentions of its people,
   items, facilities, places and task words (``Lexed``): the whole message and each of its
   pieces (sentences, and the comma parts of one) are read once;
3. ``speech_acts``: what each piece does (a request, a question, thanks, a wish, a withdrawal,
   a statement, someone else's need, a note, a condition), read once from its words and
   carried on the piece (``Acts``);
4. the screen's verdicts (``RequestScreen.verdicts``): each piece judged by the first rule of
   the table that matches (a withdrawal, a thanks, a wish, a question, a fact, a negation,
   something destructive or not offered), from the piece's ``lexed`` and ``acts`` (``Spoken``);
   then the request: what is left once the pieces that ask nothing are taken out, rewritten
   so the next stages can read it (``RequestScreen.request``: ``Request``);
5. ``readings``: the request's mentions read in their sentences, and the first doubt left (a
   name that may be a word, a name several people share) (``Readings``);
6. ``frames``: clauses, roles and task kinds → the tasks, or the question still open; then
   ``operations`` (the office's operation named where several share a shape, a send-out
   service's place) and ``unknown_items`` (a thing the office does not have, said as such);
7. the screen's decision (``RequestScreen.decide``: ``Screened``), then what is answered
   before anything else (the emailed paper's question, a recipient in doubt) and whether a
   restated or guessed reading is confirmed first;
8. ``doers``: who does the work (a service nobody has the tool for, a colleague named to make
   or do it; a keeper's work said plainly and read again);
9. ``screen.judge``: what the reader answers: the screen's own reply where the message asks
   nothing (or declines), else the frames with the screen's hints and evidence, a third
   person's need restated and asked ("Shall I ...?").

``parse`` runs them in this order, one line or two a stage.

The pieces' verdicts come before the readings because they decide what the request is: the
frames are read only from what is left once the withdrawn, negated, answered and stated pieces
are taken out; the decision on the message comes last, once the frames are read.

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
import functools
import re
import threading
import weakref
from collections import OrderedDict

from assistantx.agents.symbolic.reading.abbreviations import undotted
from assistantx.agents.symbolic.reading.antecedent import (
    WHICH_FILE,
    anothers_it,
    unanchored_it,
    with_antecedent,
)
from assistantx.agents.symbolic.reading.attributive_name import (
    attributive_name,
    with_attribute_chosen,
)
from assistantx.agents.symbolic.reading.back_reference_recipient import (
    chosen_recipient,
    recipient_in_doubt,
)
from assistantx.agents.symbolic.reading.bare_take import with_whose_and_whom
from assistantx.agents.symbolic.reading.chat_copula import spelled_are
from assistantx.agents.symbolic.reading.described_outsider import outsider_only
from assistantx.agents.symbolic.reading.doers import keepers_work, with_doers
from assistantx.agents.symbolic.reading.doubted_person import (
    chosen_of_two,
    doubted_recipient,
    either_doer,
)
from assistantx.agents.symbolic.reading.frames import (
    NOT_UNDERSTOOD,
    RESTATED,
    WHICH_ITEM,
    FrameReader,
    holder,
    named_items,
)
from assistantx.agents.symbolic.reading.group_answered import with_one_of_group
from assistantx.agents.symbolic.reading.headed_supply import headed_supply
from assistantx.agents.symbolic.reading.her_or_hers import with_her_or_you
from assistantx.agents.symbolic.reading.item_answered import with_item_answered
from assistantx.agents.symbolic.reading.keepers_place import from_keepers_place, keepers_places
from assistantx.agents.symbolic.reading.kept_roles import contradicts, said_roles
from assistantx.agents.symbolic.reading.lexicon import COMMON, Lexed, Lexicon, Mention, Reading
from assistantx.agents.symbolic.reading.machine_choice import (
    machine_choices,
    service_answered,
    service_question,
    with_service,
)
from assistantx.agents.symbolic.reading.machine_fetched import machine_fetched
from assistantx.agents.symbolic.reading.name_chosen import with_name_chosen
from assistantx.agents.symbolic.reading.named_once import the_one_named, the_ones_named
from assistantx.agents.symbolic.reading.needed_by import for_needer, needer
from assistantx.agents.symbolic.reading.offer_reply import LATER as OFFER_LATER
from assistantx.agents.symbolic.reading.offer_reply import LEFT as OFFER_LEFT
from assistantx.agents.symbolic.reading.offer_reply import (
    OfferReply,
    not_known,
    offer_reply,
    plain_stance,
)
from assistantx.agents.symbolic.reading.operation_answered import operation_answered
from assistantx.agents.symbolic.reading.operations import (
    OUT_OR_IN,
    WHERE_TO,
    OperationChooser,
    colleague_named,
)
from assistantx.agents.symbolic.reading.parts import (
    asked_part,
    items_named,
    names_work,
    operation_left_out,
    unread_part,
)
from assistantx.agents.symbolic.reading.possessive_choice import with_possessive_chosen
from assistantx.agents.symbolic.reading.readings import HERE_NOT_OUTSIDE, MentionReader, Readings
from assistantx.agents.symbolic.reading.room_receiver import (
    own_thing_unplaced,
    room_receiver,
    rooms_taken_to,
)
from assistantx.agents.symbolic.reading.room_service import (
    own_thing_to_room,
    room_service_answered,
    room_service_question,
    room_services,
    with_room_service,
)
from assistantx.agents.symbolic.reading.said_kept import kept_where_said
from assistantx.agents.symbolic.reading.screen import RequestScreen
from assistantx.agents.symbolic.reading.screen.cut_off import completed
from assistantx.agents.symbolic.reading.screen.findings import Request, Screened, Spoken
from assistantx.agents.symbolic.reading.screen.judge import answered_frame, judge
from assistantx.agents.symbolic.reading.screen.kept import chosen_kept
from assistantx.agents.symbolic.reading.screen.one_of_several import chosen_of_several
from assistantx.agents.symbolic.reading.screen.owned_head import with_owned_chosen
from assistantx.agents.symbolic.reading.screen.pronoun_subject import with_subject_answered
from assistantx.agents.symbolic.reading.screen.recipients_doing import ASIDES
from assistantx.agents.symbolic.reading.screen.unknown_work import answered_with
from assistantx.agents.symbolic.reading.several_owners import (
    any_owner_meant,
    unowned_mine,
    with_owner,
)
from assistantx.agents.symbolic.reading.stated_source import from_stated_source, stated_sources
from assistantx.agents.symbolic.reading.surface import Said, Surface
from assistantx.agents.symbolic.reading.time_clause import without_time_clauses
from assistantx.agents.symbolic.reading.unknown_items import (
    PROPOSED,
    category_asked,
    one_choice,
    proposal,
    unknown_item,
    with_choice,
)
from assistantx.agents.symbolic.reading.unlisted_thing import (
    left_behind,
    unlisted_thing,
    variety_of,
    vessel_of,
)
from assistantx.agents.symbolic.reading.unnamed_carried import unnamed_carried
from assistantx.agents.symbolic.reading.used_up import declined_use_up
from assistantx.agents.symbolic.reading.usual_thing import usual_asked
from assistantx.agents.symbolic.reading.work_unsaid import (
    WHICH_WORK,
    with_fetch_or_work,
    with_work,
)
from assistantx.core import language, task_kinds
from assistantx.core.office import Office
from assistantx.core.task_schema import Task, TaskFrame, TaskKind

# The words of a place phrase that named where a thing should be ("gloves *at* the station").
_AT_PLACE = ("at", "in", "on")
# The words of an answer to "send it out, or bring it to Bill?" that choose the hand-over.
_INSIDE_WORDS = frozenset(
    {"bring", "hand", "give", "take", "deliver", "desk", "him", "her", "them", "here", "inside"}
)

__all__ = [
    "NOT_UNDERSTOOD",
    "InstructionParser",
    "Task",
    "TaskFrame",
    "TaskKind",
    "shared_parser",
]


# One parser per office for the reasoner, the consent check and the request recognizer:
# building one reads the office into a lexicon (a tenth to a third of a CPU-second), and each
# built its own, the last two on the event loop at their first use (48 and 129 ms under
# load). Rebuilt when the task kinds' table changed since (``task_kinds.add``).
_SHARED: weakref.WeakKeyDictionary[
    Office, tuple[tuple[task_kinds.KindSpec, ...], InstructionParser]
] = weakref.WeakKeyDictionary()
_SHARED_LOCK = threading.Lock()  # the service's warm-up thread builds it; the loop may wait


FRAMES_KEPT = 256  # the shared parser's latest frames, remembered


def shared_parser(office: Office) -> InstructionParser:
    """The parser of ``office`` its readers share (parsing changes nothing in it). It also
    remembers its latest ``FRAMES_KEPT`` frames (``parse_with_answers``): the reasoner and
    the consent check read the same request alike, and a request said again (by anyone, in
    the same words) is not read again; the frames are shared, so nobody changes one."""
    kinds = task_kinds.kinds()
    with _SHARED_LOCK:
        kept = _SHARED.get(office)
        if kept is None or kept[0] != kinds:
            parser = InstructionParser(office)
            parser._remembered = OrderedDict()
            kept = _SHARED[office] = (kinds, parser)
        return kept[1]


class InstructionParser:
    """Parses instructions against one office."""

    def __init__(self, office: Office) -> None:
        self.office = office
        self.lex = Lexicon.from_office(office)
        self.screen = RequestScreen(office, self.lex)
        self.readings = MentionReader(office, self.lex)
        self.frames = FrameReader(office)
        self.operations = OperationChooser(office)
        self.surface = Surface(office, self.lex, self.screen.terms)  # the message said again
        # The frames read, by (text, requester, answers): the shared parser's only.
        self._remembered: OrderedDict[tuple[str, str, tuple[str, ...]], TaskFrame] | None = None

    # -- public --------------------------------------------------------------------------
    def parse(
        self,
        text: str,
        requester: str,
        *,
        confirmed: bool = False,
        sent_out: bool = False,
        to_self: bool = False,
        destination: str | None = None,
        any_owner: bool = False,
    ) -> TaskFrame:
        """The frame of a request: its pieces lexed and screened (speech acts, withdrawn,
        negated, destructive, facts, unsupported services), the tasks read from what is left,
        then judged. ``confirmed``: the requester already said yes to the restated reading;
        ``sent_out``: a send-out to a colleague's name is meant to leave the office;
        ``to_self``: the requester answered "me" to whom their own item goes;
        ``destination``: their answer to where a send-out goes (a place outside, as said);
        ``any_owner``: they answered "Whose X do you mean?" with any owner ("anyone's")."""
        said = self.surface(text, requester, confirmed=confirmed)  # said in the forms read
        if said.stop is not None:  # a placeholder asked about, a placement declined
            return said.stop
        spoken = self.screen.verdicts(said.text, requester)  # stages 1 to 4, piece by piece
        request = self.screen.request(spoken)
        # "... before I sign off tonight, can you sort it?": when, not a signing asked for
        # (after the screen, which reads "before he notices" as taking behind one's back)
        asked = without_time_clauses(
            request.text, self.screen.terms.is_person_word, self._task_or_machine_word
        )
        frame = self._frame(
            spoken.msg.lexed, asked, requester, sent_out, to_self, destination, any_owner
        )
        decided = self._decide(said, spoken, request, frame, requester)
        if isinstance(decided, TaskFrame):
            return _noted(decided, said)
        whole = spoken.msg.lexed
        frame = with_doers(self.office, whole, frame, requester, confirmed=confirmed)
        plain = keepers_work(self.office, whole, frame, requester)
        if plain is not None:
            return self.parse(plain, requester, confirmed=confirmed)
        return _noted(judge(self.office, decided, frame, requester, confirmed=confirmed), said)

    def _decide(
        self, said: Said, spoken: Spoken, request: Request, frame: TaskFrame, requester: str
    ) -> Screened | TaskFrame:
        """The screen's decision on the message (stage 7), then what is answered before the
        doers are checked: the screen's own reply where the message asks nothing, the
        emailed paper's question, a recipient in doubt; else the decision, asking to confirm
        a reading restated or guessed (``confirm``)."""
        screened = self.screen.decide(spoken, request)
        if screened.answered:
            return answered_frame(screened, requester)
        if said.emailed is not None:
            return TaskFrame(requester=requester, question=said.emailed.question)
        doubt = recipient_in_doubt(self.lex, said.text, requester)
        if doubt is not None:
            # "could I have Wang's plan? Zhang needs the file": Wang's, for me or for Zhang?
            return TaskFrame(requester=requester, question=doubt.question)
        attribute = attributive_name(self.office, self.lex, spoken.msg.lexed, requester)
        if attribute is not None:
            # "bring me the amber accord" where Amber owns one: hers, or an amber one?
            return TaskFrame(requester=requester, question=attribute)
        if any(e.meaning == RESTATED for e in frame.evidence):
            # "print my file and a coffee": the coffee may be a second request, or not
            screened.confirm = True
        # the guess is looked for in the request's own words too: a thing named in a reason
        # beside it ("... tea keeps getting spilled on it") is context, and must not hide
        # that the request's own thing was guessed (the badge was laminated unasked)
        left = self.lex.read(request.text).mentions
        if any(m.guessed for m in (*_said_mentions(spoken), *left)):
            # "shred my questionnaire" (the requester's words, not a rewrite of the screen's):
            # "Shall I shred your document for you?"
            screened.confirm = True
        return screened

    def _task_or_machine_word(self, word: str) -> bool:
        """A task word, or the head of a machine's name: "before I go near the grinder" says
        when, never the grinder's work asked for."""
        return self._task_word(word) or word in self._machine_heads

    @functools.cached_property
    def _machine_heads(self) -> frozenset[str]:
        return frozenset(phrase.split()[-1] for phrase in self.lex.facilities if phrase)

    def _task_word(self, word: str) -> bool:
        """Whether ``word`` is one of the office's task words or a form of one ("prints")."""
        cues = self.lex.cue_words
        return word in cues or bool(language.verb_lemmas(word) & cues)

    def _frame(
        self,
        whole: Lexed,
        request: str,
        requester: str,
        sent_out: bool,
        to_self: bool = False,
        destination: str | None = None,
        any_owner: bool = False,
    ) -> TaskFrame:
        """The tasks of the request the screen left (``request``), read from its readings;
        ``whole`` is the whole message as the lexicon read it for the screen: who has an item
        now is said anywhere, also in a statement the screen set aside ("P lent me her
        ruler. Please return it to her; it's on my desk")."""
        lexed = self.lex.read(request)  # the rewritten request, read once; later stages get it
        usual = usual_asked(self.office, lexed)
        if usual is not None:  # "bring me the usual from stores": which thing, asked
            return TaskFrame(requester=requester, question=usual)
        readings = self.readings.read(lexed, requester)
        frame = self.frames.frame(
            readings,
            requester,
            holder(whole, requester),
            named_items(whole, requester),
            to_self=to_self,
            any_owner=any_owner,
            kept_said=kept_where_said(self.office, whole.tokens, whole.mentions),
            kept_from=kept_where_said(self.office, whole.tokens, whole.mentions, taken_from=True),
            named_once=the_one_named(whole, requester),
            message_named=the_ones_named(whole, requester),
            outsider_said=outsider_only(whole, requester),
        )
        # only where the reader would act, or would pick a facility's service: a question
        # it asks already ("take that to Wang": what should I do?) stays the one asked
        acts = bool(frame.tasks) or any(m.kind == "facility" for m in whole.mentions)
        carried = unnamed_carried(whole) if acts else None
        if carried is not None:  # "take this over to the printer": what "this" is, asked
            return TaskFrame(requester=requester, question=carried)
        if frame.understood:
            # "a lemonade from the vending machine and Wang's stapler": the unlisted variety of
            # the one thing the facility makes is that thing, beside the other objects too
            as_made = self._variety_beside(readings, frame, request)
            if as_made is not None:
                return self._frame(
                    whole, as_made, requester, sent_out, to_self, destination, any_owner
                )
            # "need cable ties, the art room has some": the one kept where the requester said
            # (said anywhere, also in a statement the screen set aside)
            sources = stated_sources(self.office, whole.tokens, whole.mentions)
            tasks, unclear_source = from_stated_source(self.office, frame.tasks, sources)
            if unclear_source is not None:
                return TaskFrame(requester=requester, question=unclear_source)
            frame = frame.model_copy(update={"tasks": tasks})
            # "get a tube from Priya's cabinet": the supply kept where Priya looks after it
            places = keepers_places(self.office, whole.tokens, whole.mentions, requester)
            tasks, unclear_place = from_keepers_place(self.office, frame.tasks, places)
            if unclear_place is not None:
                return TaskFrame(requester=requester, question=unclear_place)
            frame = frame.model_copy(update={"tasks": tasks})
            unclear = unanchored_it(self.office, whole, frame.tasks)
            if unclear is not None:  # "print it", nothing said that "it" could be
                return TaskFrame(requester=requester, question=unclear)
            whose = anothers_it(
                self.office, whole, frame.tasks, requester, the_one_named(whole, requester)
            )
            if whose is not None:  # "Tam's chart is done, print it": Tam's, never mine
                tasks = [t.model_copy(update={"owner": whose}) for t in frame.tasks]
                frame = frame.model_copy(update={"tasks": tasks})
            frame = self.operations.choose(
                frame,
                lexed,
                readings.outside,
                sent_out=sent_out,
                destination=destination,
                # an errand's hurrying verb, and a word of a place outside ("the Leeds *Print*
                # Works"): neither is a service's verb
                errands=readings.errands | readings.proper,
                whole=whole,
            )
            frame = _each_errand_once(frame)
            # "print my file? it's Fern who needs the hard copy, not me": for Fern
            frame = for_needer(frame, needer(whole, requester, self.lex.name_words))
            # "Zhang needs my stapler. take it to the meeting room": Zhang gets it there
            receiver = room_receiver(whole, requester)
            frame = for_needer(frame, receiver)
            frame = declined_use_up(self.office, frame)
            # "Mao or Sun can do it": either stamps it, and it comes back to the requester
            frame = frame.model_copy(update={"tasks": either_doer(whole, frame.tasks, requester)})
            doubted = doubted_recipient(self.office, whole, frame.tasks, requester)
            if doubted is not None:  # "to Wei... or was it Wang?": whom is asked
                return TaskFrame(requester=requester, question=doubted)
            own = None if to_self else own_thing_to_room(frame, requester)
            served = (
                room_services(self.office, readings.tokens, readings.mentions, own)
                if own is not None
                else None
            )
            if served is not None and len(served[1]) == 1:
                # "take my wheel down to wrapping", one service there works on cheeses: that
                # service, the wheel back to the requester
                return self._frame(
                    whole,
                    with_room_service(self.office, request, served[1][0]),
                    requester,
                    sent_out,
                    to_self,
                    destination,
                    any_owner,
                )
            if own is not None and served is not None and served[1]:
                # several: which is asked, never the thing handed back to the requester
                question = room_service_question(self.office, own, *served)
                return TaskFrame(requester=requester, question=question)
            received = frozenset({receiver} if receiver is not None else ())
            unread = (
                unread_part(self.office, readings, frame, received) if frame.understood else None
            )
            if unread is not None:  # a part no task carries: asked, never dropped
                frame = TaskFrame(requester=requester, question=unread)
            elif not to_self and rooms_taken_to(readings.tokens, readings.mentions):
                # "take my stapler to <a room>" with nobody there found: never back to me
                unplaced = own_thing_unplaced(self.office, frame, requester)
                if unplaced is not None:
                    frame = TaskFrame(requester=requester, question=unplaced)
        elif (
            frame.question is not None
            and _asks_who(frame.question)
            and not _whom_meant(frame.question)
        ):
            # "my proof needs a read, can you sort it", the read not understood: which work
            # is meant is asked, not who gets the proof (it comes back to the requester)
            named = items_named(readings)
            left_out = operation_left_out(self.office, readings, set(), named)
            if left_out is not None:
                frame = TaskFrame(requester=requester, question=left_out)
        if not frame.tasks and (frame.question is not None or frame.decline is not None):
            # "bring me the shredder": a machine stays where it is; what to do with it is asked
            machine = machine_fetched(self.office, readings.tokens, readings.mentions)
            if machine is not None:
                return TaskFrame(requester=requester, question=machine)
        if frame.question == NOT_UNDERSTOOD:
            terms, tokens, mentions = self.screen.terms, readings.tokens, readings.mentions
            choices = machine_choices(self.office, tokens, mentions, requester)
            if choices:  # "put this through the printer": "Print your file, or copy ...?"
                return TaskFrame(requester=requester, question=service_question(choices))
            left = left_behind(tokens, mentions)
            if left is not None:  # "the thing I left at the printer": which thing is asked
                return TaskFrame(requester=requester, question=left)
            only = one_choice(terms, tokens, mentions)
            if only is not None:
                # "something to write with" where a pen is the office's one such thing: no
                # "Which would you like: pen?"; the pen is what was asked for, if nobody's
                # (a supply, a product; a colleague's is offered: "I can get you ...")
                said = with_choice(request, only[1], only[0])
                if said is not None and self._anyones(only[0]):
                    return self._frame(
                        whole, said, requester, sent_out, to_self, destination, any_owner
                    )
                return TaskFrame(requester=requester, question=proposal(only[0]))
            which = category_asked(terms, tokens, mentions)  # "a drink": tea or cocoa?
            unknown = unknown_item(terms, tokens, mentions) if which is None else None
            unlisted = unlisted_thing(mentions)
            if which is None and unknown is None and unlisted is not None:
                # "a flat white from the coffee machine": a variety of the one thing it makes
                variety = variety_of(self.office, mentions, unlisted[1])
                # "a flask of the dewar": a vessel the office lacks, of what the dewar makes
                variety = variety or vessel_of(self.office, mentions, unlisted[1])
                said = with_choice(request, *variety) if variety is not None else None
                # "a blade from the cupboard" where it keeps scalpel blades: those
                headed = headed_supply(self.office, *unlisted) if said is None else None
                if headed is not None:
                    said = with_choice(request, unlisted[0].split(), headed)
                if said is not None:
                    return self._frame(
                        whole, said, requester, sent_out, to_self, destination, any_owner
                    )
                # "50 ml of chloroform from the chem store": declined by name, nothing swapped
                unknown = self._not_there(*unlisted)
            if which is not None:
                frame = TaskFrame(requester=requester, question=which)
            elif unknown is not None:
                frame = TaskFrame(requester=requester, decline=unknown)
        return frame

    def _variety_beside(self, readings: Readings, frame: TaskFrame, request: str) -> str | None:
        """The request with an unlisted thing asked for from a facility ("a coke from the
        vending machine") said as the one product of that facility it is a variety of, where
        the frames read the request's other objects and dropped that one; None otherwise."""
        unlisted = unlisted_thing(readings.mentions)
        if unlisted is None:
            return None
        made = set(self.office.facility(unlisted[1]).products)
        if any(t.kind == "produce" and t.item in made for t in frame.tasks):
            return None
        variety = variety_of(self.office, readings.mentions, unlisted[1])
        said = with_choice(request, *variety) if variety is not None else None
        return said if said is not None and said != request else None

    def _not_there(self, thing: str, facility_id: str) -> str:
        """The decline of a thing the facility named does not make or keep, with what it does."""
        facility = self.office.facility(facility_id)
        offers = [self.office.item_type(t).name for t in facility.products]
        offers += [self.office.item_type(s.type).name for s in facility.supplies]
        has = f" It has {' and '.join(dict.fromkeys(offers))}." if offers else ""
        return (
            f"Sorry, there is no {thing} at the {facility.name} that I know of, so I can't "
            f"get you any.{has}"
        )

    def _with_one_choice(self, text: str, requester: str) -> str | None:
        """The request with its category words replaced by the office's one such thing."""
        request = self.screen.request(self.screen.verdicts(text, requester))
        readings = self.readings.read(self.lex.read(request.text), requester)
        only = one_choice(self.screen.terms, readings.tokens, readings.mentions)
        return with_choice(text, only[1], only[0]) if only is not None else None

    def _anyones(self, name: str) -> bool:
        """Whether the item type so named is nobody's (a supply kept for anyone, or a thing
        the office makes): the one thing of a category is then simply what was asked for; a
        colleague's belonging is offered first ("I can get you ...")."""
        return any(
            t.name == name and (t.kind == "product" or self.office.supplier(t.id) is not None)
            for t in self.office.item_types
        )

    def parse_with_answers(self, text: str, requester: str, answers: list[str]) -> TaskFrame:
        remembered = self._remembered
        if remembered is None:
            return self._parse_with_answers(text, requester, answers)
        key = (text, requester, tuple(answers))
        frame = remembered.get(key)
        if frame is None:
            frame = remembered[key] = self._parse_with_answers(text, requester, answers)
            if len(remembered) > FRAMES_KEPT:
                remembered.popitem(last=False)
        else:
            remembered.move_to_end(key)
        return frame

    def _parse_with_answers(self, text: str, requester: str, answers: list[str]) -> TaskFrame:
        """Re-parse after clarifying answers: a yes or no to "Shall I ...?", the reading the
        answer chose, else the original with the answers; the answer alone only when the
        question asked for the whole request. A reply answers the question asked: it never
        starts a request of its own ("Yes, I have a stapler" to "Shall I bring you one?" is
        a no, not a yes nor a new request for a stapler)."""
        text = spelled_are(undotted(text))
        answers = [spelled_are(undotted(a)) for a in answers]
        frame = self.parse(text, requester)
        for answer in answers:
            if frame.understood or frame.decline is not None:
                break
            if frame.question is not None and frame.question.startswith(OUT_OR_IN):
                frame = self._out_or_in(text, requester, answer, frame)
                continue
            op_id = operation_answered(self.office, frame.question or "", answer)
            if op_id is not None:  # "Which do you mean: print or large-format plot?" "plot"
                frame = self._with_operation(op_id).parse(text, requester)
                continue
            attributed = with_attribute_chosen(self.lex, text, frame.question or "", answer)
            if attributed is not None:  # "the amber accord" → "Amber Shaw's, or ...?" "hers"
                text, frame = attributed, self.parse(attributed, requester)
                continue
            chose = with_possessive_chosen(self.lex, text, frame.question or "", answer)
            if chose is not None:  # "grab bills ruler" → "Bill's ruler, or any?" → "any"
                text, frame = chose, self.parse(chose, requester)
                continue
            her_said = with_her_or_you(text, frame.question or "", answer)
            if her_said is not None:  # "Should Zhang Wei's lunch go to Zhang Wei, or to you?"
                text, frame = her_said, self.parse(her_said, requester)
                continue
            one_of = with_one_of_group(self.lex, text, frame.question or "", answer)
            if one_of is not None:  # "Should the stapler go to Wang, or to Sun?" "Wang"
                text, frame = one_of, self.parse(one_of, requester)
                continue
            if frame.question is not None and frame.question.startswith(PROPOSED):
                # "I can get you a pen. Would you like that?": yes asks for the pen
                taken = plain_stance(answer)
                offered = self._with_one_choice(text, requester) if taken == "yes" else None
                if offered is not None:
                    text, frame = offered, self.parse(offered, requester)
                    continue
                if taken == "no":
                    return TaskFrame(
                        requester=requester,
                        decline="OK, I won't do anything, then.",
                        decline_outcome="done",
                    )
            if frame.question is not None and "Shall I" in frame.question:
                screened = self.screen.screen(text, requester)
                if not screened.offer:
                    # "anything for my sore hands?" is asked as "got a hand cream?" (the
                    # surface's remedy): the offer is the one the reading asked
                    restated = self.surface(text, requester)
                    if restated.stop is None and restated.text != text:
                        screened = self.screen.screen(restated.text, requester)
                offer = screened.offer
                if offer and screened.outcome != "done" and not_known(answer):
                    # "Shall I get you an ordinary coffee instead?" "Sorry, I don't know
                    # more than I wrote.": no answer, so the question stays open (asked
                    # again, then "I could not understand"), never dropped as a no
                    continue
                yes_no: OfferReply = plain_stance(answer)
                if offer:  # an answer was given already: only a plain yes for now acts
                    yes_no = offer_reply(self.screen.terms.acts, answer)
                    left = {"later": OFFER_LATER, "unclear": OFFER_LEFT}.get(yes_no)
                    if left is not None:
                        return TaskFrame(requester=requester, decline=left, decline_outcome="done")
                if yes_no == "yes":
                    frame = self.parse(offer or text, requester, confirmed=True)
                    continue
                if yes_no == "no":
                    return TaskFrame(
                        requester=requester,
                        decline="OK, I won't do anything, then.",
                        decline_outcome="done",
                    )
            if frame.question is not None and HERE_NOT_OUTSIDE in frame.question:
                # "fax it to the green room" → "Where should I fax it to?" → "the bank": the
                # answer takes the place of the office's own place, read by the same stage
                said = self.readings.read(self.lex.read(text)).outside
                place = re.sub(r"^\s*to\s+", "", answer.strip(), flags=re.IGNORECASE)
                if re.match(r"be\b", place, flags=re.IGNORECASE):
                    continue  # "to be dry cleaned": the work again, no place; still asked
                if said is not None and said.phrase and said.phrase in text:
                    text = text.replace(said.phrase, place.rstrip(" .!?"), 1)
                    frame = self.parse(text, requester)
                    continue
            subject = with_subject_answered(
                self.screen.terms, text, requester, frame.question or "", answer
            )
            if subject is not None:  # "she needs ..." → "Who do you mean by 'she'?" → "Rose"
                text, frame = subject, self.parse(subject, requester)
                continue
            chosen_name = with_name_chosen(self.lex, text, frame.question or "", answer)
            if chosen_name is not None:  # "Who do you mean by 'Tomás': ...?" "Tomás Herrera"
                text, frame = chosen_name, self.parse(chosen_name, requester)
                continue
            picked = with_owned_chosen(
                self.screen.terms, text, requester, frame.question or "", answer
            )
            if picked is not None:  # "my lamp" → "your inspection lamp or ...?" → "the desk one"
                text, frame = picked, self.parse(picked, requester)
                continue
            if frame.question is not None and frame.question.startswith(WHICH_FILE):
                # "print it" → "Which file do you mean by 'it'?" → "Kwame's shoot": the
                # answer is the request's own object, in the place of its "it"
                asked = self.screen.terms.named(self.lex.read(frame.question), "item")
                kind = self.office.item_type(asked[0]).name if len(asked) == 1 else ""
                meant = self.parse(with_antecedent(text, answer, kind), requester)
                whose = {
                    p
                    for m in self.lex.read(answer).mentions
                    if m.kind == "person" and m.possessive
                    for p in m.ids
                }
                if whose and not whose & {t.owner for t in meant.tasks}:
                    continue  # "Kwame's" read as someone else's file: asked, never guessed
                text, frame = with_antecedent(text, answer, kind), meant
                continue
            served = self._machine_chosen(text, requester, frame.question, answer)
            if served is not None:  # "Print your file, or copy your document?" "Copy."
                text, frame = served, self.parse(served, requester)
                continue
            fetched_or = with_fetch_or_work(self.office, text, frame.question or "", answer)
            if fetched_or is not None:  # "Shall I bring you your costume, or have it mended?"
                text, frame = fetched_or, self.parse(fetched_or, requester)
                continue
            if frame.question is not None and frame.question.startswith(WHICH_WORK):
                # "do something with my prep" → "vacuum seal or blast chill?" → "vacuum
                # seal": the work said, done to the item; anything else is asked again
                meant = self.parse(with_work(text, answer), requester)
                # "sign": the work said, its own question next ("Who should sign ...?")
                if meant.understood or not (meant.question or WHICH_WORK).startswith(WHICH_WORK):
                    text, frame = with_work(text, answer), meant
                continue
            named = with_item_answered(self.lex, self.office, text, frame.question or "", answer)
            if named is not None:  # "send my signed statement …" "The document.": that one
                meant = self.parse(named, requester)
                if meant.understood or not (meant.question or "").startswith(WHICH_ITEM):
                    text, frame = named, meant
                    continue
            whom = chosen_recipient(self.lex, frame.question or "", answer)
            if whom is not None:  # "Wang's plan file for you, or for Zhang Wei?" "For Zhang."
                text, frame = whom, self.parse(whom, requester)
                continue
            one = chosen_of_two(self.lex, text, frame.question or "", answer)
            if one is not None:  # "Who should get your pen: Wei Na or Wang Fang?" "Wang"
                text, frame = one, self.parse(one, requester)
                continue
            unowned = unowned_mine(self.lex, frame.question or "", answer, requester)
            if unowned is not None:  # "Whose lunch ...?" "Mine." from one with none: said
                frame = TaskFrame(requester=requester, question=unowned)
                continue
            whose_said = with_whose_and_whom(self.lex, text, frame.question or "", answer)
            if whose_said is not None:  # "Whose stapler should I take ...?" "Zhang's, me"
                text, frame = whose_said, self.parse(whose_said, requester)
                continue
            if any_owner_meant(self.lex, frame.question or "", answer):
                # "Whose stopwatch do you mean?" "Anyone's, any will do.": any owner's
                frame = self.parse(text, requester, any_owner=True)
                continue
            owned = with_owner(self.lex, text, frame.question or "", answer)
            if owned is not None:  # "Several colleagues have a tray: whose ...?" "Bruno's"
                text, frame = owned, self.parse(owned, requester)
                continue
            whole = completed(text, frame.question or "", answer)
            if whole is not None:  # "take my tray to" → "Joss": "take my tray to Joss"
                text, frame = whole, self.parse(whole, requester)
                continue
            part = asked_part(frame.question) if frame.question is not None else None
            if part is not None and not_known(answer):
                # "Sorry, I don't know more than I wrote": no answer, so the part is still
                # unread and asked again, never replaced by the reply's words (the rest done)
                continue
            if part is not None and not names_work(self.office, frame.question or "", answer):
                continue  # "a read?" "Me.": the work is still not said; asked again
            if part is not None and part in text:
                # "I'm not sure what you mean by 'off to the plant'" → "courier it to the
                # plant": the answer takes the place of the part asked about
                instead = answer.strip().rstrip(" .!?")
                lead = part.split()[0]
                if lead.lower() in ("to", "into") and instead.lower().split()[:1] != [lead.lower()]:
                    instead = f"{lead} {instead}"  # "to the post room" → "Hana": "to Hana"
                elif lead.lower() in _AT_PLACE and instead.lower().split()[:1] not in (
                    [w] for w in (*_AT_PLACE, "to", "for")
                ):
                    # "gloves at the nurses' station" (kept elsewhere) → "Nell": "for Nell"
                    instead = f"for {instead}"
                elif lead.lower() == "my" and not _determined(instead):
                    instead = f"{lead} {instead}"  # "my memo" → "document": "my document"
                text = text.replace(part, instead, 1)
                frame = self.parse(text, requester)
                continue
            if frame.question is not None and frame.question.startswith(WHERE_TO):
                # the answer is the place outside ("the client", "to our lawyers"): read as
                # the request's own "to ...", by the same stage, not as a new request
                if not_known(answer):
                    continue  # "sorry, I don't know more than I wrote": no place; still asked
                place = re.sub(r"^\s*to\s+", "", answer.strip(), flags=re.IGNORECASE)
                if re.match(r"be\b", place, flags=re.IGNORECASE):
                    continue  # "to be dry cleaned": the work again, no place; still asked
                frame = self.parse(f"{text.rstrip(' .!?')} to {place}", requester)
                joined = any(
                    t.destination not in (None, place.rstrip(" .!?")) for t in frame.tasks
                )  # "off to the cleaner to Harlow Cleaners": the answer is the whole place
                if joined or (
                    frame.question is not None and not frame.question.startswith(OUT_OR_IN)
                ):
                    # the words appended read otherwise ("... with the courier to Riverside
                    # print plant": "Riverside" looked up as a colleague): the answer is
                    # the place outside, as said, never a person to find
                    frame = self.parse(text, requester, destination=place.rstrip(" .!?"))
                continue
            if frame.question is not None and _asks_who(frame.question) and _is_me(answer):
                # "Who should get your reel?" "Me.": the requester, not a new request
                frame = self.parse(text, requester, to_self=True)
                continue
            kept = chosen_kept(self.screen.terms, text, answer)
            if kept is not None:  # "do you mean the lunch box or the worn book?"
                text = kept
                frame = self.parse(text, requester)
                continue
            if (
                frame.question is not None
                and (with_said := answered_with(frame.question, answer)) is not None
            ):  # "What should I do about the document with Wang?" "take it to her"
                answered = self.parse(with_said, requester)
                if answered.understood:
                    frame = answered
                    continue
            picked = chosen_of_several(self.screen.terms, text, answer)
            if picked is not None:  # "one of Sunny's tools": "do you mean the pump or ...?"
                text = picked
                frame = self.parse(text, requester)
                continue
            chosen = self._chosen_reading(text, answer)
            if chosen:
                frame = self._choosing(chosen).parse(text, requester)
                continue
            asked_everything = frame.question == NOT_UNDERSTOOD
            # what the request (and the answers) said of whose things are and who gets them:
            # a re-read that contradicts it is never acted on; the question stays open
            roles = said_roles([self.lex.read(t) for t in (text, *answers)], requester)
            combined = self.parse(f"{text}. {answer}", requester)
            if combined.understood and contradicts(combined, roles):
                continue
            if combined.understood or not asked_everything:
                frame = combined
                continue
            alone = self.parse(answer, requester)
            if alone.understood and contradicts(alone, roles):
                continue
            frame = alone if alone.understood else combined
        return frame

    def _machine_chosen(
        self, text: str, requester: str, question: str | None, answer: str
    ) -> str | None:
        """The request with the service the answer chose, where the question asked which
        service of the machine the thing at hand is put through for (``machine_choice``)."""
        if question is None:
            return None
        readings = self.readings.read(self.lex.read(text), requester)
        choices = machine_choices(self.office, readings.tokens, readings.mentions, requester)
        if choices and question == service_question(choices):
            choice = service_answered(choices, answer)
            return with_service(text, choice) if choice is not None else None
        # "What should I do with your cheese in the Wrapping room: wax it, or ...?" "wax"
        for m in readings.mentions:
            served = (
                room_services(self.office, readings.tokens, readings.mentions, m.id)
                if m.kind == "item"
                else None
            )
            if served is None or len(served[1]) < 2:
                continue
            if question == room_service_question(self.office, m.id, *served):
                op = room_service_answered(served[1], answer)
                return with_room_service(self.office, text, op) if op is not None else None
        return None

    def _out_or_in(self, text: str, requester: str, answer: str, asked: TaskFrame) -> TaskFrame:
        """The answer to "send it out by courier to Bill, or bring it to Bill here?": the
        service's verb or "out" sends it out as written; a hand-over word or the colleague's
        name brings it to them instead; anything else leaves the question open."""
        out = self.parse(text, requester, sent_out=True)
        said = self.lex.read(answer)
        words = {t.word for t in said.tokens}
        if words & (self.operations.sending_words() | {"out", "outside"}):
            return out
        sent = [t for t in out.tasks if t.destination is not None]
        colleague = colleague_named(self.lex.read(sent[0].destination or "")) if sent else None
        named = {i for m in said.mentions for i in m.ids}
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

    def _with_operation(self, op_id: str) -> InstructionParser:
        """The same stages, with the operation the requester chose when asked which."""
        other = copy.copy(self)
        other._remembered = None  # reads differently: remembers nothing of its own
        other.operations = copy.copy(self.operations)
        other.operations.chosen = op_id
        return other

    def _choosing(self, chosen: dict[str, Reading]) -> InstructionParser:
        """The same stages, with a lexicon that reads the name words the requester was asked
        about as they answered (nothing of this parser changes)."""
        other = copy.copy(self)
        other._remembered = None  # reads differently: remembers nothing of its own
        other.lex = dataclasses.replace(self.lex, chosen=chosen)
        other.screen = RequestScreen(self.office, other.lex)
        other.readings = MentionReader(self.office, other.lex)
        other.surface = self.surface.reading_with(other.lex, other.screen.terms)
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


# The words of an answer that names only the one who asks: "me", "to me", "myself please".
_ME = frozenset(
    {"me", "myself", "mine", "i", "to", "for", "please", "just", "its", "it", "is", "do", "will"}
    | {"thanks", "thank", "you", "cheers", "ta"}
)
_SELF = frozenset({"me", "myself", "mine"})
# "I do.", "I will": the requester answering who as the subject of the question's verb
_I_DO = (("i", "do"), ("i", "will"))


def _said_mentions(spoken: Spoken) -> tuple[Mention, ...]:
    """The message's mentions a guess of the request's thing is looked for in: the whole
    message's, or, where the screen set aside what the colleague given to will do ("...,
    she needs to check my results first"), the other pieces' (a thing that piece names is
    theirs to work on, never the request's, so no guess of it is confirmed)."""
    aside = [f.piece for f in spoken.findings if f.meaning in ASIDES]
    if not aside:
        return spoken.msg.lexed.mentions
    return tuple(m for p in spoken.msg.pieces if p not in aside for m in p.lexed.mentions)


def _noted(frame: TaskFrame, said: Said) -> TaskFrame:
    """The frame with what the surface took out said first in its evidence (a fallback kept
    back: "a fallback: 'scissors' only if stapler cannot be had, ...")."""
    if not said.notes:
        return frame
    return frame.model_copy(update={"evidence": [*said.notes, *frame.evidence]})


def _each_errand_once(frame: TaskFrame) -> TaskFrame:
    """One errand said twice in one message is one task: an item sent outside ("the document
    in the printer needs to go to the bank, can you fax it": the facility's service and the
    verb each read as the task), as nothing sent out comes back to be sent again; and the same
    work on, or move of, someone's own thing for the same person ("take my lunch to the
    microwave. it needs heating": the room's work and the need each read as the task), as one
    thing is not heated or handed over twice. Things made for anyone (a coffee, a printout of
    nobody's file) are left as said: two of them may be meant."""
    kept: list[Task] = []
    for task in frame.tasks:
        once = task.destination is not None or task.owner is not None
        if once and any(task == k for k in kept):
            continue
        kept.append(task)
    if len(kept) == len(frame.tasks):
        return frame
    return frame.model_copy(update={"tasks": kept})


# The words that open a noun phrase with its own say of whose or which thing it is.
_DETERMINERS = frozenset(
    {"a", "an", "the", "my", "your", "his", "her", "our", "their", "this", "that", "its", "it"}
)


def _determined(answer: str) -> bool:
    """Whether an answer that takes a part's place says itself whose or which thing it is
    ("the certificate", "Olive's memo", "it's my document"): a bare noun ("document") keeps
    the request's own "my"."""
    words = answer.lower().split()
    return not words or words[0] in _DETERMINERS or "'" in words[0] or "’" in words[0]


def _asks_who(question: str) -> bool:
    """Whether ``question`` asks who: "Who should get your reel?", and the same asked after
    what is known ("Isla Bell already has their case opener; who should get it?")."""
    asked = question.lower()
    return asked.startswith("who ") or "; who " in asked


def _whom_meant(question: str) -> bool:
    """Whether ``question`` asks which colleague a name means ("Who do you mean by 'Rosa':
    ...?"): no question of who gets the thing, so it is asked before the work around it."""
    return question.lower().startswith("who do you mean by")


def _is_me(answer: str) -> bool:
    """Whether an answer only names the requester ("Me.", "to me", "myself", "me please", "I
    do")."""
    words = language.words(answer.lower())
    said_i = any(tuple(words[n : n + 2]) in _I_DO for n in range(len(words) - 1))
    return bool(words) and set(words) <= _ME and (bool(set(words) & _SELF) or said_i)
