"""Unsafe: "set light to Reed's banner", "set off the fire alarm", "microwave my stapler":
declined with the reason, nothing fetched or moved. A fire, a false alarm or heating what is
no food puts people and the building in danger, whatever the purpose the message gives ("so
we can check the fireproofing took"), so the act is never read as an errand on its object.

A one-word act that is also a thing's name ("torch", "light", "microwave") is the act only in
the verb's place with an object after it ("torch Reed's banner"): "bring me a torch" fetches
the torch, "torch, please" asks for one. An office that heats things with the act's verb
("microwave my lunch" where a microwave heats lunches) offers it: the act on the operation's
own input is its service, on anything else it is declined."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import DETERMINERS, starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece, sub_pieces
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_UNATTENDED = tuple(tuple(e.split()) for e in english.entries("unattended_times"))
_ON = frozenset({"on", "running", "going"})
_WITH_OBJECT = frozenset(tuple(e.split()) for e in english.entries("unsafe_acts_with_object"))


def unsafe(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if _left_running(piece):
        return _declined(terms, piece, "leave a machine running unattended")
    for sub in sub_pieces(piece):
        words = sub.words
        at = sub.verb_at(terms.en.lead_in)
        for act in terms.en.unsafe_acts:
            if not starts_with(words, at, act):
                continue
            after = at + len(act)
            if (len(act) == 1 or act in _WITH_OBJECT) and not _has_object(piece, words, after):
                continue  # "torch please", "a light", "set off for home": no act on a thing
            if _offered(terms, msg, piece, act):
                continue
            return _declined(terms, piece, " ".join(act))
    return None


def _left_running(piece: Piece) -> bool:
    """ "leave the heat press on overnight", "keep the kiln running all weekend": a machine of
    the office left on with nobody there (english.yaml ``unattended_times``) is a fire risk."""
    if not any(m.kind == "facility" for m in piece.lexed.mentions):
        return False
    words = piece.words
    return any(
        words[n] in _ON and starts_with(words, n + 1, when)
        for n in range(len(words))
        for when in _UNATTENDED
    )


def _has_object(piece: Piece, words: list[str], after: int) -> bool:
    """Whether a noun phrase follows a one-word act: a determiner or pronoun ("the", "my",
    "it"), or a person's possessive name ("Reed's")."""
    if after >= len(words):
        return False
    if words[after] in DETERMINERS:
        return True
    tokens = piece.lexed.tokens  # "Reed's" is the token "reed", the word "reeds"
    return any(
        m.kind == "person"
        and m.possessive
        and words[after] in (tokens[m.start].word, tokens[m.start].word + "s")
        for m in piece.lexed.mentions
    )


def _offered(terms: Terms, msg: Message, piece: Piece, act: tuple[str, ...]) -> bool:
    """Whether the office offers the act as its operation on what is named: its verb is an
    operation's, and every item the piece names (else the message: "my lunch is in the
    fridge, microwave it") is that operation's input; nothing named at all is the service's
    own question to ask."""
    office = terms.office
    ops = [o for o in office.operations if act[0] in o.request_phrases]
    if not ops:
        return False
    inputs = {o.input for o in ops if o.input is not None}
    for lexed in (piece.lexed, msg.lexed):
        named = {i.split(":")[0] for m in lexed.mentions if m.kind == "item" for i in m.ids}
        if named:
            return named <= inputs
    return True


def _declined(terms: Terms, piece: Piece, said: str) -> Finding:
    return Finding(
        "destructive",
        piece,
        f"unsafe: {said}",
        message=(
            f"Sorry, I won't do that ({said}): fire, false alarms and heating things that "
            f"are not food put people and the building in danger. {terms.capabilities()}"
        ),
    )
