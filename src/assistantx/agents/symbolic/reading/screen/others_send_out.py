"""Others' send-out: "Dev's contract needs couriering to Leeds", "Pat's letter needs to be
posted": a colleague's thing said to need one of the office's send-out services, with no
request wording. Sending a thing out of the office cannot be undone, and only its owner's
word is the owner's request (the speaker's own "my contract needs couriering" is read as
before): it is asked about ("Shall I courier it?"), never sent on a statement."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language

_NEEDS = frozenset({"needs", "need"})
# "Dev's *signed* contract": the words the owner's name may stand from the thing
_OWNER_REACH = 2
# "Dev's contract *really* needs", "... needs *to be* couriered": words around "needs"
_NEED_REACH = 2


def others_send_out(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return None
    if not terms.send_out_verbs:
        return None
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    owner = _owner_first(mentions)
    if owner is None or requester in owner.ids:
        return None
    thing = next((m for m in mentions if m.kind == "item" and m.start >= owner.end), None)
    if thing is None or thing.start - owner.end > _OWNER_REACH:
        return None
    words = [t.word for t in tokens]
    at = next(
        (
            n
            for n in range(thing.end, thing.end + _NEED_REACH + 1)
            if n < len(words) and words[n] in _NEEDS
        ),
        None,
    )
    if at is None:
        return None
    verb_at = at + 3 if words[at + 1 : at + 3] == ["to", "be"] else at + 1
    if verb_at >= len(words) or words[verb_at] not in terms.send_out_verbs:
        return None
    verb = _base_verb(terms, words[verb_at])
    whose = tokens[owner.start : owner.end]
    name = " ".join(t.text for t in whose).removesuffix("'s").removesuffix("’s")
    said = " ".join(t.text for t in tokens[thing.start : thing.end])
    rest = _after_word(_sentence(msg.text, piece.start), tokens[verb_at].text)
    return Finding(
        "statement",
        piece,
        "a colleague's thing said to need sending out: asked, never sent on a statement",
        message=f"Sending {name}'s {said} out of the office can't be undone.",
        offer=f"{verb} {name}'s {said}{rest}",
        shall=f"Shall I {verb} it{rest}?",
    )


def _owner_first(mentions: tuple[Mention, ...]) -> Mention | None:
    """The colleague whose thing opens the piece ("Dev's contract ..."), if any."""
    first = next((m for m in mentions if m.kind != "word"), None)
    if first is None or first.kind != "person" or not first.possessive:
        return None
    return first


def _base_verb(terms: Terms, form: str) -> str:
    """The send-out service's own verb that ``form`` is a form of ("posting": "post")."""
    for op in terms.office.operations:
        if not op.sends_out:
            continue
        for verb in op.verbs:
            if form in language.verb_forms(verb.split()[0]):
                return verb
    return form


def _sentence(text: str, start: int) -> str:
    """The sentence of ``text`` from ``start`` on: a piece may end at a comma that only
    splits an address ("to Acme Ltd, 12 Mill Lane"), which the destination keeps."""
    end = re.search(r"[.!?;]", text[start:])
    return text[start:] if end is None else text[start : start + end.start()]


def _after_word(text: str, word: str) -> str:
    """What ``text`` says after ``word`` ("... couriering *to Leeds, 12 Mill Lane*"), its
    commas kept, its closing punctuation not."""
    found = re.search(rf"\b{re.escape(word)}\b", text)
    if found is None:
        return ""
    return text[found.end() :].rstrip(" .!?")
