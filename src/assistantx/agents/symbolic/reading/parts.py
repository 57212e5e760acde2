"""After the operations: a part of the request that no task carries is asked about, never
dropped.

The frames stage makes tasks from the clauses it can read; a part it cannot read must not
vanish from the errand ("get my report past legal and then off to the plant": the review
done, the sending out silently left out, and "Done" reported). The parts no task carries:

- a destination after "to" that is nothing of the office (no person, place, facility or
  item, not "me") and no task's destination outside: "off to the plant", "then over to head
  office";
- a sending away with no task that sends anything out: "send it out", "get it away";
- a send-out service asked for by a request's own verb, or a facility named as doing the
  work ("past legal"), on an item a task carries, run by no task ("courier my report to the
  head office and vet it" read as the review alone);
- the requester's paper in an everyday noun the office has no one thing for ("my memo",
  ``own_papers.unread_paper``): "take my memo to Olive, then bring me a cuppa" never does
  the tea alone;
- any thing an errand's verb takes, "my"/a colleague's and a noun no name of the office
  reads (``unnamed_things``): "take my lamp to Rose, and bring me Grace's highlighter"
  never brings the highlighter alone;
- a facility's name said as someone's belonging (``owned_facility``): "take my kettle to Mark"
  never makes Mark a tea at the kitchen's kettle;
- an operation named by its display name, or by the head noun of it after an article ("a
  legal read", "a read" where a legal read and a style read both exist), on an item the
  request names, run by no task (``operation_left_out``): after "Who should get your
  proof?" "Me.", the proof handed back unread would be reported done.

Each is asked about before anything moves, quoting the part in the requester's words (with
the office's ways of sending things out, where it has some); the answer takes the part's
place in the request (``InstructionParser.parse_with_answers``). A "to" before a verb ("to
sign") is a purpose, not a destination, and a destination a task already has is read.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.event_clause import in_time_clause
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.occasion import occasion_people
from assistantx.agents.symbolic.reading.original_back import original_of_copy
from assistantx.agents.symbolic.reading.own_papers import unread_paper
from assistantx.agents.symbolic.reading.owned_facility import owned_facility
from assistantx.agents.symbolic.reading.readings import Readings
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.agents.symbolic.reading.unnamed_things import unnamed_thing
from assistantx.agents.symbolic.reading.unread_compounds import (
    unread_compound,
    unread_sent_thing,
)
from assistantx.core import english, language
from assistantx.core.office import Facility, Office
from assistantx.core.task_schema import TaskFrame, operation_of
from assistantx.core.wording import ways_out
from assistantx.memory.names import normalize

_TO = frozenset({"to", "towards", "toward"})
# The words before a "to" that no verb governs: "and then off to the plant", "then to X".
_PARTICLES = frozenset({"off", "over", "on"})
_NO_VERB = _PARTICLES | {"then", "afterwards"}
# What opens a noun phrase after "to" that could be a place ("to *the* plant"); "my" and the
# pronouns are the lexicon's own mentions, read as the requester or a person.
_NP_OPENERS = frozenset({"the", "a", "an", "our", "their", "this", "that", "some"})
# The particles of sending something away, and the verbs that send with them.
_AWAY = frozenset({"out", "away"})
_SENDING = frozenset({"send", "get", "ship", "mail", "post", "dispatch"})
_OBJECTS = frozenset({"it", "them", "this", "that", "these", "those"})
# What ends a phrase: a sentence or clause mark before the next word, or a joining word.
_PHRASE_MARKS = frozenset(".,;!?\n")
_PHRASE_ENDS = frozenset({"and", "then", "or", "but", "so", "please", "pls", "asap", "by"})
_LONGEST = 6  # words in a destination phrase: longer is no place named
# The words before a facility that make it the one doing the work ("get it past legal").
_PAST = frozenset({"past", "through", "via"})
# What may stand before a request's own verb: a clause's start, a join, a courtesy.
_REQUEST_OPENERS = frozenset({"", "and", "then", "also", "please", "pls", "just", "you"})
# The words that take a thing to a place ("take it *to* the post room", "drop it *into* ...").
_TO_PLACE = frozenset({"to", "into"})
# The articles before an operation's name said as a noun: "a legal read", "the read".
_NAME_ARTICLES = frozenset({"a", "an", "the", "another", "its", "some"})
# How the question quotes the part, so the answer can take its place in the request.
ASKED = "Sorry, I'm not sure what you mean by “"
ASKED_END = "”."
# How a question about an operation's name lists the work it may mean.
WHICH_WORK = " I can arrange "


def unread_part(
    office: Office,
    readings: Readings,
    frame: TaskFrame,
    received: frozenset[str] = frozenset(),
) -> str | None:
    """The question about a part of the request that no task of ``frame`` carries, or None
    when every part is read. ``received``: who the message says gets a thing taken to a room
    (``room_receiver``), whom no room's question is then asked about."""
    if not frame.understood:
        return None
    destinations = {
        w for t in frame.tasks if t.destination for w in language.words(t.destination.lower())
    }
    run = {operation_of(office, t) for t in frame.tasks}
    items = {t.item for t in frame.tasks}
    left_out = operation_left_out(office, readings, run, items) or _place_left_out(
        office, readings, frame, received
    )
    if left_out is not None:
        return left_out
    phrase = (
        owned_facility(readings.mentions, readings.tokens, office)
        or unread_compound(
            office, readings.mentions, [t.text for t in readings.tokens], _inputs(office, frame)
        )
        or unread_sent_thing(readings.mentions, [t.text for t in readings.tokens])
        or unread_paper(readings.mentions, readings.tokens)
        or _unnamed(office, readings, frame)
        or _unknown_destination(readings, destinations)
        or _unsent(readings, destinations)
        or _service_left_out(office, readings, frame)
    )
    if phrase is None:
        return None
    return f"{ASKED}{phrase}{ASKED_END}{_means(office)} Could you tell me?"


