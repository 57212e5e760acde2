"""Stage 4 of the reader: readings → a task frame (what to do, with which item, for whom).

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
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence
from functools import partial

from assistantx.agents.symbolic.reading import shared_object
from assistantx.agents.symbolic.reading._kinds import FILE_KINDS, TaskReader
from assistantx.agents.symbolic.reading._objects import modifiers
from assistantx.agents.symbolic.reading._parties import (
    Clause,
    Roles,
    UnresolvedPronoun,
    clause_roles,
)
from assistantx.agents.symbolic.reading.asides import aside_length
from assistantx.agents.symbolic.reading.asked_maker import asked_maker
from assistantx.agents.symbolic.reading.asked_sender import sent_by_the_asked
from assistantx.agents.symbolic.reading.asking_forms import done_forms
from assistantx.agents.symbolic.reading.bare_take import whose_and_whom
from assistantx.agents.symbolic.reading.collected_own import collected_for_work
from assistantx.agents.symbolic.reading.compound_items import first_part_item
from assistantx.agents.symbolic.reading.definite_own import requesters_own
from assistantx.agents.symbolic.reading.directed_work import (
    asks_someone_to_work,
    hands_across,
    has_it_done,
    obliged_to_go,
)
from assistantx.agents.symbolic.reading.given_back import (
    given_back_by_speaker,
    returned_to_whom,
    unowned_return,
)
from assistantx.agents.symbolic.reading.group_recipient import without_group_pronoun
from assistantx.agents.symbolic.reading.her_or_hers import her_thing_asked
from assistantx.agents.symbolic.reading.joined_doers import each_doer
from assistantx.agents.symbolic.reading.joined_owners import each_owner
from assistantx.agents.symbolic.reading.joined_recipients import for_each
from assistantx.agents.symbolic.reading.kept_at import kept_owners
from assistantx.agents.symbolic.reading.lexicon import Lexed, Mention
from assistantx.agents.symbolic.reading.named_once import the_one_named
from assistantx.agents.symbolic.reading.named_tool import works_by_named_tool
from assistantx.agents.symbolic.reading.needs_met import (
    met_by,
    needs_said_again,
    same_work,
    says_a_need,
    says_an_unnamed_need,
    unnamed_need_met,
)
from assistantx.agents.symbolic.reading.one_from import one_from, owned_as_one_from
from assistantx.agents.symbolic.reading.original_back import (
    ORIGINAL_ELSEWHERE,
    original_back,
    original_to_its_source,
)
from assistantx.agents.symbolic.reading.others_thing import others_thing_declined
from assistantx.agents.symbolic.reading.own_item_unknown import none_of_yours, own_item_unknown
from assistantx.agents.symbolic.reading.owners_need import back_to_owner
from assistantx.agents.symbolic.reading.part_recipients import (
    closes_a_part,
    handed_along,
    names_a_recipient,
    shared_recipient,
)
from assistantx.agents.symbolic.reading.purpose import others_purpose
from assistantx.agents.symbolic.reading.put_for import puts_at_someones_place
from assistantx.agents.symbolic.reading.readings import Readings
from assistantx.agents.symbolic.reading.referent import NamedItem, referent
from assistantx.agents.symbolic.reading.room_receiver import rooms_taken_to
from assistantx.agents.symbolic.reading.said_kept import owned_as_said
from assistantx.agents.symbolic.reading.said_operation import as_said
from assistantx.agents.symbolic.reading.said_owner import passed_over, pronoun_owner
from assistantx.agents.symbolic.reading.service_modifier import describes_work
from assistantx.agents.symbolic.reading.several_owners import whose_of_several
from assistantx.agents.symbolic.reading.source_not_recipient import taken_from
from assistantx.agents.symbolic.reading.tokens import Token, prev_word
from assistantx.agents.symbolic.reading.vocative import addressed_person
from assistantx.agents.symbolic.reading.work_unsaid import fetch_or_work, which_work
from assistantx.core import english, language, task_kinds
from assistantx.core.asked_to_have import asked_to_have
from assistantx.core.office import Office
from assistantx.core.task_schema import FILE_KIND, SHAPE_KIND, Evidence, Task, TaskFrame
from assistantx.core.wording import file_noun

_BREAK_WORDS = english.words("clause_breaks")
_JOIN_WORDS = english.words("clause_joins")
_SKIP_AFTER_JOIN = english.words("skip_after_join")
# the requester as the subject of a wish ("I'd like", "I want"), and the wish's verbs
_SUBJECT_SELF = english.words("self_subjects")
_WISH_VERBS = english.words("wish_verbs")
_SELF_TAKING = english.words("self_taking_verbs")
_IN_ADDITION = english.words("in_addition")
_REQUEST_MODALS = english.words("request_modals")
_PAPER_NOUNS = english.words("paper_nouns") | english.words("paper_heads")
_DEFINITE = frozenset({"the", "this", "that", "our"})
# the cues of a clause that hands things over, whose coordinated objects are its own
_HANDING_CUES = frozenset({"give", "make", "send"})
# The meaning of a frame's evidence that asks the parser to restate the whole request first
# ("print my file and a coffee": "Shall I print your file and bring you a coffee?")
RESTATED = "a thing made from nothing after other work, with no 'too': restated first"

# The question asked when a request names no item the office knows ("Which item do you mean
# for me to send by courier?"); its answer is read by ``item_answered``.
WHICH_ITEM = "Which item do you mean"


NOT_UNDERSTOOD = (
    "Sorry, I'm not sure what you need. What should I do, with which item, and for whom?"
)
"""The question for a text in which no request was found (not an unclear request)."""


class FrameReader:
    """Reads the task frame of one office's readings."""

    def __init__(self, office: Office) -> None:
        self.office = office
        self.reader = TaskReader(office)
        # every form of each operation's one-word verbs and its own ``done:`` word → the
        # operations it names ("rewinding", "rewound" → rewind)
        self._op_of: dict[str, set[str]] = {}
        for op in office.operations:
            forms = {f for v in op.verbs for f in language.verb_forms(v.split()[0]) if " " not in v}
            for form in forms | done_forms(op, office):
                self._op_of.setdefault(form, set()).add(op.id)

    def frame(
        self,
        readings: Readings,
        requester: str,
        holder: str | None = None,
        named: Sequence[NamedItem] = (),
        *,
        to_self: bool = False,
        any_owner: bool = False,
        kept_said: Mapping[str, str] | None = None,
        kept_from: Mapping[str, str] | None = None,
        named_once: str | None = None,
        message_named: Sequence[str] = (),
        outsider_said: bool = False,
    ) -> TaskFrame:
        """The tasks the readings ask for, or the question that is still open. ``holder``:
        who the whole message says has an item now (``holder``), for one given back;
        ``named``: the items the whole message names (``named_items``), for a task whose
        object was no item word of the office; ``to_self``: the requester answered "me" to
        whom their own item or file goes, so it goes to them, not asked again; ``any_owner``:
        the requester answered whose the thing is with any owner ("anyone's"), so it is
        anyone's, not asked again; ``kept_said``: item type → its one keeper where the whole
        message says the thing is kept (``said_kept``); ``kept_from``: the same, with the
        places it is said to be taken from too, for a thing read as the requester's own only
        because they give it; ``named_once``: the one colleague the
        whole message names (``the_one_named``), whom "his" means when the request's own
        words name nobody; ``message_named``: every colleague it names (``the_ones_named``),
        whom "them both" means when the request's own words name nobody before it;
        ``outsider_said``: it describes an outsider and names no colleague, whom "for him"
        then means."""
        if readings.doubt is not None:
            return TaskFrame(requester=requester, question=readings.doubt)
        tokens = readings.tokens
        tasks: list[Task] = []
        last_person: list[str] = []
        objects: list[Mention] = []
        previous_cues = True
        previous_roles = Roles()  # the roles of the clause before
        previous_asked: list[str] = []  # whom the clause before asked ("could Liu read ...")
        previous_need = False  # the clause before said someone needs something
        previous_unnamed_need = False  # ... someone named by what they are ("an intern")
        from_need: list[Task] = []  # the tasks made by clauses that say a need
        previous_ops: set[str] = set()  # the operations the clause before named by verb
        previous_places: set[str] = set()  # the places the clause before named
        clauses = self._clauses(readings)
        answered: set[int] = set()  # clauses that only named whom a pronoun meant
        addressed = addressed_person(tokens, readings.mentions, readings.gaps)
        placed: dict[str, str] = {}  # item type → the one a place phrase named
        said_from: list[str] = []  # whom the clauses take a thing from ("from Pat")
        waiting: tuple[Clause, Roles] | None = None  # a service on "it", waiting for the thing
        unaddressed: list[Task] = []  # the latest tasks whose clauses named no recipient
        whom_asked: str | None = None  # one thing for a group of recipients: to whom?
        for k, clause in enumerate(clauses):
            if k in answered:
                continue
            # "get it from June and bring it to her": the same thing, so not June
            passed_on = said_from if self._passes_it_on(clause, tokens) else []
            roles_of = partial(
                clause_roles,
                tokens,
                requester=requester,
                last_person=last_person,
                addressed=addressed,
                taken_from=passed_on,
                message_named=message_named,
                outsider_said=outsider_said,
            )
            try:
                roles = roles_of(clause)
            except UnresolvedPronoun as exc:
                later = _named_later(clauses, k + 1)
                if later is None and named_once is not None:
                    later = (-1, named_once)  # "Is Otto in? I need his ruler": Otto's
                besides = _besides_owners(
                    tokens, readings.mentions, clause, requester, last_person, addressed
                )
                grouped = without_group_pronoun(tokens, clauses, k, str(exc.args[0]))
                if later is None and besides is not None:
                    roles = besides  # "Nadia needs Miles's kit, take it to her": Nadia
                elif later is None and grouped is not None:
                    # "can we get them some water? bring it to me": the group's thing goes
                    # to the speaker, whom the later clause names
                    clause = grouped
                    roles = roles_of(clause)
                elif later is None:
                    unclear = f"Who do you mean by {exc.args[0]!r}? Please tell me their name."
                    return TaskFrame(requester=requester, question=unclear)
                else:
                    # "bring me his stapler. Zhang Wei": the answer names him
                    answered.add(later[0])
                    try:
                        roles = clause_roles(
                            tokens,
                            clause,
                            requester,
                            [*last_person, later[1]],
                            addressed=addressed,
                            taken_from=passed_on,
                        )
                    except UnresolvedPronoun:
                        # "take it from Faith to him": the one named is whom it comes from
                        unclear = f"Who do you mean by {exc.args[0]!r}? Please tell me their name."
                        return TaskFrame(requester=requester, question=unclear)
            unclear_place = kept_owners(self.office, tokens, clause, roles, requester, placed)
            if unclear_place is not None:  # "the ladder in the kitchen", where none is kept
                return TaskFrame(requester=requester, question=unclear_place)
            found = referent(clause, tokens, named) if not tasks else None
            if found is not None:
                # "Olive has a craft knife, bring it to me": the item another sentence named
                pointed, owner = found
                rest = [m for m in clause.mentions if m.start != pointed.start]
                mentions = sorted([*rest, pointed], key=lambda m: m.start)
                clause = dataclasses.replace(clause, mentions=mentions)
                if owner is None:  # "the parcel in the post room ... courier it"
                    owner = placed.get(pointed.id)
                if owner is not None and pointed.start not in roles.owners:
                    roles.owners[pointed.start] = owner
            earlier = list(objects)  # the things named before this clause
            objects += clause.objects()
            # "scan my report and send the pdf to Wang": the earlier work as its verb named it
            before = tasks[-1] if tasks else None
            as_verb = as_said(before, previous_ops, self.office)
            made = self.reader.tasks(clause, roles, requester, as_verb)
            if tasks and as_verb is not None and not made and as_verb is not before:
                if self.reader.makes_file(as_verb) and not self.reader.makes_file(tasks[-1]):
                    # "scan my report and send the pdf to Wang": the verb's operation makes
                    # the file this clause sends on; the task is that operation's from here
                    tasks[-1] = as_verb
            elif as_verb is not before:
                made = self.reader.tasks(clause, roles, requester, before)
            # "I need a coffee. can Gao knock one up?": Gao makes it, and it is still mine;
            # the clause's own "one" ("pour one") is that product again, no second one
            maker = asked_maker(self.office, tasks, clause, tokens, made)
            if maker is not None:
                tasks[-1], made = maker, []
            if not made and shared_object.waits_for_object(clause.mentions):
                waiting = (clause, roles)  # "get it copied and ...": the thing said next
            elif (
                waiting is not None
                and made
                and shared_object.opens_with_participle(clause.mentions)
            ):
                # "get it copied and stamped": the stamp found the paper; the copy, said
                # first on the same "it", is done on it too, first
                made = [*self.reader.tasks(*waiting, requester, made[0]), *made]
                waiting = None
            else:
                waiting = None
            said = [m for m in objects if m.id in self.reader.kinds]
            if not made and tasks and said and shared_object.opens_with_participle(clause.mentions):
                # "my document printed and copied": the print read a file for the document,
                # the copy's object is the paper as said, not the print's file
                if said[-1].id != tasks[-1].item:
                    paper = tasks[-1].model_copy(update={"item": said[-1].id})
                    made = self.reader.tasks(clause, roles, requester, paper)
            # "could Mark send me his file?": Mark's own, sent by him
            made = sent_by_the_asked(made, _asked_subjects(tokens, clause), clause, tokens)
            made = _to_each(made, roles, _asked_subjects(tokens, clause))
            each = for_each(made, roles.each, self.office, requester)
            if isinstance(each, str):
                # "Wang and Sun need a stapler": one stapler, whose? Asked once the whole
                # message is read (a later "him" of nobody is asked first, as before)
                whom_asked = whom_asked or each
            else:
                made = each  # "bring Wang and Sun a coffee": a coffee each
            made = each_owner(made, roles.co_owners)  # "Wang and Sun's files": both files
            made = each_doer(made, roles.doers)  # "signed by Wang and Sun": both sign
            made = [requesters_own(self.office, tokens, clause, roles, t, requester) for t in made]
            # "bring her lunch" with nothing to say whether to her or hers (to me): asked
            her_or_you = her_thing_asked(
                self.office, tokens, clause.mentions, made, requester, roles.recipient
            )
            if her_or_you is not None:
                return TaskFrame(requester=requester, question=her_or_you)
            for t in made:  # "take the tray to Amber" where three colleagues have one
                whose = whose_of_several(self.office, tokens, clause, roles, t, requester, earlier)
                # "take the stapler" from someone with none: whose, and to whom, unsaid
                whose = whose or whose_and_whom(self.office, tokens, clause, roles, t, requester)
                if whose is not None:
                    return TaskFrame(requester=requester, question=whose)
            if found is not None and found[1] is None:
                made = [self._not_mine(t, requester) for t in made]
            # "print my log. I need the spreadsheet for the meeting": the item a task already
            # works on for that person, named again as what they need, is context
            made = [t for t in made if not any(self._restates(e, t) for e in tasks)]
            # "Hal still has to sign my policy. Take my policy to him and bring it back": the
            # paper handed to whoever the earlier work is by is the way to that work
            made = [t for t in made if not any(_to_the_doer(e, t) for e in tasks)]
            # "Ramón's long lens please, the telephoto, ...": the item named again by another
            # of its names in the same clause is the same errand, and keeps its owner
            made = [
                t for n, t in enumerate(made) if not any(self._restates(e, t) for e in made[:n])
            ]
            if tasks and previous_need:  # "P needs a printout of X, print one for her": one
                made = [t for t in made if not same_work(tasks[-1], t)]
            said_ops = self._ops_said(clause, tokens)
            if tasks and self._refers_back(clause) and said_ops and said_ops <= previous_ops:
                # "my tape needs rewinding, get it rewound": the work the need said, asked
                # for again on "it" by the same operation's verb, is the same work, once
                made = [t for t in made if not same_work(tasks[-1], _on_item(t, tasks[-1]))]
            previous_ops = said_ops
            if tasks and previous_need and self._unnamed(clause) and met_by(tasks[-1], made):
                # "Priya needs the agenda, print it for her", "Chen needs my contract, make
                # her a copy": the work on the needed thing (by "it", or unsaid) meets it
                tasks.pop()
            # "an intern needs a stapler. could you bring a stapler (one) to Wang?": one, to
            # Wang, never a second for the speaker the need was read as
            unnamed_need = previous_unnamed_need
            if tasks and unnamed_need and unnamed_need_met(tasks[-1], made, requester):
                tasks.pop()
            previous_need = says_a_need(clause, tokens)
            previous_unnamed_need = says_an_unnamed_need(clause, tokens)
            if tasks and len(made) == 1 and _for_another(tasks[-1], made[0], clause, requester):
                # "please scan my invoice. Mark needs a scan of it": the same work, and whom
                # its product is for; one scan, handed to Mark
                tasks[-1] = tasks[-1].model_copy(update={"recipient": made[0].recipient})
                made = []
            if made and tasks and not previous_cues and self._refers_back(clause):
                tasks.pop()  # "my lunch is in the fridge, please heat it up": context only
                # "can Zhang check my report and sign it": the one asked to look it over
                asked = [*previous_roles.actor, *previous_roles.bare, *previous_asked]
                made = [_by_the_one_asked(t, asked, requester) for t in made]
            elif (
                tasks
                and self._refers_back(clause)
                and (at := self._carried_to_work(tasks[-1], made, said_ops, previous_places))
            ):
                # "take my deed down to the studio and have it digitised": carrying the
                # thing to where the work is done is the way to that work, done on it
                work = self._on_fetched(tasks.pop(), made[0], requester)
                made = [work if work.facility else work.model_copy(update={"facility": at})]
            elif (
                tasks
                and self._refers_back(clause)
                and collected_for_work(
                    self.office,
                    tasks[-1],
                    made,
                    _named_besides(previous_roles, requester),
                    requester,
                )
            ):
                # "get my form, then photocopy it for me": collected from the requester for
                # the work, which hands it back; never asked where the thing is
                made = [self._on_fetched(tasks.pop(), made[0], requester)]
            elif tasks and self._refers_back(clause) and _first_leg(tasks[-1], made):
                # "get my lunch out of the fridge and heat it": one errand, on the item
                # fetched ("the parcel in the post room ..., courier it": the one kept there)
                made = [self._on_fetched(tasks.pop(), made[0], requester)]
            # "put the clerk's stamp on my invoice and courier it": the tool named is the work
            previous_cues = bool(clause.cues) or works_by_named_tool(self.office, clause, made)
            previous_places = {m.id for m in clause.mentions if m.kind == "place"}
            previous_roles = roles
            said_from += roles.source
            previous_asked = _asked_subjects(tokens, clause)
            if made and tasks and handed_along(clause.mentions, tokens, roles.recipient_at):
                # "print the slides and bring them and a coffee to Zhang": the slides too
                tasks[-1] = self.reader.fill(tasks[-1], roles, requester)
            whole = shared_recipient(tokens, roles.recipient, roles.recipient_at)
            if whole is not None:
                # "print my file and a coffee, both for Wang": the printout is Wang's too
                tasks = [
                    t.model_copy(update={"recipient": whole})
                    if any(t is u for u in unaddressed)
                    else t
                    for t in tasks
                ]
            # "print my file": no recipient said yet (one said of all may come later)
            unaddressed = [*unaddressed, *made] if not roles.recipient else []
            again = None if maker is not None else _one_more(tasks, clause, tokens, roles, made)
            if maker is not None:
                pass  # the product asked for before, now with its maker (above)
            elif again is not None:
                if tasks and unnamed_need and unnamed_need_met(tasks[-1], [again], requester):
                    tasks.pop()
                tasks.append(again)  # "make me a coffee and bring Tam one too": Tam's own
            elif made:
                tasks = [*_without_subsumed(tasks, made), *made]
                if previous_need:  # this clause's, by now
                    from_need += made
            elif tasks and original_back(tasks[-1], clause, tokens):
                # "make him a copy of it and bring me the original back": the copy's original
                # comes back to whoever put it in; the copy still goes where it was asked
                if not original_to_its_source(tasks[-1], roles, requester):
                    return TaskFrame(requester=requester, question=ORIGINAL_ELSEWHERE)
            elif tasks:
                tasks[-1] = self.reader.fill(tasks[-1], roles, requester)
            if tasks:  # "needs a ruler, can you take one from Mark to her": Mark's ruler
                tasks[-1] = owned_as_one_from(tasks[-1], one_from(tokens, clause.mentions))
        # "Wang needs a printout for the meeting. Print my file and take it to him": the
        # request is how the need is met, once its recipient is said; one printout
        tasks = needs_said_again(tasks, from_need)
        rejected = _rejected_items(readings)
        # a rejected item is never fetched; with nothing left, the checks below ask
        tasks = [t for t in tasks if t.item not in rejected]
        objects = [m for m in objects if m.id not in rejected]
        # "my glove needs a virkon dip": the virkon says how the dip is done, no object
        objects = [m for m in objects if not describes_work(tokens, readings.mentions, m)]
        tasks = [self._given_back(t, holder) for t in tasks]
        # "return Wang's stapler", "give Wang his stapler back": from the speaker to Wang
        tasks = [given_back_by_speaker(t, tokens, readings.mentions, requester) for t in tasks]
        unowned = next(
            (t for t in tasks if unowned_return(t, tokens, readings.mentions, requester)), None
        )
        if unowned is not None and unowned.item is not None:
            whose = returned_to_whom(self._item_name(unowned.item))
            return TaskFrame(requester=requester, question=whose)
        # "Ms Okafor needs her tape back, take it from Pat to her": Pat hands it over
        tasks = [taken_from(self.office, t, said_from) for t in tasks]
        # "shred my old thingy, and bring me a coffee": the coffee, another task's object that
        # no work of the office takes, is that task's own, never the shred's
        worked = {op.input for op in self.office.operations if op.input is not None}
        objects_of_tasks = frozenset(
            t.item for t in tasks if t.item is not None and t.item not in worked
        )
        tasks = [
            self._named_elsewhere(t, named, requester, placed, objects_of_tasks) for t in tasks
        ]
        tasks = [self._my_unknown_thing(t, readings, requester) for t in tasks]
        tasks = [self._kept_fragment(t, clauses, readings.gaps, requester) for t in tasks]
        # "Need the register. ... it'll have to come out of the cabinet": the one kept there
        mine_said = any(m.kind == "self" and m.possessive for m in readings.mentions)
        tasks = [
            owned_as_said(
                t,
                dict(kept_said or {}),
                requester,
                mine_said=mine_said,
                kept_from=dict(kept_from or {}),
            )
            for t in tasks
        ]
        # "Olek's 4-gas is due a bump test": the owner's thing goes back to its owner
        tasks = [back_to_owner(t, tokens, readings.mentions, requester) for t in tasks]
        # "Zhang's laptop needs printing": never the requester's own file in its place
        others = others_thing_declined(self.office, tokens, readings.mentions, tasks, requester)
        if others is not None:
            return TaskFrame(requester=requester, decline=others)
        unsent = self._no_files(tasks)
        if unsent is not None:  # "fwd my invoice pdf to Ravi" where no file is kept
            return TaskFrame(requester=requester, decline=unsent)
        if any_owner:
            tasks = [self._anyones(t, requester) for t in tasks]
        if to_self:  # "X already has their Y; who should get it?" "Me.": to the requester
            tasks = [_to_requester(t, requester) for t in tasks]
        question = (
            whom_asked
            or self._uncovered(objects, tasks)
            or (None if any_owner else self._whose_service(tasks, readings, requester))
            or which_work(self.office, tasks, readings.mentions, requester, tokens)
            # "get my costume sorted" where the office mends costumes: fetch, or mend?
            or fetch_or_work(self.office, tasks, tokens, requester)
            # "heat up my lunch" from someone with no lunch here: said and asked
            or own_item_unknown(self.office, tasks, requester, self.reader.kinds)
            or self._check(
                tasks,
                requester,
                to_self,
                bool(rooms_taken_to(tokens, readings.mentions)),
                any(t.word == "me" for t in tokens),
                any_owner=any_owner,
            )
        )
        # "print my file and a coffee": both read, the whole restated before anything moves
        restated = (
            [Evidence(words="", meaning=RESTATED)] if any(c.restated for c in clauses) else []
        )
        return TaskFrame(
            requester=requester,
            tasks=tasks if question is None else [],
            question=question,
            evidence=restated,
        )

    def _on_fetched(self, fetched: Task, work: Task, requester: str) -> Task:
        """The work a later clause does on "it", the item the earlier clause fetched: that
        item, whose it was said to be (the one kept in the post room); said of nobody's, and
        the requester has none of the kind, the one the office keeps for anyone (or whose
        belonging a facility keeps, asked of its owner as usual)."""
        item = work.item or fetched.item
        owner = fetched.owner
        if owner is None and item is not None:
            owner = self._nobodys(item, requester)
        return work.model_copy(update={"item": item, "owner": owner or work.owner})

    def _not_mine(self, task: Task, requester: str) -> Task:
        """ "the parcel has to go off to Galway. Courier it please": work on "it", an item
        another sentence named as nobody's, is the requester's only if they have one of the
        kind; else the one the office keeps (a transfer is left to the planner as before)."""
        if task.kind == "transfer" or task.item is None or task.owner != requester:
            return task
        owner = self._nobodys(task.item, requester)
        return task.model_copy(update={"owner": owner}) if owner is not None else task

    def _nobodys(self, item: str, requester: str) -> str | None:
        """Whose item of a type said of nobody is meant: the requester's own, if they have
        one; else the one the office keeps (``Office.kept_owner``); None: not known."""
        if requester in self.office.owners_of(item):
            return requester
        return self.office.kept_owner(item, besides=requester)

    def _restates(self, earlier: Task, task: Task) -> bool:
        """Whether ``task`` only names again, for the same person, the item ``earlier``
        already works on (its file, its item): a purpose or a reason, not a new errand. A
        task that moves the item on to someone else, or someone else's, is new."""
        if earlier.recipient != task.recipient or task.item is None:
            return False
        if earlier.kind == task.kind and earlier.item == task.item and task.actor is None:
            if earlier.actor is not None and task.owner == earlier.owner:
                # "need Wang's signature on my invoice, can you get it signed": the same
                # work by the doer already named, asked for again without the name
                return True
        if earlier.kind == task.kind == "send_file":
            # "get me Luca's costings? the spreadsheet": the file named again by another of
            # its names, read as the requester's own to themselves, is the same file
            return task.owner == task.recipient and earlier.item == task.item
        if earlier.kind == task.kind:
            # "fetch Bill's tripod? I need the tripod": anyone's item of the kind already
            # on its way to the same person is the need said again, not a second errand
            return (
                task.kind == "transfer"
                and task.owner is None
                and task.source is None
                and earlier.item == task.item
            )
        if task.kind == "send_file":
            return task.owner == task.recipient and self._covers(earlier, task.item)
        return (
            task.kind == "transfer"
            and task.owner in (None, task.recipient)
            and earlier.item == task.item
            and task_kinds.works_on_item(earlier.kind)
        )

    def _ops_said(self, clause: Clause, tokens: Sequence[Token]) -> set[str]:
        """The operations a clause names by a form of a verb of theirs."""
        return {
            op
            for m in clause.mentions
            if m.kind == "cue"
            for op in self._op_of.get(tokens[m.start].word, ())
        }

    def _carried_to_work(
        self, earlier: Task, made: list[Task], ops: set[str], places: set[str]
    ) -> str | None:
        """The facility where ``earlier`` only carries a thing to ("take my deed down to
        the studio"), at a place the clause before named, that does the work a later clause
        asks on "it" ("... and have it digitised") for the same person: the carrying is the
        way to that work. A thing taken to a person ("down to Drew in the studio") is a
        delivery, read as before."""
        if not (
            len(made) == 1
            and ops
            and earlier.kind == "transfer"
            and earlier.owner == earlier.recipient == made[0].recipient
            and made[0].item in (earlier.item, None)
        ):
            return None
        found = [
            f.id for f in self.office.facilities if f.location in places and set(f.operations) & ops
        ]
        return found[0] if len(found) == 1 else None

    @staticmethod
    def _passes_it_on(clause: Clause, tokens: Sequence[Token]) -> bool:
        """Whether the clause hands on a thing said before by "it"/"them", naming none."""
        return any(
            m.kind == "pronoun" and tokens[m.start].word in ("it", "them") for m in clause.mentions
        ) and not any(m.kind == "item" for m in clause.mentions)

    def _unnamed(self, clause: Clause) -> bool:
        """Whether a clause names no item of its own to work on ("print it", "make her a
        copy": the copy is what the work makes, not a thing it takes)."""
        return not any(
            m.kind == "item" and any(self.office.item_type(i).kind != "product" for i in m.ids)
            for m in clause.mentions
        )

    @staticmethod
    def _refers_back(clause: Clause) -> bool:
        return any(m.kind == "pronoun" and not m.possessive for m in clause.mentions) and not any(
            m.kind == "item" for m in clause.mentions
        )

    # -- clauses -------------------------------------------------------------------------
    def _clauses(self, readings: Readings) -> list[Clause]:
        tokens, mentions, gaps = readings.tokens, readings.mentions, readings.gaps
        clauses: list[Clause] = [Clause([])]
        aside_end = 0  # an aside's mentions, skipped ("and while you're at it grab ...")
        # clauses that start a new part after one handing "it" to its recipient
        opened_after_part: set[int] = set()
        for n, m in enumerate(mentions):
            if n < aside_end:
                continue
            word = tokens[m.start].word
            gap = gaps[m.start]
            joined = word in _JOIN_WORDS or word in _BREAK_WORDS
            after_join = n + 1 if joined else n
            aside = aside_length(mentions, after_join, tokens) if joined or "," in gap else 0
            spaced_dash = gap.strip() in ("-", "–", "—", "--") and gap != gap.strip()
            # a sentence may start on a word that is no mention ("... stool. the stool"): the
            # break is wherever one starts since the last mention (a title's stop is none)
            since = mentions[n - 1].end if n else m.start
            ended = "".join(gaps[since : m.start + 1])
            hard = (any(c in ended for c in ".!?;") or spaced_dash) and bool(clauses[-1].mentions)
            soft = bool(aside) or (
                (joined or "," in gap)
                and (
                    self._starts_request(mentions, after_join, tokens)
                    or self._made_beside(clauses[-1], mentions, after_join, tokens)
                    # "take it to Wang, and a coffee for me": the print's part is whole
                    or closes_a_part(clauses[-1].mentions, mentions, after_join, tokens)
                    # "Mark needs a ruler, leave mine on his desk": how the need is met
                    or (
                        says_a_need(clauses[-1], tokens)
                        and puts_at_someones_place(mentions, after_join, tokens)
                    )
                )
            )
            unsaid = (
                not soft
                and joined
                and self._made_beside(clauses[-1], mentions, after_join, tokens, unsaid=True)
            )
            if (hard or soft or unsaid) and clauses[-1].mentions:
                closed = (
                    not hard
                    and (joined or "," in gap)
                    and closes_a_part(clauses[-1].mentions, mentions, after_join, tokens)
                )
                clauses.append(Clause([], restated=unsaid))
                if closed:
                    opened_after_part.add(len(clauses) - 1)
            if aside:
                aside_end = after_join + aside
                continue
            if m.kind == "word" and (word in _JOIN_WORDS or word in _BREAK_WORDS):
                continue
            clauses[-1].mentions.append(m)
        for k in opened_after_part:
            # "take it to Wang, and a coffee": for me or for Wang? restated and asked first
            # (a part with a verb of its own, "also bring a coffee", is read as before)
            said = clauses[k].mentions
            if not names_a_recipient(said, tokens) and not any(m.kind == "cue" for m in said):
                clauses[k].restated = True
        for c in clauses:
            c.modifiers = modifiers(tokens, c.mentions, self.reader.sourced, self.reader.formats)
            c.modifiers |= others_purpose(tokens, c.mentions)  # "... so it can be couriered"
            c.cues = {
                k
                for m in c.mentions
                if m.kind == "cue" and m.start not in c.modifiers
                for k in m.ids
            }
        return [c for c in clauses if c.mentions]

    @staticmethod
    def _starts_request(mentions: Sequence[Mention], n: int, tokens: Sequence[Token]) -> bool:
        while n < len(mentions) and tokens[mentions[n].start].word in _SKIP_AFTER_JOIN:
            n += 1
        return n < len(mentions) and (
            mentions[n].kind == "cue"
            or asks_someone_to_work(mentions, n, tokens)
            or hands_across(mentions, n, tokens)
            or has_it_done(mentions, n, tokens)
            or obliged_to_go(mentions, n, tokens)
        )

    def _made_beside(
        self,
        current: Clause,
        mentions: Sequence[Mention],
        n: int,
        tokens: Sequence[Token],
        *,
        unsaid: bool = False,
    ) -> bool:
        """ "print my slides, and I'd like a cappuccino too", "..., and a tea for me too":
        after a request for work on an item (a print, a copy, a seal), the requester's own
        wish with its object ("I'd like", "I want") or a thing a service makes from nothing
        said to be wanted besides ("too", "as well") opens a request of its own: the work
        cannot act on a drink. A clause that hands things over ("bring me the stapler and a
        coffee") keeps its coordinated objects, and whom they go to."""
        cues = {k for m in current.mentions if m.kind == "cue" for k in m.ids}
        if not cues:
            return False
        while n < len(mentions) and tokens[mentions[n].start].word in _SKIP_AFTER_JOIN:
            n += 1
        if n >= len(mentions):
            return False
        if (  # "..., and may I use Chen's scissors": the modal before its subject
            n + 1 < len(mentions)
            and tokens[mentions[n].start].word in _REQUEST_MODALS
            and mentions[n + 1].kind == "self"
        ):
            n += 1
        first = mentions[n]
        if first.kind == "self" and tokens[first.start].word in _SUBJECT_SELF:
            # "send my tripod to Noor, and I'd like my flask": the wish's own subject is its
            # recipient, after handing work too
            k = n + 1  # "I would also like": past the modal and "also"
            while k < len(mentions) and tokens[mentions[k].start].word in _SKIP_AFTER_JOIN:
                k += 1
            if k >= len(mentions):
                return False
            verb = tokens[mentions[k].start].word
            # "... and could I borrow Piet's clamp", "can I have my flask": a verb of having
            # with the requester as its subject asks for the thing for them too
            if not (
                (mentions[k].kind == "cue" and verb in _WISH_VERBS)
                or (mentions[k].kind in ("cue", "word") and verb in _SELF_TAKING)
            ):
                return False
            j = k + 1
            if (  # "I'd like to borrow Piet's clamp": past "to" and the verb of having
                j + 1 < len(mentions)
                and tokens[mentions[j].start].word == "to"
                and tokens[mentions[j + 1].start].word in _SELF_TAKING
            ):
                j += 2
            if (  # "I'd like my flask", "borrow Piet's clamp": past the owner's word
                j < len(mentions)
                and mentions[j].kind in ("self", "person")
                and mentions[j].possessive
            ):
                j += 1
            return j < len(mentions) and mentions[j].kind == "item"
        if cues & _HANDING_CUES:
            return False
        if first.kind != "item" or not self.reader.made_from_nothing(first.id):
            return False
        if not unsaid:
            return _said_in_addition(tokens, first.end)
        # ``unsaid``: "print my file and a coffee", no "too": a thing no work of the clause
        # makes (a print makes no coffee) may be a second request; read as one, restated
        return not any(first.id in self.reader.products_of(k) for k in cues)

    # -- checks ----------------------------------------------------------------------------
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
        if task.kind in FILE_KINDS and self.reader.kinds[type_id] in ("electronic", "personal"):
            return True  # "print my report", "email my contract"
        if self.reader.kinds[type_id] == "electronic" and self.reader.makes_file(task):
            return True  # "scan my reel and send me the PDF": the file the scan makes
        # the tool a kind's doer uses (the office's sealing tool, whatever its type id)
        return (task.kind, type_id) in {
            ("print", self.reader.printout),
            ("copy", self.reader.copy),
            *((task.kind, p) for p in self.reader.products_of(task.kind)),
            (task.kind, task_kinds.tool_type(task.kind, self.office)),
        }

    def _asked_to(self, kind: str) -> str:
        """What the requester asked for, in the office's words: "for me to fax or courier"
        (its operations of the kind's shape), never the task kind's internal name."""
        shape = next((s for s, k in SHAPE_KIND.items() if k == kind), None)
        names = [op.name for op in self.office.with_shape(shape)] if shape else []
        if names:
            return f"for me to {' or '.join(dict.fromkeys(names))}"
        return task_kinds.kind(kind).which_item

    def _check(
        self,
        tasks: list[Task],
        requester: str,
        to_self: bool = False,
        to_room: bool = False,
        to_me: bool = False,
        *,
        any_owner: bool = False,
    ) -> str | None:
        """The question still open about ``tasks``; ``to_room``: the words take a thing to a
        room, so who gets the requester's own thing is the room's question (whom the message
        says needs it, else who there: ``room_receiver``, ``parts``), not asked here;
        ``to_me``: the words say "me", so who gets it is said and where it is is asked;
        ``any_owner``: any owner's thing will do, so whose it is is not asked."""
        if not tasks:
            return NOT_UNDERSTOOD
        for t in tasks:
            if to_self and t.owner == t.recipient == requester:
                continue  # "Who should get your reel?" "Me.": it comes to the requester
            name = self._item_name(t.item) if t.item else "item"
            if t.item is None:
                asked = self._asked_to(t.kind)
                return f"{WHICH_ITEM}{' ' if asked else ''}{asked}?"
            done_by_one = t.kind in task_kinds.person_kinds() and not task_kinds.needs_tool(t.kind)
            if done_by_one and (t.actor is None or t.actor == requester):
                # "have somebody sign my contract": the work said ("Who should sign ...?")
                return f"Who should {_work_said(t.kind)} your {name}? Please tell me their name."
            if t.kind == "transfer":
                personal = self.reader.kinds[t.item] == "personal"
                if t.owner is None and personal and not any_owner:
                    return f"Whose {name} do you mean?"
                kept = t.owner is not None and self.office.keeper(t.owner, t.item) is not None
                held = t.source is not None and t.source != t.owner  # "it's on my desk"
                if t.owner is not None and t.owner == t.recipient and not (kept or held):
                    if to_room and t.owner == requester:
                        continue  # "take my stapler to the meeting room": who there, later
                    who = "you" if t.owner == requester else self.office.person(t.owner).name
                    if who != "you" and t.owner not in self.office.owners_of(t.item):
                        # "Hedda lent me her umbrella ...": not one the office knows as hers
                        return (
                            f"As far as I know, {who} has no {name} of their own. Whose "
                            f"{name} is it, and who should get it?"
                        )
                    if who == "you" and requester not in self.office.owners_of(t.item):
                        return none_of_yours(self.office, t.item)  # "bring me my book", none
                    if who == "you" and to_me:
                        # "bring me my book" where it is on them as far as the office knows:
                        # whom is said; where it is now is the open question
                        return f"Where is your {name}? As far as I know you have it with you."
                    return (
                        f"Who should get {who}r {name}?"
                        if who == "you"
                        else (f"{who} already has their {name}; who should get it?")
                    )
            if t.kind == "send_file" and t.owner == t.recipient:
                return f"Who should I pass your {file_noun(self.office)} on to?"
        return None

    def _no_files(self, tasks: Sequence[Task]) -> str | None:
        """A file to pass on ("email my invoice", "fwd my invoice pdf") where the office
        keeps no electronic files: said in words, never the paper carried instead."""
        if self.office.file_type() is not None:
            return None
        for t in tasks:
            if t.kind == FILE_KIND:
                people = {p.id: p.name for p in self.office.people}
                to = f" to {people[t.recipient]}" if t.recipient in people else ""
                return (
                    "Sorry, I can't pass on electronic files: this office keeps none I can "
                    f"send. If you'd like the paper taken{to} instead, just ask me."
                )
        return None

    def _anyones(self, task: Task, requester: str) -> Task:
        """``task`` on anyone's thing where the requester said any owner will do: their own
        read where they have none is nobody's in particular."""
        if task.item is None or task.owner != requester:
            return task
        if requester in self.office.owners_of(task.item):
            return task
        return task.model_copy(update={"owner": None})

    def _whose_service(
        self, tasks: Sequence[Task], readings: Readings, requester: str
    ) -> str | None:
        """ "Could you weigh the parcel?" said by someone who has no parcel: a service on a
        thing whose owner is not said is the requester's own only if they have one; with none
        of theirs and none the office keeps for anyone (a supply; a colleague's belonging kept
        at a facility is theirs, no supply), whose it is is asked (never a thing tried from the
        requester's desk where there is none). "my parcel" is left as said."""
        said_mine = any(
            m.kind == "self" and readings.tokens[m.start].word in ("my", "mine")
            for m in readings.mentions
        )
        for t in tasks:
            if (
                t.kind not in ("heat", "copy")
                or t.item is None
                or t.owner != requester
                or said_mine
            ):
                continue
            if self.reader.kinds.get(t.item) == "electronic":
                continue
            if requester in self.office.owners_of(t.item):
                continue
            if self.office.supplier(t.item) is not None:
                continue  # the office's own, kept for anyone
            # a colleague's kept at a facility is still a colleague's: whose is asked, never
            # the requester's own put in (fix213a class 4: "could you get the key copied")
            return f"Whose {self._item_name(t.item)} do you mean?"
        return None

    def _item_name(self, type_id: str) -> str:
        return self.office.item_type(type_id).name

    def _my_unknown_thing(self, task: Task, readings: Readings, requester: str) -> Task:
        """ "ask Mao to sign my letter": "my" before a word that is no item of this office,
        as the object of a kind that works on a property (a paper one signs, a file): the
        requester's one item with that property, named in the restatement so they can
        correct it; two such items of theirs, or none, still ask "which item?"."""
        if task.item is not None or not task_kinds.kind_of(task.kind):
            return task
        prop = task_kinds.kind(task.kind).works_on
        if prop is None:
            return task
        # "sign this contract extension": the paper's name as a compound's first part
        named = first_part_item(self.office, readings.mentions, prop, requester)
        if named is not None:
            return task.model_copy(update={"item": named, "owner": task.owner or requester})
        mine = _my_unknown_words(readings)
        if mine != 1 and not (mine == 0 and _unlisted_papers(readings) == 1):
            return task
        person = self.office.person(requester)
        fits = [o.type for o in person.owns if getattr(self.office.item_type(o.type), prop)]
        if len(fits) != 1:
            return task
        return task.model_copy(update={"item": fits[0], "owner": task.owner or requester})

    def _kept_fragment(
        self, task: Task, clauses: Sequence[Clause], gaps: Sequence[str], requester: str
    ) -> Task:
        """ "lunch. fridge. pls", "keys - key safe - now": terse fragments that name a
        personal item and, in a fragment of its own with no verb, the facility where the
        requester's own item of that type is kept: the requester's own. Nobody's said, and
        the requester keeps none there, whose is still asked."""
        if task.kind != "transfer" or task.owner is not None or task.item is None:
            return task
        if self.reader.kinds[task.item] != "personal" or task.source is not None:
            return task
        keeper = self.office.keeper(requester, task.item)
        if keeper is None:
            return task
        for c in clauses:
            if c.cues:
                continue
            there = [m for m in c.mentions if m.kind == "facility" and keeper.id in m.ids]
            alone = all(m.kind in ("facility", "word") for m in c.mentions)
            # "lunch, fridge, now pls": set off by a comma or dash in the item's own clause
            set_off = any(any(ch in gaps[m.start] for ch in ",-–—/") for m in there)
            if there and (alone or set_off):
                return task.model_copy(update={"owner": requester})
        return task

    def _named_elsewhere(
        self,
        task: Task,
        named: Sequence[NamedItem],
        requester: str,
        placed: dict[str, str],
        taken: frozenset[str] = frozenset(),
    ) -> Task:
        """ "get Wren to sign off the bill? it's the invoice on my desk": a task whose object
        is no item word of the office ("the bill", a word that is also a name) takes the one
        item of the kind it works on that another sentence names; two such items, or none,
        still ask "which item?". An item another task of the message acts on that no work of
        the office takes (``taken``: "shred my old thingy, and bring me a coffee") is that
        request's own object, never borrowed: the task's own object is still asked."""
        if task.item is not None:
            return task
        spec = task_kinds.kind(task.kind) if task_kinds.kind_of(task.kind) else None
        prop = spec.works_on if spec is not None else None
        fits = {
            (item, owner)
            for item, owner in named
            if (prop is None or getattr(self.office.item_type(item), prop)) and item not in taken
        }
        if len({item for item, _ in fits}) != 1:
            return task
        item, owner = sorted(fits, key=lambda f: f[1] is None)[0]
        if owner is None:  # said of nobody: the one a place phrase named
            owner = placed.get(item)
        filled = task.model_copy(update={"item": item, "owner": owner or task.owner or requester})
        return filled if owner is not None else self._not_mine(filled, requester)

    def _given_back(self, task: Task, holder: str | None) -> Task:
        """ "Wren lent me her umbrella, please return it to her": an item going back to its
        owner is taken from whoever the text says has it now (the office file still says the
        owner), never asked about as if the owner had it."""
        if task.kind != "transfer" or task.owner is None or task.owner != task.recipient:
            return task
        if holder is None or holder == task.owner or task.source is not None:
            return task
        if task.item is None or self.office.keeper(task.owner, task.item) is not None:
            return task
        if task.owner not in self.office.owners_of(task.item):
            return task  # an item the office does not know as theirs: asked, not guessed
        return task.model_copy(update={"source": holder})


