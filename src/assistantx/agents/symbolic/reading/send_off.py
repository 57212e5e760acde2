"""A send-out service asked for by plain English rather than its own verb: "my scripts need
sending off to Edexcel", "send my scripts off to the exam board (WJEC)", "send my tunic to
Parkside Laundry to be laundered" (the readings stage, where the service's own verb found no
send-out).

"send" with "off", "out" or "away" before its "to" sends the item out of the office: the
service is the one send-out operation of the office that takes the item named (several, or
none: not read so, and the reader goes on as before). "send ... to <place> to be <done>"
names the service by its own verb's past participle, with or without the particle. What
follows the "to" is then a destination outside, never a colleague to look up; a plain "send
my scripts to Bram" stays a hand-over.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping, Sequence

from assistantx.agents.symbolic.reading.destination import Outside, VerbPhrase, find_outside
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language

_SEND = frozenset(language.verb_forms("send")) | {"send"}
_PARTICLES = frozenset({"off", "out", "away"})
_CLAUSE_END = frozenset(".!?;,\n")
_REACH = 8  # how far after "send" its particle or "to" may stand


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
        if word not in _SEND or k in names:
            continue
        stop = next(
            (j for j in range(k + 1, len(tokens)) if any(c in _CLAUSE_END for c in gaps[j])),
            len(tokens),
        )
        to = next((j for j in range(k + 1, min(stop, k + _REACH)) if words[j] == "to"), None)
        if to is None:
            continue
        operation = _named_after(words, to, stop, done_forms)
        if operation is None and set(words[k + 1 : to]) & _PARTICLES:
            taking = [op for op, item in inputs.items() if item in items]
            operation = taking[0] if len(taking) == 1 else None
        if operation is None:
            continue
        others = [n for n in range(len(tokens)) if n != k]
        return find_outside(tokens, gaps, [VerbPhrase(operation, frozenset({word}), ())], others)
    return None


def _named_after(
    words: Sequence[str], to: int, stop: int, done_forms: Mapping[str, frozenset[str]]
) -> str | None:
    """ "... to Parkside Laundry to be laundered": the send-out its participle names."""
    for j in range(to + 1, stop - 2):
        if words[j] == "to" and words[j + 1] == "be":
            named = [op for op, forms in done_forms.items() if words[j + 2] in forms]
            return named[0] if len(named) == 1 else None
    return None
