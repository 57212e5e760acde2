"""A test or instrument the office does not have, asked for with a verb that names no work of
its own: "run an NMR on my crude product", "can you do a CT scan of my parcel", "run a mass
spec on my sample", "get my sample through the PCR". The verb ("run", "do", "get": english.yaml
``generic_work_verbs``) picks no service by itself; the words beside it name the work, and
here they name nothing of the office. Reading the verb alone would run whatever service the
office has under it (the IR spectrometer's "run") and hand back its result, a wrong physical
action: declined, saying what the office's machines do, never another service run instead.

The work is named (a) by the words between "a"/"an" right after the verb ("do me a ...") and a
preposition before the thing worked on ("an NMR on my ...", "a CT scan of my ..."), or (b) by
the instrument said after "through", "on", "in", ... the thing ("my sample through the PCR").
Such a word names another test when the office knows it under no name (no mention of a thing,
product, service, facility or person covers it) and it is written in capitals ("NMR", "CT") or
the dictionary has no such word ("nmr", "spec"). Read as before: the office's own names ("run
an IR on my sample" where the spectrometer is "IR", "run a spectrum of my sample", "do a print
of my file", "do me a coffee"), plain English nouns ("run a check on my sample"), a particle
("run off 3 copies"), a plain instrument ("run my phone through the diagnostics rig"), and a
verb that names its service ("laminate my badge")."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece, sub_pieces
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.unknown_work import ADDRESSED
from assistantx.agents.symbolic.reading.screen.wrong_instrument import does
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office

_GENERIC = english.words("generic_work_verbs")
_COMMON = english.words("common")
# "do me a ...", "run us an ...": whom the work is for, before the work's name
_FOR = frozenset({"me", "us"})
_ARTICLES = frozenset({"a", "an"})
# what joins the work's name to the thing worked on: "an NMR on my sample", "a scan of it"
_OF_THING = frozenset({"on", "of", "for", "with", "in", "to"})
# what names the instrument after the thing: "my sample through the PCR"
_BY = frozenset({"through", "on", "in", "into", "with", "using", "via"})
_THE = frozenset({"the", "a", "an", "your", "our", "that", "this"})
# the longest name of a test said between the article and the preposition ("a mass spec")
_REACH = 3
# "I", "we" before the verb: the speaker's own doing, nothing asked of me
_SPEAKER = frozenset({"i", "id", "im", "ive", "we", "if"})


def unknown_test(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    for sub in sub_pieces(piece):
        words = sub.words
        at = _generic_verb_at(words, sub.verb_at(terms.en.lead_in))
        if at is None or set(words[:at]) & _SPEAKER:
            continue
        if at and not ((piece.acts.request or piece.asks) and set(words[:at]) & ADDRESSED):
            continue  # asked at the head ("run ..."), or put to me ("can you ...")
        lexed = terms.lex.read(sub.text)
        tokens, mentions = lexed.tokens, lexed.mentions
        if at >= len(tokens) or tokens[at].word != words[at]:
            continue  # the lexicon read the words otherwise: nothing to align
        named = _named_work(tokens, mentions, at) or _named_instrument(tokens, mentions, at)
        if named is None:
            continue
        return Finding(
            "unsupported",
            piece,
            f"a test or instrument the office does not have: {named}",
            message=(
                f"Sorry, there is no {named} here, and I won't run another machine in its "
                f"place. {_has(terms.office)} I did nothing."
            ),
        )
    return None


def _generic_verb_at(words: Sequence[str], at: int) -> int | None:
    """Where the generic verb is: the first word past the lead-in, or the "do" the lead-in
    took ("can you do a CT scan ...", "do me an NMR ...")."""
    for k in (at, at - 1, at - 2):
        if not 0 <= k < len(words):
            continue
        if k < at - 1 and words[at - 1] not in _FOR:
            return None
        if {words[k], *language.verb_lemmas(words[k])} & _GENERIC:
            return k
    return None


def _covered(mentions: Sequence[Mention], k: int) -> bool:
    """Whether token ``k`` is part of a name the office knows (a thing, a service, a place)."""
    return any(m.start <= k < m.end and m.kind != "word" for m in mentions)


def _foreign(token: Token, mentions: Sequence[Mention], k: int) -> bool:
    """Whether token ``k`` names something the office knows under no name: written in capitals
    ("NMR") or a word the dictionary lacks ("spec"), and no office name covers it."""
    text = token.text
    if not text.isalpha() or len(text) < 2 or _covered(mentions, k):
        return False
    if token.word in _COMMON:
        return False  # "in at 3", "on it": a plain word of English
    return text.isupper() or not language.lemmas(token.word)


def _thing_at(tokens: Sequence[Token], mentions: Sequence[Mention], k: int) -> bool:
    """Whether a thing (the speaker's or an item) is said from token ``k`` on ("my sample",
    "the sample"), never a person worked on ("on mrs hughes")."""
    starts = {k, k + 1} if k < len(tokens) and tokens[k].word in _THE else {k}
    return any(m.kind in ("item", "self") and m.start in starts for m in mentions)


def _named_work(tokens: Sequence[Token], mentions: Sequence[Mention], at: int) -> str | None:
    """ "run an NMR on my sample", "do me a CT scan of my parcel": the words between the
    article and the preposition, where one of them names nothing of the office."""
    k = at + 1
    if k < len(tokens) and tokens[k].word in _FOR:
        k += 1
    if k >= len(tokens) or tokens[k].word not in _ARTICLES:
        return None
    end = k + 1
    while end < len(tokens) and end - k <= _REACH and tokens[end].word not in _OF_THING:
        end += 1
    if end >= len(tokens) or end == k + 1 or tokens[end].word not in _OF_THING:
        return None
    if any(tokens[j].after_pause for j in range(k + 1, end + 1)):
        return None  # "do me a favour, ...": a clause of its own
    if not any(_foreign(tokens[j], mentions, j) for j in range(k + 1, end)):
        return None
    if not _thing_at(tokens, mentions, end + 1):
        return None
    return " ".join(t.text for t in tokens[k + 1 : end])


def _named_instrument(tokens: Sequence[Token], mentions: Sequence[Mention], at: int) -> str | None:
    """ "get my sample through the PCR": the thing right after the verb, then the
    instrument right after the thing."""
    k = at + 1
    if not _thing_at(tokens, mentions, k):
        return None
    # the item named within a few words ("my blood sample"), the thing's last word
    items = [m for m in mentions if m.kind == "item" and k <= m.start <= k + _REACH]
    if not items:
        return None
    thing = min(items, key=lambda m: m.start).end
    if thing >= len(tokens) - 1 or tokens[thing].word not in _BY:
        return None
    j = thing + 1
    while j < len(tokens) and tokens[j].word in _THE:
        j += 1
    if j < len(tokens) and _foreign(tokens[j], mentions, j):
        return tokens[j].text
    return None


def _has(office: Office) -> str:
    """What the office's machines do: "The IR spectrometer can IR scan samples; ..."."""
    said = [does(office, f) for f in office.facilities if f.operations]
    if not said:
        return "This office has no machine that works on things."
    return "; ".join([said[0], *(s[0].lower() + s[1:] for s in said[1:])]) + "."