# Words between "not" and the item it rejects: "not the stapler", "not his scissors".
_DETERMINERS = english.words("determiners")


_PLACE_WORDS = english.words("place_words")
# "Olive has a knife", "Bill's got one": the verbs that say who has an item
_HAVE = english.words("possession_verbs") | {"has", "have", "had", "got", "owns", "keeps", "s"}


def named_items(lexed: Lexed, requester: str) -> tuple[NamedItem, ...]:
    """The items a whole message names, with whose each was said to be ("my invoice",
    "Wren's ruler"), in order; the reader's stages may have set the sentence aside."""
    out: list[NamedItem] = []
    for n, m in enumerate(lexed.mentions):
        if m.kind != "item" or len(m.ids) != 1:
            continue
        before = lexed.mentions[n - 1] if n else None
        owner: str | None = None
        if before is not None and before.end == m.start:
            if before.kind == "self" and lexed.tokens[before.start].word in ("my", "mine"):
                owner = requester
            elif before.kind == "person" and before.possessive and len(before.ids) == 1:
                owner = before.ids[0]
            else:  # "does Wang still have his stapler?": his, Wang's
                owner = pronoun_owner(lexed, before, the_one_named(lexed, requester))
        owner = owner or _said_to_have(lexed, n)
        out.append((m.ids[0], owner))
    return tuple(out)


