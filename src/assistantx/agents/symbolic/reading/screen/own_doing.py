"""Own doing: "could you bring me a magnifier? need to check the contacts": the speaker's own
need to do something that is no errand or service of the office ("check", "look over"), said
beside a request, is why the request is made. What it names ("the contacts") is the object of
the speaker's own activity, never the request's, so the piece is context, not read for tasks.
"I need to get my shoot printed" is no such piece: "get" is an errand's verb. A colleague's
work said as the speaker's own ("grab me a pen, gotta sign the contracts") is theirs to do,
and the doing is read before its place or thing is taken for a placement ("can u grab
bjorns laser, need to check levels on L2"). The speaker about to do a thing ("bring me goggles
and gloves, heading in to weigh", "..., about to print") is theirs too, even where it is a
service of the office: the going says who does it, so no service is run on the things
asked."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.obligation import PERSON_WORK
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english, language

_SPEAKER = frozenset({"i", "we", "id", "ive", "im", "ill"})
# "need to", "have to", "got to", "gotta", "want to": the speaker's own plan or obligation
_OWN_PLAN = frozenset({"need", "needs", "have", "has", "got", "want", "must", "gotta", "going"})
_BETWEEN = frozenset({"still", "just", "really", "also", "first", "ve", "got"})
# "heading in to", "about to": the speaker's own going to do a thing (english.yaml)
_ABOUT_TO = tuple(tuple(p.split()) for p in english.entries("own_about_to"))
_SPEAKER_IS = frozenset({"im", "i", "am", "just", "were", "we", "are"})
# "going to need a pen": a need said, asked, never the speaker's own doing
_NEEDING = english.words("need_verbs") | english.words("wanting_verbs")
# "going to get ...", "about to bring ...": an errand's verb, asked
_ERRANDS = english.words("handing_verbs") | english.words("dative_verbs")


def own_doing(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if piece.acts.imperative or piece.acts.question is not None or piece.asks:
        return None
    if not any(p.acts.request or _asks_for_a_thing(p) for p in msg.pieces if p is not piece):
        return None  # alone it may be the request itself: read on
    words = content(piece.words)
    wish = words[:2] in (["id", "like"], ["i", "would"], ["we", "would"])
    if words[:1] and words[0] in _SPEAKER:
        words = words[1:]
    if wish:  # "I'd like to look under the boiler": a plan of one's own, as "want to"
        words = ["want", *words[2 if words[:1] == ["would"] else 1 :]]
    if _about_to(words, terms.lex.operation_words):
        return Finding("statement", piece, "the speaker's own doing, context only")
    rest = after_plan(words, _OWN_PLAN, _BETWEEN)
    if not rest or rest[0] in terms.service_verbs:
        return None  # "need to heat it up": a service here, asked
    # "gotta sign the contracts": a colleague's work ("sign", "seal") done by the speaker
    # themselves, never asked of the robot; an errand ("get", "send") is asked
    own_work = rest[0] in PERSON_WORK
    if rest[0] in terms.lex.cue_words and not own_work:
        return None  # "need to get my shoot printed": an errand here, asked
    if own_work or infinitive(words, rest):
        return Finding("statement", piece, "the speaker's own doing, context only")
    if terms.request_verb(rest, 0):
        return None
    if rest[0] in terms.lex.items or rest[0] in terms.office_words:
        return None
    return Finding("statement", piece, "the speaker's own doing, context only")


def _about_to(words: list[str], office_verbs: frozenset[str]) -> bool:
    """Whether ``words`` (the speaker's subject dropped) say the speaker is about to do a
    thing: "heading in to weigh", "about to print the proofs" ("to", then a verb); a need
    ("going to need a pen") or an errand ("going to get ...") is asked. A verb of the
    office's own work is a verb where the dictionary lacks it ("about to degrease")."""
    while words and words[0] in _SPEAKER_IS:
        words = words[1:]
    for phrase in _ABOUT_TO:
        n = len(phrase)
        if tuple(words[:n]) == phrase and len(words) > n:
            verb = words[n]
            if verb in _NEEDING or verb in _ERRANDS:
                return False
            return verb in language.verb_lemmas(verb) or verb in office_verbs
    return False


def infinitive(words: list[str], rest: list[str]) -> bool:
    """Whether the plan's "to" is said and the word after it is a verb of English: "need to
    *book* in the delivery", "have to *file* the invoices" name the speaker's own doing by a
    verb, even where the same word names a thing of the office (a book, a file) or a
    service nothing here offers ("book"); read as the thing, the reason fetched a book or
    declined the whole request. The office's own errands and services are no such verb (the
    caller reads them as asked). "gotta" says no "to" ("gotta book?" is "got a book?")."""
    return words[0] != "gotta" and rest[0] in language.verb_lemmas(rest[0])


def after_plan(
    words: list[str], plans: frozenset[str], between: frozenset[str]
) -> list[str] | None:
    """The words after a plan's "need to" / "have to" / "gotta" (``plans``, with any of
    ``between`` before its "to"): "need to check the contacts" → "check the contacts"; None
    where the words open with no plan, or the plan is asked of someone ("I need you to ...")."""
    if not words or words[0] not in plans:
        return None
    rest = words[1:]
    while rest and rest[0] in between:
        rest = rest[1:]
    if words[0] != "gotta":
        if rest[:1] != ["to"]:
            return None  # "I need you to scan ...": asked of someone, read on
        rest = rest[1:]
    return rest


def _asks_for_a_thing(piece: Piece) -> bool:
    """ "Is there a loupe going spare?", "anyone got a torch?": a question about a thing of
    the office, a request in disguise, that the speaker's own doing beside it explains."""
    return piece.asks and any(m.kind == "item" for m in piece.lexed.mentions)
