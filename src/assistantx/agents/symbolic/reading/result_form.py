"""The form a service's result takes, said after its verb: "scan to PDF my signed contract",
"burn to disc my photos", "write to tape the backups". After an operation's verb, "to" (or
"into", "as") and a word of one of the office's products is the product the work makes, never
a recipient nor a verb of its own ("to book my ..."): the thing stays the office's product, so
nobody is looked up by its name ("I don't know anyone called 'PDF'" before). Which words are
products is the office's own data (its operations' products)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core.office import Office

INTO_WORDS = frozenset({"to", "into", "as"})  # "scan to PDF", "burn into", "save as"


def products(office: Office) -> frozenset[str]:
    """The item types the office's operations make."""
    return frozenset(op.product for op in office.operations if op.product)


def result_form(
    tokens: Sequence[Token], mentions: Sequence[Mention], n: int, made: frozenset[str]
) -> bool:
    """Whether ``mentions[n]`` is a product said right after "to" that follows a service's
    verb ("scan *to PDF*")."""
    m = mentions[n]
    if m.kind != "item" or not set(m.ids) & made or m.start < 2:
        return False
    if tokens[m.start - 1].word not in INTO_WORDS or tokens[m.start].after_pause:
        return False
    verb = next((v for v in mentions[:n] if v.end == m.start - 1), None)
    return verb is not None and verb.kind == "cue"