def _said_to_have(lexed: Lexed, at: int) -> str | None:
    """ "Olive Grant has a craft knife", "Bill's got one of those staplers": the one person
    a statement says has the item mention ``at``, with only a verb of having and determiners
    between them."""
    item = lexed.mentions[at]
    person = next(
        (m for m in reversed(lexed.mentions[:at]) if m.kind not in ("word", "self")), None
    )
    if person is None or person.kind != "person" or person.possessive or len(person.ids) != 1:
        return None
    tokens = lexed.tokens
    before = prev_word(tokens, person.start)  # "could Mr K have": the title skipped
    if asked_to_have(before, [t.word for t in tokens[person.end : item.start]]):
        return None  # "could Nkechi have a stapler": she is to get one, not lend hers
    # "does Mark still have a ruler": the adverb says when, and is passed over
    between = [t.word for t in lexed.tokens[person.end : item.start] if not passed_over(t.word)]
    if not between or between[0] not in _HAVE:
        return None
    if not all(w in _HAVE or w in _DETERMINERS for w in between):
        return None
    return person.ids[0]


_LEND = frozenset({*language.verb_forms("lend"), *language.verb_forms("loan")})
_BORROWED = frozenset(language.verb_forms("borrow")) - {"borrow"}
_WITH_ME = (("i", "have", "it"), ("ive", "got", "it"), ("i", "have", "got", "it"), ("with", "me"))


