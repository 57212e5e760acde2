"""An opinion about what a thing needs: "to be frank I think the book needs a full support,
not just stitching", "imo the meeting room could do with a bigger table", "honestly I reckon
the report needs a full rewrite". A hedge of the speaker's view ("I think", "I reckon", "in my
view", "to be honest", "personally") before a clause whose subject is a thing (no person, not
the speaker, not "you") and whose verb says what the thing needs or should have ("needs",
"could do with", "should have") is the speaker's view, told: with no request anywhere in the
message it asks nothing, and what it names is never a thing to fetch, nor one to decline as
missing ("there is no full support in this office"). It is answered in words.

A request anywhere in the message ("I reckon the printer needs paper, can you top it up") is
read as before, and so is a subject that is a person ("I think Zhang needs my stapler"), the
speaker ("I think I need a stapler") or unhedged ("the report needs printing"). Work the
office does, said as the need ("I think my report needs printing"), and "needs to" and a verb
("needs to go to Zhang") are read as before too: they name what to do."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language


def _phrases(key: str) -> tuple[tuple[str, ...], ...]:
    return tuple(sorted((tuple(p.split()) for p in english.entries(key)), key=lambda p: -len(p)))


_HEDGES = _phrases("opinion_hedges") + _phrases("stance_phrases")
_NEEDS = _phrases("opinion_needs")
_OPENERS = english.words("speech_openers")
_NOT_THINGS = english.words("subject_pronouns") | english.words("unnamed_doers")
_ASKING = english.words("request_markers") - {"like", "love"}
_YOU = english.words("addressee_pronouns")
# what may stand before the work or thing needed ("a full rewrite", "another good look")
_BEFORE_NEED = english.words("opinion_need_openers")
_SUBJECT_REACH = 5  # "the big table in room two": the longest subject read
_MODALS = english.words("request_modals") | frozenset({"should", "ought"})
# what opens the other side of the view ("..., not just stitching", "rather than a patch")
_CONTRASTS = _phrases("opinion_contrasts")


def opinion(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    others = [p for p in msg.pieces if p is not piece]
    if any(_asks(p) and not _viewed(terms, msg, p) for p in others):
        return None  # "I reckon the printer needs paper, can you top it up": asked
    if _viewed(terms, msg, piece):
        named = tuple(f"person:{p}" for p in terms.named(piece.lexed, "person") if p != requester)
        return Finding("statement", piece, "an opinion of what a thing needs, told", context=named)
    if _only_hedges(piece) and any(_viewed(terms, msg, p) for p in others):
        return Finding("statement", piece, "the hedge of the opinion, told")  # "in my view,"
    words = [t.word for t in piece.lexed.tokens]
    contrast = any(tuple(words[: len(c)]) == c for c in _CONTRASTS)
    if (
        contrast
        and not _asks(piece)
        and any(_viewed(terms, msg, p) for p in msg.pieces if p.end <= piece.start)
    ):
        return Finding("statement", piece, "what the opinion sets its need against, told")
    return None


def _viewed(terms: Terms, msg: Message, piece: Piece) -> bool:
    """Whether ``piece`` is a hedged view of what a thing needs, asking nothing itself."""
    acts = piece.acts
    if piece.asks or acts.imperative or acts.question is not None:
        return False
    words = [t.word for t in piece.lexed.tokens]
    start, hedged = _after_hedges(words)
    hedged = hedged or any(_only_hedges(p) for p in msg.pieces if p is not piece)
    if not hedged:
        return False  # "the report needs printing": read as before
    need = next(
        (
            (n, v)
            for n in range(start + 1, min(len(words), start + _SUBJECT_REACH + 1))
            for v in _NEEDS
            if tuple(words[n : n + len(v)]) == v
        ),
        None,
    )
    if need is None:
        return False
    at, verb = need
    if acts.request and verb[0] not in _MODALS:
        return False  # asked some other way; "could do with": the modal of the need
    if not _a_thing(terms, piece, words, start, at):
        return False
    rest = words[at + len(verb) :]
    if not rest or rest[0] == "to" or set(words[start:]) & (_YOU | _ASKING) - set(verb):
        return False  # "needs to go to Zhang", "needs you to look at it": what to do
    k = 0
    while k < len(rest) and rest[k] in _BEFORE_NEED:
        k += 1
    # "needs printing": the office's own work, read as before
    return not (k < len(rest) and _office_work(terms, rest[k]))


def _asks(piece: Piece) -> bool:
    acts = piece.acts
    return piece.asks or acts.request or acts.imperative or acts.question is not None


def _after_hedges(words: list[str]) -> tuple[int, bool]:
    """Where the clause begins after the openers and hedges that open ``words``, and whether
    one of them was a hedge of the speaker's view."""
    k, hedged = 0, False
    while k < len(words):
        phrase = next((h for h in _HEDGES if tuple(words[k : k + len(h)]) == h), None)
        if phrase is not None:
            k, hedged = k + len(phrase), True
        elif _stance_infinitive(words[k : k + 3]):
            k, hedged = k + 3, True  # "to be blunt": never a colleague called Frank
        elif language.is_stance_adverb(words[k]):
            k, hedged = k + 1, True  # "honestly", "personally"
        elif words[k] in _OPENERS:
            k += 1
        else:
            break
    return k, hedged


def _stance_infinitive(w: list[str]) -> bool:
    return len(w) == 3 and w[:2] == ["to", "be"] and language.is_stance_adverb(f"{w[2]}ly")


def _only_hedges(piece: Piece) -> bool:
    """ "to be honest,", "..., tbh": a piece of the message that is only a hedge."""
    words = [t.word for t in piece.lexed.tokens]
    end, hedged = _after_hedges(words)
    return hedged and end == len(words)


def _a_thing(terms: Terms, piece: Piece, words: list[str], start: int, at: int) -> bool:
    """Whether ``words[start:at]`` is a thing: no person (a possessive "Zhang's" only says
    whose), not the speaker, not "you", nobody unnamed."""
    subject = words[start:at]
    if set(subject) & (_NOT_THINGS | _YOU | terms.self_words - {"my", "our"}):
        return False
    for m in piece.lexed.mentions:
        if m.start < start or m.start >= at:
            continue
        if m.kind == "person" and not m.possessive:
            return False  # "I think Frank needs a stapler": his need
        if m.kind in ("self", "pronoun") and not m.possessive:
            return False
    return not language.is_finite_verb(subject[-1]) or subject[-1] in terms.thing_words


def _office_work(terms: Terms, word: str) -> bool:
    forms = {word} | language.verb_lemmas(word)
    return bool(forms & (terms.lex.cue_words | terms.lex.operation_words | terms.service_verbs))
