"""What a record or system wants, said after the request: "I need something to weigh this bag
of nails on. the register wants weights in grams", "bring me a finds bag, the database needs
everything bagged". A thing that is no colleague, no outsider, no machine or place of the
office (a register, a catalogue, the system) wanting something that is no work of the office
says why the request is made; the robot can hand it nothing. Read as a want of its own, "the
register" was asked about as a person nobody knew, after the request had been understood.
The clause is dropped before reading; said alone (nothing asked before it), or with a
colleague, an outsider ("the client wants ...") or a machine or thing the office names ("the
kettle needs water", "the storybook needs moving") as its subject, it is read as before."""

from __future__ import annotations

import re
from collections.abc import Callable, Container

from assistantx.core import english, language

_PEOPLE_NOUNS = (
    english.words("outsider_nouns") | english.words("role_nouns") | english.words("self_words")
)
_WANT = r"(?:wants|want|needs|need|requires|require|asks\s+for|expects|insists\s+on)"
_CLAUSE = re.compile(
    # a pause or a sentence's end after the request, perhaps "as"/"because"
    r"(?P<cut>\s*(?:[,;.!?]+|\s[-–—]+)\s*(?:(?:as|because|cos|coz|since)\s+)?)"
    r"(?:the|our|this|that)\s+(?P<who>[^\W\d_]+(?:\s+[^\W\d_]+)?)\s+"
    rf"{_WANT}\s+(?P<want>[^,;.!?]+)[.!]*\s*$",
    re.IGNORECASE,
)


def without_thing_wants(
    text: str, is_person_word: Callable[[str], bool], machine_words: Container[str]
) -> str:
    """``text`` without a closing clause in which a thing that is no person, machine or place
    wants something ("..., the register wants weights in grams"). ``machine_words``: the
    words of the office's machines, places and work, and its things' one-word names."""
    m = _CLAUSE.search(text)
    if m is None or not text[: m.start("cut")].strip():
        return text
    who = [w.lower() for w in m.group("who").split()]
    if any(is_person_word(w) or w in _PEOPLE_NOUNS or w in machine_words for w in who):
        return text  # "..., the client wants a copy", "..., the kettle needs water"
    if m.group("want").lower().startswith("to "):
        return text  # "..., the carpenters want to check it": someone's intention, told
    wanted = [
        w
        for w in re.findall(r"[^\W\d_]+", m.group("want").lower())
        if not language.is_function_word(w)
    ]
    if any(is_person_word(w) or w in machine_words for w in wanted):
        return text  # "..., the form needs Wang's signature": work asked of the office
    if not all(language.is_noun(w) for w in who) or language.is_function_word(who[-1]):
        return text
    return text[: m.start("cut")]