def holder(lexed: Lexed, requester: str) -> str | None:
    """Who the text says has an item now, if anyone: the requester when they were lent it or
    borrowed it, or it is on their desk or with them ("P lent me her ruler", "it's on my
    desk", "I have it"); a colleague when it is on their desk ("it's on Bill's desk")."""
    words = [t.word for t in lexed.tokens]
    for n, w in enumerate(words):
        after = words[n + 1 : n + 4]
        if w in _LEND and "me" in after:
            return requester  # "lent me", "loaned it to me"
        if w in _BORROWED and n and words[n - 1] in ("i", "ive", "id", "we"):
            return requester  # "I borrowed"
        if w == "my" and after[:1] and after[0] in _PLACE_WORDS:
            return requester  # "on my desk"
        if any(tuple(words[n : n + len(p)]) == p for p in _WITH_ME):
            return requester
    for m in lexed.mentions:
        nxt = lexed.tokens[m.end].word if m.end < len(lexed.tokens) else ""
        if m.kind == "person" and m.possessive and len(m.ids) == 1 and nxt in _PLACE_WORDS:
            return m.ids[0]  # "it's on Bill's desk"
    return None


def _said_in_addition(tokens: Sequence[Token], at: int) -> bool:
    """Whether the phrase from token ``at`` to its pause says it is asked for besides ("a
    coffee for me *too*", "a tea *as well*"): without it, "print my document and a visitor
    pass" may ask for the pass printed, and is asked about."""
    words: list[str] = []
    for t in tokens[at:]:
        if words and (t.after_pause or t.word in _JOIN_WORDS):
            break
        words.append(t.word)
    pairs = {" ".join(words[k : k + 2]) for k in range(len(words) - 1)}
    return bool((set(words) | pairs) & _IN_ADDITION)