def _unnamed(office: Office, readings: Readings, frame: TaskFrame) -> str | None:
    """The thing an errand's verb takes that no name of the office reads (``unnamed_thing``),
    less "the original" of a copy the frame makes: "make Zhang a copy of my document and
    bring me the original back" is the copy's own return (``original_back``), and less what
    the frame's own services make, said in a form the names do not list ("photocopy my form
    and bring me the copies")."""
    said = unnamed_thing(
        readings.mentions, readings.tokens, _unnamed_owners(readings, frame), frame.requester
    )
    if said is None or original_of_copy(said, frame.tasks):
        return None
    if _portion_of_the_asked(readings, said, frame):
        return None
    return None if _made_here(office, said, frame) else said


# the portions a thing is asked for in ("a pair", "a couple"), English, not the office's
_PORTIONS = english.words("portion_words")


def _portion_of_the_asked(readings: Readings, phrase: str, frame: TaskFrame) -> bool:
    """Whether ``phrase`` is only a portion ("a pair", "a couple") of the one thing the
    message names and the frame already carries: "I need safety glasses. Can you find me a
    pair?" asks for the glasses once, never for a "pair" of something unsaid."""
    said = phrase.lower().split()
    if not said or said[-1] not in _PORTIONS or len(said) > 2:
        return False
    named = {i for m in readings.mentions if m.kind == "item" for i in m.ids}
    return len(named) == 1 and all(t.item in named for t in frame.tasks) and bool(frame.tasks)


def _made_here(office: Office, phrase: str, frame: TaskFrame) -> bool:
    """Whether the noun ending ``phrase`` is, in any inflection, a word of the name of what
    one of the frame's services makes ("the copies" of a photocopy)."""
    noun = phrase.lower().split()[-1]
    forms = {noun, *language.lemmas(noun).get("NOUN", ())}
    for t in frame.tasks:
        op_id = operation_of(office, t)
        product = office.operation(op_id).product if op_id is not None else None
        if product is None:
            continue
        made = office.item_type(product)
        names = {w for p in (made.name, *made.synonyms, product) for w in p.lower().split()}
        if forms & names:
            return True
    return False


