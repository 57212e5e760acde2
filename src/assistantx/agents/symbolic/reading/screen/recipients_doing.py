"""What the one a request gives to will do with it, said after it: "Please take my lab book
over to Renée. She needs to check my results before the write-up", "Bring my draft to Omar.
He has to look over my figures first", "Take my binder to Kai, he wants to compare my
readings". After a complete request that names one colleague to give to, a piece whose
subject is that colleague ("he", "she", "they", or the name) and which says their own plan
("needs to", "has to", "wants to" + a verb) says why: context only. Its doing is theirs, never
work asked of me, and what it works on ("my results", "my figures") is nothing to fetch nor
to ask about, even where its verb is one of the office's services ("check").

A need of a thing ("He also needs my stapler") is a second request, read as before, and so
is a person's work on the thing handed ("she needs to stamp it", "he has to sign it") and a
plan on a thing the office has ("she needs to sign my form": which form goes is asked as
before); a piece after a request that names nobody, or two colleagues, or no thing of its
own ("take it to Kai, he wants to compare my readings": "it" may be what he compares), is
read as before.

The same holds for a made thing handed on ("print my report and take it to Zhang, he wants to
go through the figures") and for what the thing the plan works on names only as its topic:
a thing of the office said with no owner ("she wants to go through *the invoices*") is what
they will look at, not a thing to fetch; one said as someone's ("my form") is read as before.

An outsider's want after a complete request ("Could you bring me a stapler? A visitor wants to
pin up a poster", "Could you borrow a camera for me? A reader wants a photo of the display
case"): the subject is a person named by what they are (``outsider_need.outsider_subject``),
and what they want or want to do is why the request is made; nothing it names is fetched or
asked about. One said as an addition ("a visitor wants a pen *too*"), or alone with no request
before it ("a visitor wants a coffee"), is read as before. The words are English's
(``data/english.yaml``); nothing here knows an office."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.obligation import PERSON_WORK
from assistantx.agents.symbolic.reading.outsider_need import outsider_subject
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.own_doing import after_plan, infinitive
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.recipients_reason import party_ids
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english, language

# "needs to", "has to", "wants to", "has got to", "must": a colleague's plan or obligation
_PLAN = frozenset({"needs", "need", "has", "have", "wants", "want", "got", "must", "gotta"})
_BETWEEN = frozenset({"still", "just", "really", "first", "got", "probably"})
_THIRD = frozenset({"he", "she", "they"})
# what points back to the thing asked for ("she needs to stamp *it*")
_BACK = frozenset({"it", "them", "this", "that", "these", "those"})
# an outsider's want: "wants", "needs", "would like", "could do with"
_WANTS = tuple(
    sorted(
        {(w,) for w in english.words("need_verbs")}
        | {tuple(p.split()) for p in english.entries("modal_wants")},
        key=len,
        reverse=True,
    )
)
_ADDED = frozenset(english.entries("in_addition"))  # "a visitor wants a pen too": one more
_LONGEST_SUBJECT = 6  # "my two young guests of ours" at most
# whose a thing is, said before it ("*my* form"): the thing is someone's, read as before
_OWNERS = frozenset({"my", "our", "your", "his", "her", "their"})
# the finding's meaning: the parser reads no guess of the request's thing in such a piece
RECIPIENTS_DOING = "what the colleague the request names will do: context"
OUTSIDERS_REASON = "what someone from outside wants, why the request is made: context"
ASIDES = frozenset({RECIPIENTS_DOING, OUTSIDERS_REASON})


def recipients_doing(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    acts = piece.acts
    if piece.asks or acts.imperative or acts.question is not None:
        return None
    earlier = [
        p for p in msg.pieces if p.end <= piece.start and (p.acts.request or p.acts.imperative)
    ]
    if not any(m.kind == "item" and not m.guessed for p in earlier for m in p.lexed.mentions):
        return None  # "take it to Kai. He wants ...": the request's thing may be the one said
    words = content(piece.words)
    mentions = piece.lexed.mentions
    if _said_as_added(words):
        return None  # "Zhang wants a pen too": one more thing, a second request
    outsiders = _outsiders_want(words)
    if outsiders is not None:
        return _outsiders_reason(piece, outsiders)
    parties = {i for p in earlier for i in party_ids(p)} - {requester}
    if len(parties) != 1:
        return None  # nobody to give to, or two: whom "she" means is read as before
    people = [m for m in mentions if m.kind == "person"]
    if words[:1] and words[0] in _THIRD:
        if people:
            return None  # "she needs to check Wang's ...": another colleague, read as before
        rest = after_plan(words[1:], _PLAN, _BETWEEN)
    else:
        first = people[0] if people else None
        if first is None or first.start != 0 or first.possessive or set(first.ids) != parties:
            return None
        if len(people) > 1:
            return None
        rest = after_plan(
            content([t.word for t in piece.lexed.tokens[first.end :]]), _PLAN, _BETWEEN
        )
    if not rest or not infinitive(words, rest):
        return None  # "he also needs my stapler": a thing needed, a second request
    if rest[0] in PERSON_WORK or set(rest[1:4]) & _BACK:
        return None  # "she needs to stamp it": a person's work on the thing, read as before
    if _owned_thing(piece):
        return None  # "she needs to sign my form": a thing of someone's, read as before
    return Finding("statement", piece, RECIPIENTS_DOING)


def _outsiders_reason(piece: Piece, wanted: list[str]) -> Finding | None:
    """ "a reader wants a photo of the display case", "a visitor wants to pin up a poster":
    why the request before is made, context; a colleague or someone's thing named in it ("a
    visitor wants Wang's stapler") and a person's work on the thing ("the courier needs to
    sign it") are read as before."""
    if any(m.kind == "person" for m in piece.lexed.mentions) or _owned_thing(piece):
        return None
    if wanted[:1] != ["to"]:
        return Finding("statement", piece, OUTSIDERS_REASON)  # "wants a photo of ..."
    rest = wanted[1:]
    if not rest or rest[0] not in language.verb_lemmas(rest[0]):
        return None
    if rest[0] in PERSON_WORK or set(rest[1:4]) & _BACK:
        return None
    return Finding("statement", piece, OUTSIDERS_REASON)


def _said_as_added(words: list[str]) -> bool:
    """Whether the piece says "too" / "also" / "as well": a want added to the request's."""
    joined = f" {' '.join(words)} "
    return any(f" {w} " in joined for w in _ADDED)


def _outsiders_want(words: list[str]) -> list[str] | None:
    """The words after an outsider's want ("a visitor wants *to pin up a poster*", "a reader
    wants *a photo of the display case*"); None where the piece opens with no such want."""
    for n in range(2, min(len(words), _LONGEST_SUBJECT + 1)):
        if not outsider_subject(words[:n]):
            continue
        rest = tuple(words[n:])
        want = next((w for w in _WANTS if rest[: len(w)] == w), None)
        if want is None:
            return None
        after = list(rest[len(want) :])
        return after or None
    return None


def _owned_thing(piece: Piece) -> bool:
    """Whether a thing of the office in ``piece`` is said as someone's ("my form", "Wang's
    stapler"), not only named as what the plan looks at ("the invoices")."""
    tokens = piece.lexed.tokens
    mentions = piece.lexed.mentions
    owners = {m.end for m in mentions if m.kind == "person" and m.possessive}
    return any(_owned(m, tokens[m.start - 1].word if m.start else "", owners) for m in mentions)


def _owned(m: Mention, before: str, owners: set[int]) -> bool:
    return m.kind == "item" and not m.guessed and (before in _OWNERS or m.start in owners)