def _work_said(kind: str) -> str:
    """The work a person is asked to do, as its verb ("sign"), where the kind's first word
    is one; else "do that with"."""
    try:
        words = english.kind_words(kind)
    except KeyError:
        words = ()
    first = words[0] if words else ""
    return first if first and first in language.verb_lemmas(first) else "do that with"


# "the stapler can wait": the words after a thing that put it off
_PUT_OFF = frozenset(tuple(p.split()) for p in english.entries("put_off_phrases"))


def _rejected_items(readings: Readings) -> set[str]:
    """Item types the requester rejected outright ("..., sorry, a pen, not the stapler")."""
    tokens = readings.tokens
    rejected: set[str] = set()
    for m in readings.mentions:
        if m.kind != "item":
            continue
        k = m.start - 1
        while k >= 0 and tokens[k].word in _DETERMINERS:
            k -= 1
        if k >= 0 and tokens[k].word == "not":
            rejected.update(m.ids)
        # "bring me a pen. the stapler can wait": the thing said to wait is put off, not asked
        after = tuple(t.word for t in tokens[m.end : m.end + 2])
        if after in _PUT_OFF and (m.start == 0 or k < 0 or tokens[k + 1].opens):
            rejected.update(m.ids)
    return rejected


def _my_unknown_words(readings: Readings) -> int:
    """How many times the request says "my" before a word the lexicon read as no name of the
    office ("my letter" where the office's paper is a "document")."""
    tokens, mentions = readings.tokens, readings.mentions
    named = {k for m in mentions if m.kind != "word" for k in range(m.start, m.end)}
    return sum(
        1
        for k, t in enumerate(tokens[:-1])
        if t.word == "my"
        and k + 1 not in named
        and tokens[k + 1].word.isalpha()
        and not any(c in ".,;:!?" for c in readings.gaps[k + 1])
    )