def _unnamed_owners(readings: Readings, frame: TaskFrame) -> frozenset[str | None]:
    """Whose things the tasks carry where no name of the thing was said: read from a plain
    noun by another stage ("take my lease to Ines to be stamped": my one paper to stamp)."""
    named = {i for m in readings.mentions if m.kind == "item" for i in m.ids}
    return frozenset(t.owner for t in frame.tasks if t.item not in named)


def _inputs(office: Office, frame: TaskFrame) -> frozenset[str]:
    """The item types the frame's operations take as their input, each on its task's item."""
    found: set[str] = set()
    for t in frame.tasks:
        op_id = operation_of(office, t)
        if op_id is not None and t.item is not None and office.operation(op_id).input == t.item:
            found.add(t.item)
    return frozenset(found)


def operation_left_out(
    office: Office, readings: Readings, run: set[str | None], items: set[str | None]
) -> str | None:
    """The question about an operation of the office named in the request ("a legal read")
    on one of ``items`` that none of the operations in ``run`` is; None when there is none.
    The question names the operations the words may mean, so the answer can choose one."""
    tokens = readings.tokens
    words = [t.word for t in tokens]
    office_words = {
        k
        for m in readings.mentions
        if m.kind in ("person", "item", "facility", "place")
        for k in range(m.start, m.end)
    }
    for op in office.operations:
        if op.input is None or op.input not in items or op.id in run or not op.verbs:
            continue
        at = _said_at(words, normalize(op.name).split(), office_words | _words_of_things(readings))
        if at is None:
            continue
        head = normalize(op.name).split()[-1]
        meant = [
            o.name
            for o in office.operations
            if o.input == op.input and normalize(o.name).split()[-1:] == [head]
        ]
        phrase = " ".join(t.text for t in tokens[at[0] : at[1]])
        offer = " or ".join(f"a {n}" for n in dict.fromkeys(meant))
        return f"{ASKED}{phrase}{ASKED_END}{WHICH_WORK}{offer}. Could you tell me?"
    return None


def names_work(office: Office, question: str, answer: str) -> bool:
    """Whether ``answer`` to a question of ``operation_left_out`` names work: a word of an
    operation's name or one of its verbs ("the legal one", "vet it"); "Me." names none, and
    must not take the place of the work asked about."""
    if WHICH_WORK not in question:
        return True
    said = set(language.words(answer.lower()))
    words = {
        w
        for op in office.operations
        for phrase in (op.name, *op.verbs)
        for w in normalize(phrase).split()
    }
    return bool(said & words)


def _place_left_out(
    office: Office, readings: Readings, frame: TaskFrame, received: frozenset[str]
) -> str | None:
    """The question about a place of the office the request takes something to ("print my
    agenda and take it to the post room") that no task goes to: no task's facility, source,
    operation or person is there. The robot hands things to people, so who there gets it
    is asked (naming who looks after it), never the place dropped and the item brought back
    to the requester."""
    tokens = readings.tokens
    # "to the post desk for Grace's meeting": where Grace's meeting is; she gets it
    # "Zhang needs it. take it to the meeting room": Zhang, said to need it, gets it
    occasions = occasion_people(tokens, readings.mentions) | received
    if occasions and all(t.recipient in occasions for t in frame.tasks):
        return None
    for m in readings.mentions:
        if m.kind not in ("place", "facility") or m.start < 1:
            continue
        k = m.start - 1
        while k > 0 and tokens[k].word in _NP_OPENERS:
            k -= 1
        if tokens[k].word not in _TO_PLACE:
            continue
        if in_time_clause(tokens, k):
            continue  # "freeze it before it comes into the studio": when, not where
        if m.kind == "place":
            facilities = [f for f in office.facilities if f.location == m.id]
        elif office.facility(m.id).operations:
            facilities = [office.facility(m.id)]  # "to the legal desk": that desk's work
        else:
            # a store that runs nothing, named as the way to its room ("down to the kit
            # room", the kit cage's other name): the room, where the washing machine is too
            room = office.facility(m.id).location
            facilities = [f for f in office.facilities if f.location == room]
        if _goes_to(office, frame, m.id if m.kind == "place" else None, facilities):
            continue
        there = [p.id for p in office.people if m.kind == "place" and p.location == m.id]
        keepers = list(dict.fromkeys([*(g for f in facilities for g in f.guards), *there]))
        names = " or ".join(office.person(g).name for g in keepers)
        kept = f" ({names} {'is' if len(keepers) == 1 else 'are'} there.)"
        phrase = " ".join(t.text for t in tokens[k : m.end])
        return (
            f"{ASKED}{phrase}{ASKED_END} I hand things to people, not to rooms: who "
            f"there should get it?{kept if keepers else ''}"
        )
    return None


