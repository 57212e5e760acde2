"""A thing named only by the requester's habit: "the usual", "my usual", "the same as last
time", "same again". The robot keeps no record of what anyone had before, so the words name
nothing it can know: read as a thing's name they were declined as one the place lacks ("there
is no usual at the stores"), or the place's one thing was guessed. They are asked about
instead: which thing, listing what the place named keeps or makes ("Which would you like from
the stores: gloves, batteries or dust mask?"), or plainly which thing where no place is named.

Only where the habit stands for the thing: a request that names one of the office's things
("my usual coffee", "a coffee, same as last time") is read as that thing, and "as usual" (a
manner) is no such phrase. The phrases are english.yaml's ``usual_phrases``."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english
from assistantx.core.office import Office

_PHRASES = tuple(tuple(p.split()) for p in english.entries("usual_phrases"))
# each phrase's own word, after its determiner ("usual", "same"): a message without one of
# them says none of the phrases (looked for before the phrases are)
_OWNERS = frozenset({"the", "my", "our", "his", "her", "their"})
_KEYS = frozenset(next(w for w in p if w not in _OWNERS) for p in _PHRASES)
# The words that may follow the phrase where it is the whole object: a place, whom it is for,
# when, a courtesy, a join ("the usual *from* stores", "my usual *please*"); any other word
# goes on the thing's name ("my usual latte": a latte, however the office reads it).
_OBJECT_ENDS = frozenset(
    {"from", "at", "in", "for", "to", "and", "then", "again", "today", "now", "too", "if"}
    | {"when", "asap", "thanks", "thank", "thx", "cheers", "ta", "x", "on", "off"}
    | english.words("polite")
)


def _says_usual(tokens: Sequence[Token]) -> bool:
    """Whether one of the phrases stands as a whole object: at the end, before a pause, or
    before a word that opens another phrase."""
    words = [t.word for t in tokens]
    if _KEYS.isdisjoint(words):
        return False
    for p in _PHRASES:
        for k in range(len(words) - len(p) + 1):
            if tuple(words[k : k + len(p)]) != p:
                continue
            after = k + len(p)
            if after == len(tokens) or tokens[after].after_pause or tokens[after].opens:
                return True
            if words[after] in _OBJECT_ENDS:
                return True
    return False


def usual_asked(office: Office, lexed: Lexed) -> str | None:
    """The question of which thing is meant where the request names its thing only by habit
    ("bring me the usual from stores"); None where it names none so, or names a thing."""
    if not _says_usual(lexed.tokens) or any(m.kind == "item" for m in lexed.mentions):
        return None
    kept: list[str] = []
    where = ""
    for m in lexed.mentions:
        if m.kind == "facility":
            facilities = [office.facility(i) for i in m.ids]
        elif m.kind == "place":
            facilities = [f for f in office.facilities if f.location in m.ids]
        else:
            continue
        for f in facilities:
            kept += [office.item_type(t).name for t in f.products]
            kept += [office.item_type(s.type).name for s in f.supplies]
        if kept:
            where = f" from the {facilities[0].name}" if len(facilities) == 1 else ""
            break
    known = "I don't know what you usually have."
    if not kept:
        return f"Which thing would you like? {known} Please tell me what to bring."
    names = list(dict.fromkeys(kept))
    if len(names) == 1:  # "Which would you like: notepad?" asks nothing
        return f"Which thing would you like{where}? It has {names[0]}. {known}"
    listed = f"{', '.join(names[:-1])} or {names[-1]}"
    return f"Which would you like{where}: {listed}? {known}"
