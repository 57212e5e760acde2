"""An offer made to the assistant: "would you like a ruler?", "do you want a stapler?",
"fancy a coffee?", "can I get you a tea?".

English offers a thing by asking whether the one spoken to wants it (a verb of wanting whose
subject is "you", said or left out, and a thing as its object), or by the speaker proposing
to give the one spoken to something ("can I get *you* a tea?"). Said to the assistant, such a
message was most likely meant for a colleague (sent to the wrong chat); the assistant wants
nothing, and the speaker asked for nothing: it is a question, answered and met with "Shall I
bring you one?", never a fetch. It is no offer where the wanting takes an infinitive ("would
you like to bring me a pen?", "do you want to get me a stapler?": a request put politely) or
"me/us" ("do you want me to ...?"), nor where "you" gets a verb of its own ("can I get you to
bring me ...": a request)."""

from __future__ import annotations

from assistantx.core import english, language

_MODALS = english.words("request_modals") | frozenset({"do", "does", "did", "will", "shall"})
_YOU = frozenset({"you", "u", "ya", "yous", "yall"})
# "would anyone like a coffee?": the speaker offers the office at large, most likely in the
# wrong chat; nobody asked the assistant for anything
_GROUP = frozenset({"anyone", "anybody", "someone", "somebody", "everyone", "everybody"})
_WANTING = frozenset({"like", "love", "want", "fancy", "need"})
# "would you care for a tea?": a verb that wants with "for"
_WANTING_FOR = frozenset({"care"})
_SPEAKER = frozenset({"i", "we"})
_GIVING = english.words("dative_verbs") | frozenset({"get", "make", "bring", "fetch", "pour"})
# what may follow a verb of wanting and make it no offer of a thing
_NOT_A_THING = frozenset({"to", "me", "us", "it", "that", "this", "them", "him", "her"})


def offered(w: list[str], asks: bool) -> bool:
    """Whether the words ``w`` (lowercase, courtesy removed) offer the one spoken to a thing;
    ``asks``: the piece ends with a question mark, which a bare "fancy a coffee?" needs to be
    an offer rather than the speaker's own clipped "(I) fancy a coffee"."""
    k = 0
    if w[:1] and w[0] in _MODALS:
        if w[1:2] and w[1] in _SPEAKER:
            return _gives_you(w[2:])  # "can I get you a tea?"
        k = 1
    if w[k : k + 1] and w[k] in _YOU | _GROUP:
        k += 1
    elif k == 1 or not asks:
        return False
    if k == 1 and not (asks and w[0] in _YOU | _GROUP):
        return False  # "you want a pen?" is an offer only as a question
    rest = w[k:]
    if rest[:1] and rest[0] in _WANTING_FOR and rest[1:2] == ["for"]:
        rest = rest[2:]
    elif rest[:1] and rest[0] in _WANTING:
        rest = rest[1:]
    else:
        return False
    # "do you fancy getting me a coffee?": the wanting is of a doing, a request put politely
    return (
        bool(rest) and rest[0] not in _NOT_A_THING and not language.is_present_participle(rest[0])
    )


def _gives_you(rest: list[str]) -> bool:
    """ "get you a tea", "bring you one": a giving verb, "you" and a thing after it, never
    "get you to ...", which asks the one spoken to to do something."""
    return len(rest) > 2 and rest[0] in _GIVING and rest[1] in _YOU and rest[2] not in _NOT_A_THING