def _goes_to(
    office: Office, frame: TaskFrame, place: str | None, facilities: Sequence[Facility]
) -> bool:
    """Whether a task of ``frame`` goes to the place or to one of its facilities."""
    ids = {f.id for f in facilities}
    where = {p.id: p.location for p in office.people}
    ops = {op for f in facilities for op in f.operations}
    for t in frame.tasks:
        if t.facility in ids or t.source in ids or t.owner in ids or operation_of(office, t) in ops:
            return True
        people = [p for p in (t.recipient, t.actor, t.owner, t.source) if p]
        if place is not None and any(where.get(p) == place for p in people):
            return True
    return False


def items_named(readings: Readings) -> set[str | None]:
    """The office's item types the request names."""
    return {m.id for m in readings.mentions if m.kind == "item"}


def _words_of_things(readings: Readings) -> set[int]:
    """Where a service's verb was read as a plain word of a thing's noun phrase ("the print
    queue file", "Gwen's file on the shred bins", the lexicon's ``_noun_use`` and
    ``_topic_of_thing``): the name of a thing or its topic, no work asked."""
    return {m.start for m in readings.mentions if m.kind == "word" and m.in_name}


def _said_at(
    words: Sequence[str], name: Sequence[str], office_words: set[int]
) -> tuple[int, int] | None:
    """Where an operation's name is said as a noun, its article kept with it: the whole name
    of two words or more ("legal read"), or its head noun right after an article ("a read",
    "the courier"); never inside the name of a person, item, facility or place ("the post
    desk")."""
    n = len(name)
    if not n:
        return None
    for k in range(len(words) - n + 1):
        if office_words & set(range(k, k + n)) or list(words[k : k + n]) != list(name):
            continue
        if n >= 2:
            return (k - 1 if k and words[k - 1] in _NAME_ARTICLES else k), k + n
    for k in range(1, len(words)):
        if k not in office_words and words[k] == name[-1] and words[k - 1] in _NAME_ARTICLES:
            return k - 1, k + 1
    return None


def asked_part(question: str) -> str | None:
    """The part of the request a question of ``unread_part`` asked about, in the requester's
    words; None for any other question."""
    if not question.startswith(ASKED) or ASKED_END not in question:
        return None
    return question[len(ASKED) : question.index(ASKED_END)]


def _means(office: Office) -> str:
    """How this office sends things out, for the requester's answer."""
    said = ways_out([op for op in office.operations if op.sends_out])
    return f" {said}" if said else ""


