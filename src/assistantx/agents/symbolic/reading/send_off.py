"""A send-out service asked for by plain English rather than its own verb: "my scripts need
sending off to Edexcel", "send my scripts off to the exam board (WJEC)", "send my tunic to
Parkside Laundry to be laundered" (the readings stage, where the service's own verb found no
send-out).

"send" with "off", "out" or "away" before its "to" sends the item out of the office: the
service is the one send-out operation of the office that takes the item named (several, or
none: not read so, and the reader goes on as before). "send ... to <place> to be <done>"
names the service by its own verb's past participle, with or without the particle. "go",
"be sent" with "off", "out" or "away" ("could my vials go out on dry ice to Kessler Labs") say
the same of the item. A plain "send my papers to Ironbridge Records Store" sends out too when
what follows the "to" is a proper name of a place (capitalised words, one of them a word of a
place or firm, or a word nobody of the office is called; or capitalised words and the head
noun of a kind of place: "Westgate branch") that names nobody and nothing of the office.
What follows the "to" is then a destination outside, never a colleague to look up; a plain
"send my scripts to Bram" stays a hand-over.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping, Sequence

from assistantx.agents.symbolic.reading.destination import Outside, VerbPhrase, find_outside
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.named_place import named_place
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language

_SEND = frozenset(language.verb_forms("send")) | {"send"}
# Verbs of the item going out of the office, read as sending only with a particle ("go out").
_GO = frozenset(language.verb_forms("go")) | {"go"}
_PARTICLES = frozenset({"off", "out", "away"})
# "to be laundered", "to get resoled": the verbs before a send-out's participle
_WORK_AUX = frozenset({"be", "get"})
_CLAUSE_END = frozenset(".!?;,\n")
# how far after "send" its particle or "to" may stand: "send my signed rental form out on the
# van run to ..." puts ten words between (the clause's end bounds it too)
_REACH = 12


def sent_off(
    tokens: Sequence[Token],
    gaps: Sequence[str],
    mentions: Sequence[Mention],
    inputs: Mapping[str, str | None],
    done_forms: Mapping[str, frozenset[str]],
    names: Collection[int] = (),
) -> Outside | None:
    """The send-out asked for by "send ... off/out/away to X" or "send ... to X to be
    <done>". ``inputs``: each send-out operation's input item type; ``done_forms``: the forms
    of each one's verbs; ``names``: token indices inside a name of the office."""
    words = [t.word for t in tokens]
    items = {i for m in mentions if m.kind == "item" for i in m.ids}
    for k, word in enumerate(words):
        if word not in _SEND | _GO or k in names:
            continue
        if word in _GO and not _item_goes(tokens, gaps, mentions, k):
            continue  # "I'm going out to the bank": a person goes, nothing is sent
        stop = next(
            (j for j in range(k + 1, len(tokens)) if any(c in _CLAUSE_END for c in gaps[j])),
            len(tokens),
        )
        to = next((j for j in range(k + 1, min(stop, k + _REACH)) if words[j] == "to"), None)
        if to is None:
            continue
        operation = _named_after(words, to, stop, done_forms) if word in _SEND else None
        particle = bool(set(words[k + 1 : to]) & _PARTICLES)
        named = word in _SEND and _outside_name(tokens, mentions, to + 1, stop, names)
        if operation is None and (particle or named):
            taking = [op for op, item in inputs.items() if item in items]
            operation = taking[0] if len(taking) == 1 else None
        if operation is None:
            continue
        # the verb is this "send": an earlier one is no verb of it ("send ... send"); the
        # office's own names stay names, so an address's parts after its comma ("Café Lune,
        # 12 Mill Street") are read as the place's, never as a colleague
        others = {*names, *(n for n in range(k) if words[n] == word)}
        return find_outside(tokens, gaps, [VerbPhrase(operation, frozenset({word}), ())], others)
    return None


def _item_goes(
    tokens: Sequence[Token], gaps: Sequence[str], mentions: Sequence[Mention], k: int
) -> bool:
    """Whether the subject of the going verb at ``k`` is an item ("my vials *go* out"): an
    item named earlier in its clause, and no person nor pronoun of a person between."""
    start = k
    while start > 0 and not any(c in _CLAUSE_END for c in gaps[start]):
        start -= 1
    before = [m for m in mentions if start <= m.start < k]
    if any(tokens[j].word in _PERSONS for j in range(start, k)):
        return False
    return any(m.kind == "item" for m in before) and not any(m.kind == "person" for m in before)


_PERSONS = frozenset({"i", "im", "we", "you", "he", "she", "they", "someone", "somebody"})


def _outside_name(
    tokens: Sequence[Token],
    mentions: Sequence[Mention],
    start: int,
    stop: int,
    names: Collection[int],
) -> bool:
    """Whether the words from ``start`` to the clause's end (``stop``) are a proper name of
    a place outside ("Ironbridge Records Store", "Kessler Labs in Basel"): two or more
    capitalised words first (after "the"), none of them inside a name of the office
    (``names``: its places and people) but as part of a longer name ("Sam *Records*" in
    "Ironbridge Records Store"), and no item of the office among them."""
    k = start + 1 if start < stop and tokens[start].word == "the" else start
    run = k
    while run < stop and tokens[run].text[:1].isupper():
        run += 1
    # "Westgate branch": one capitalised word is a place's name when the head noun of a
    # place follows it (reading/named_place.py)
    if run - k < 2 and not (run > k and named_place(tokens[k - (k > start) : run + 1])):
        return False
    whole = [m for m in mentions if m.kind in ("person", "place", "facility", "group")]
    if any(m.start >= k and m.end >= run and m.start < run for m in whole):
        return False  # "to Nia Kessel", "to Nia at the desk": a colleague's whole name
    if any(m.start <= k < m.end for m in whole):
        return False  # the run starts inside a name of the office
    return not any(m.kind == "item" and k <= m.start < run for m in mentions)


def _named_after(
    words: Sequence[str], to: int, stop: int, done_forms: Mapping[str, frozenset[str]]
) -> str | None:
    """ "... to Parkside Laundry to be laundered", "... off to get resoled": the send-out its
    participle names."""
    for j in range(to, stop - 2):
        if words[j] == "to" and words[j + 1] in _WORK_AUX:
            named = [op for op, forms in done_forms.items() if words[j + 2] in forms]
            return named[0] if len(named) == 1 else None
    return None