def _unlisted_papers(readings: Readings) -> int:
    """How many times the request names a paper by words the lexicon read as no name of
    the office, headed by a word for a paper ("the sampling plan", "this risk assessment",
    "the rota"): a definite word, up to two plain words, then the paper's noun."""
    tokens, mentions = readings.tokens, readings.mentions
    named = {k for m in mentions if m.kind != "word" for k in range(m.start, m.end)}
    count = 0
    for k, t in enumerate(tokens):
        if t.word not in _PAPER_NOUNS or k in named:
            continue
        j = k - 1
        while j >= 0 and k - j <= 3 and tokens[j].word not in _DEFINITE:
            if j in named or not tokens[j].word.isalpha():
                break
            if any(c in ".,;:!?" for c in readings.gaps[j + 1]):
                break
            j -= 1
        if j >= 0 and tokens[j].word in _DEFINITE:  # "this" may be read as a pronoun
            count += 1
    return count


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


def _on_item(task: Task, earlier: Task) -> Task:
    """``task`` on ``earlier``'s item where its own object was only "it"."""
    return task if task.item is not None else task.model_copy(update={"item": earlier.item})


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


def _to_each(made: list[Task], roles: Roles, asked: Sequence[str] = ()) -> list[Task]:
    """ "send my rota to Hal and to Dawn", "... to Hal and Dawn": a file goes to each person
    named as a recipient (a copy costs nothing; one physical item could not). ``asked``: the
    colleagues the clause asks to do the sending ("could Zhang send Wang my file?"): the
    sender is no recipient of it, so the file goes to Wang only."""
    if len(made) != 1 or made[0].kind != "send_file" or not roles.recipient:
        return made
    # "could Mark send me his file?": Mark sends it; a file is never passed on to whose it is
    people = [
        p
        for p in dict.fromkeys([*roles.recipient, *roles.bare])
        if p != made[0].owner and p not in asked
    ]
    if len(people) == 1:
        return [made[0].model_copy(update={"recipient": people[0]})]
    if len(people) < 2:
        return made
    return [made[0].model_copy(update={"recipient": who}) for who in people]