def _unknown_destination(readings: Readings, destinations: set[str]) -> str | None:
    tokens, gaps = readings.tokens, readings.gaps
    at = _mention_at(readings.mentions)
    for n, t in enumerate(tokens):
        if t.word not in _TO or n + 1 >= len(tokens) or _ends_before(tokens, gaps, n + 1):
            continue
        first = tokens[n + 1]
        if first.word not in _NP_OPENERS:
            continue  # "to sign", "to me", "to Bram": a purpose, or the lexicon's own
        if not n or tokens[n - 1].word not in _NO_VERB:
            continue  # "fax it to the bank", "my letter to the owners": a verb's or a noun's
        end = _phrase_end(tokens, gaps, n + 2)
        span = range(n + 1, end)
        if end == n + 2 or any(at[k].kind != "word" for k in span if k in at):
            continue  # "to the": no noun; "to the post room": a place of the office
        if readings.outside is not None and readings.outside.holds(n + 1):
            continue  # a send-out service's destination, read by the readings stage
        words = {tokens[k].word for k in span} - _NP_OPENERS
        if words & destinations:
            continue
        start = n - 1 if tokens[n - 1].word in _PARTICLES else n
        return " ".join(tok.text for tok in tokens[start:end])
    return None


def _unsent(readings: Readings, destinations: set[str]) -> str | None:
    """ "send it out" with no task sending anything out: the sending is a part unread."""
    if destinations:
        return None
    tokens = readings.tokens
    for n, t in enumerate(tokens):
        if t.word not in _AWAY or n < 2:
            continue
        nxt = tokens[n + 1].word if n + 1 < len(tokens) else ""
        if nxt == "of":
            continue  # "get it out of the fridge": from a place
        verb, obj = tokens[n - 2].word, tokens[n - 1].word
        if obj in _OBJECTS and language.verb_lemmas(verb) & _SENDING | ({verb} & _SENDING):
            return " ".join(tok.text for tok in tokens[n - 2 : n + 1])
    return None


def _service_left_out(office: Office, readings: Readings, frame: TaskFrame) -> str | None:
    """A service's verb said ("courier", "vet") on an item some task carries, where no task
    runs that service: the words from the verb to the end of its clause."""
    items = {t.item for t in frame.tasks}
    run = {operation_of(office, t) for t in frame.tasks}
    tokens, gaps = readings.tokens, readings.gaps
    for m in readings.mentions:
        if m.kind != "cue":
            continue
        verb = tokens[m.start].word
        before = tokens[m.start - 1].word if m.start and not tokens[m.start].opens else ""
        if before not in _REQUEST_OPENERS:
            continue  # "so he can post it", "to be faxed": someone else's work, a purpose
        said = [
            op
            for op in office.operations
            if op.input in items
            and op.sends_out
            and (verb in op.verbs or bool(language.verb_lemmas(verb) & set(op.verbs)))
        ]
        if said and not any(op.id in run for op in said):
            end = _phrase_end(tokens, gaps, m.end)
            return " ".join(tok.text for tok in tokens[m.start : end])
    for m in readings.mentions:
        # "past legal", "through the laminator": the facility as where the work is done
        # (not "from/at the post desk": where an item is)
        if m.kind != "facility" or not m.start or tokens[m.start - 1].word not in _PAST:
            continue
        offered = [office.operation(op) for op in office.facility(m.id).operations]
        said = [op for op in offered if op.input in items]
        if said and not any(op.id in run for op in said):
            return " ".join(tok.text for tok in tokens[m.start - 1 : m.end])
    return None


def _mention_at(mentions: Sequence[Mention]) -> dict[int, Mention]:
    return {k: m for m in mentions for k in range(m.start, m.end)}


def _ends_before(tokens: Sequence[Token], gaps: Sequence[str], k: int) -> bool:
    """Whether a sentence or clause mark stands before token ``k``."""
    return tokens[k].opens or any(c in _PHRASE_MARKS for c in gaps[k])


def _phrase_end(tokens: Sequence[Token], gaps: Sequence[str], k: int) -> int:
    """Where the noun phrase running on from token ``k`` ends (exclusive)."""
    stop = min(len(tokens), k + _LONGEST)
    while k < stop and not _ends_before(tokens, gaps, k) and tokens[k].word not in _PHRASE_ENDS:
        k += 1
    return k
