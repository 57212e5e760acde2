"""Unsupported service: "scan my contract" or "make me a cup of tea" where nothing in the
office offers it: declined, never swapped for something else; the speaker's own doing
("I need to pay the bill") beside a request is context."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece, sub_pieces
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content


def unsupported(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    found = unsupported_service(terms, piece)
    if found is not None and own_doing(terms, piece) and asked_elsewhere(terms, msg, piece):
        # "I need to pay the bill. Could you bring me a calculator?": what the speaker
        # will do themselves is context for the request beside it, not asked of me
        return Finding("statement", piece, "the speaker's own doing, context only")
    return found


def own_doing(terms: Terms, piece: Piece) -> bool:
    """ "I need to pay ...", "we have to scan ...": the speaker's own activity ("to"
    and a verb after a first-person subject), not "I need you to ..."."""
    w = content(piece.words)
    if not w or w[0] not in terms.self_words or set(w) & {"you", "u"}:
        return False
    return "to" in w[1:4]


def asked_elsewhere(terms: Terms, msg: Message, piece: Piece) -> bool:
    return any(p.acts.request for p in msg.pieces if p is not piece)


def unsupported_service(terms: Terms, piece: Piece) -> Finding | None:
    for sub in sub_pieces(piece):
        words = sub.words
        at = sub.verb_at(terms.en.lead_in)
        if at < len(words) and words[at] in terms.en.service_verbs:
            verb = words[at]
            nxt = words[at + 1] if at + 1 < len(words) else ""
            ours = verb in terms.lex.cue_words or verb in terms.office_words
            if not ours or (verb not in terms.lex.cue_words and nxt in DETERMINERS):
                return decline_service(terms, piece, verb)
        cue = next((n for n, w in enumerate(words) if terms.request_verb(words, n)), None)
        if cue is None:
            continue
        for n in range(cue + 1, len(words)):
            w = words[n]
            if w in terms.en.modifier_prepositions or words[n - 1] in ("my", "our"):
                break
            if w in terms.en.service_products and w not in terms.office_words:
                if possessive_of_name(piece.text, w, terms.office_words):
                    continue  # "Chip's scanner": a colleague's, not "chips"
                return decline_service(terms, piece, w, product=True)
    return None


def decline_service(terms: Terms, piece: Piece, word: str, *, product: bool = False) -> Finding:
    what = f"get you any {word}" if product else word  # "any": mass and count nouns alike
    return Finding(
        "unsupported",
        piece,
        f"not offered here: {word}",
        message=(
            f"Sorry, I can't {what}: nothing in this office offers that, and I won't "
            f"swap it for something else. {terms.capabilities()}"
        ),
    )


# -- rewrites ------------------------------------------------------------------------


def possessive_of_name(text: str, word: str, office_words: frozenset[str]) -> bool:
    """Whether ``word`` ("chips") is how a name's possessive ("Chip's") was folded."""
    if not word.endswith("s") or word[:-1] not in office_words:
        return False
    return re.search(rf"\b{re.escape(word[:-1])}['’]s\b", text, re.IGNORECASE) is not None