def _for_another(earlier: Task, task: Task, clause: Clause, requester: str) -> bool:
    """Whether ``task`` is ``earlier``'s work again, on the same item pointed back to ("a
    scan of it"), only for someone else: whom the product is for, not a second job."""
    refers = any(m.kind == "pronoun" and not m.possessive for m in clause.mentions)
    return (
        refers
        and task.kind == earlier.kind
        and task.kind not in ("transfer", "send_file")
        and task.item == earlier.item
        and task.owner == earlier.owner
        and earlier.recipient == requester
        and task.recipient != requester
    )


def _by_the_one_asked(task: Task, asked: Sequence[str], requester: str) -> Task:
    """A person's work on "it" (a signature) whose doer is unsaid, after a clause with no
    work of its own that asks a colleague to look the item over ("can Zhang check my report
    and sign it", "ask Zhang to read my contract and sign it"): that colleague does it. The
    subject of a statement ("Zhang has my report") is no party, so never the doer."""
    if task.actor is not None or task.kind not in task_kinds.person_kinds():
        return task
    if task_kinds.needs_tool(task.kind):
        return task
    doer = next((p for p in asked if p != requester), None)
    return task if doer is None else task.model_copy(update={"actor": doer})


def _asked_subjects(tokens: Sequence[Token], clause: Clause) -> list[str]:
    """The colleagues a clause asks something of as the subject of a request's modal
    ("could Liu Yang read my report": Liu, whatever the verb's form)."""
    return [
        m.ids[0]
        for m in clause.mentions
        if m.kind == "person"
        and len(m.ids) == 1
        and m.start > 0
        and tokens[m.start - 1].word in _REQUEST_MODALS
    ]


# "one" or "another" standing for one more of the thing just named; the words before it that
# make it a particular one ("the one", "which one") instead
_ONE_MORE = frozenset({"one", "another"})
_PARTICULAR = frozenset({"the", "this", "that", "which", "any", "every", "each", "no"})


def _one_more(
    tasks: list[Task], clause: Clause, tokens: Sequence[Token], roles: Roles, made: list[Task]
) -> Task | None:
    """ "make me a coffee and bring Tam one too", "... then another for Kit": a clause with
    no thing of its own whose object is "one" or "another", with someone of its own to have
    it, asks one more of what the clause before made or fetched (anyone's), for them."""
    if made or not tasks or not roles.recipient:
        return None
    last = tasks[-1]
    if last.kind not in ("produce", "transfer") or last.owner is not None:
        return None
    if any(m.kind in ("item", "pronoun") for m in clause.mentions):
        return None
    for m in clause.mentions:
        if m.kind != "word" or m.ids[0] not in _ONE_MORE or m.possessive:
            continue
        before = tokens[m.start - 1].word if m.start > 0 else ""
        after = tokens[m.end].word if m.end < len(tokens) else ""
        if before in _PARTICULAR or after == "of":
            continue
        who = roles.recipient[-1]
        if who == last.recipient:
            return None
        return last.model_copy(update={"recipient": who})
    return None


def _named_besides(roles: Roles, requester: str) -> set[str]:
    """The people a clause's roles name besides the requester (a doer, a recipient, ...)."""
    said = [*roles.recipient, *roles.source, *roles.actor, *roles.bare, *roles.returned_to]
    return {p for p in said if p != requester}


def _first_leg(earlier: Task, made: list[Task]) -> bool:
    """Whether ``earlier`` (a fetch of an item to someone) is only the way to the work a
    later clause does on that same item for the same person ("... and heat it")."""
    return (
        len(made) == 1
        and task_kinds.works_on_item(made[0].kind)
        and earlier.kind == "transfer"
        and made[0].item in (earlier.item, None)  # None: "it", the item fetched
        and earlier.recipient == made[0].recipient
    )


def _to_the_doer(earlier: Task, task: Task) -> bool:
    """Whether ``task`` hands the item of ``earlier``, a person's work (a signature, a
    stamp), to the one who does that work: the way to it, which the work's own errand
    already makes (it goes to them and comes back)."""
    return (
        task.kind == "transfer"
        and earlier.kind in task_kinds.person_kinds()
        and earlier.actor is not None
        and task.recipient == earlier.actor
        and (task.item, task.owner) == (earlier.item, earlier.owner)
    )


def _besides_owners(
    tokens: Sequence[Token],
    mentions: Sequence[Mention],
    clause: Clause,
    requester: str,
    last_person: Sequence[str],
    addressed: str | None,
) -> Roles | None:
    """ "Nadia needs Miles's dev kit - could you ask him and take it to her?", "Kit's after a
    torch, take Omar's over to him": of the two colleagues named, the one said as the owner
    of a thing ("Miles's dev kit", also in the clause itself) is not whom "her" brings it
    to; with exactly one other colleague named, the pronoun is them. None: still unclear
    (the reader asks)."""
    owned = {
        m.ids[0]: mentions[n + 1].ids
        for n, m in enumerate(mentions[:-1])
        if m.kind == "person"
        and m.possessive
        and len(m.ids) == 1
        and mentions[n + 1].kind == "item"
        and mentions[n + 1].start == m.end
    }
    things = {i for ids in owned.values() for i in ids}
    # the owner's thing is what this clause hands on: "it", or the thing named again ("Hal's
    # clipboard snapped, Dawn's here, lend him mine" is no hand-over of Hal's clipboard)
    again = any(
        (m.kind == "pronoun" and tokens[m.start].word in ("it", "them"))
        or (m.kind == "item" and set(m.ids) & things)
        for m in clause.mentions
    )
    owners = set(owned) if again else set()
    left = [x for x in dict.fromkeys(last_person) if x != requester and x not in owners]
    if not owners & set(last_person) or len(left) != 1:
        return None
    try:
        # "Kit's after a torch, take Omar's over to him": Omar, named again in this clause
        # as the owner, is not whom "him" means
        return clause_roles(
            tokens, clause, requester, left, addressed=addressed, not_meant=frozenset(owners)
        )
    except UnresolvedPronoun:
        return None


def _to_requester(task: Task, requester: str) -> Task:
    """``task`` handing a colleague's thing to that colleague again, given to the requester
    instead: the requester answered "me" to who should get it."""
    if task.kind != "transfer" or task.owner in (None, requester) or task.recipient != task.owner:
        return task
    return task.model_copy(update={"recipient": requester})
