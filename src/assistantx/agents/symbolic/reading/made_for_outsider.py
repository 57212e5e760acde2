"""Made for an outsider: "chopped quail for Blaze please, 160g", "a ration for Rex please": a
thing the office makes, asked "for" a capitalised name that is nobody of the office and no word
of it, with "please" and nobody else named to get it, is made for the speaker, who will use it
for whoever that is (an animal, a client, a guest). It had asked "I don't know anyone called
'Blaze'. Who do you mean?", which the speaker cannot answer: Blaze is no colleague.

A name close to a colleague's ("a coffee for Zhnag please", "... for Svm") may be that
colleague misspelt: asked about, as before; as is any thing that is not made here ("my stapler
for Blaze please"), a message with no "please" ("chopped quail for Blaze": who Blaze is may
matter) and one that names a colleague as well ("... for Blaze, give it to Sam")."""

from __future__ import annotations

import difflib
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english
from assistantx.core.office import Office

_PLEASE = english.words("asking_words") & english.words("request_markers")
# How near a word is to a colleague's name for it to be read as that name misspelt.
_NEAR = 0.6


def made_for_outsider(
    office: Office,
    tokens: Sequence[Token],
    mentions: Sequence[Mention],
    n: int,
    people_words: frozenset[str],
) -> bool:
    """Whether mention ``n`` (a word nobody of the office is called) is whom a made thing is
    for, said after it and "for", in a polite message that names no colleague."""
    m = mentions[n]
    if not m.text[:1].isupper() or m.possessive or m.start < 2:
        return False
    if tokens[m.start - 1].word != "for":
        return False
    before = next((x for x in mentions if x.end == m.start - 1), None)
    if before is None or before.kind != "item" or len(before.ids) != 1:
        return False
    if not any(op.product == before.id for op in office.operations):
        return False  # "my stapler for Blaze": no thing made here, asked as before
    if not any(t.word in _PLEASE for t in tokens):
        return False
    if any(x.kind == "person" for x in mentions):
        return False  # a colleague named as well: whom it is for may be them
    word = tokens[m.start].word
    return not difflib.get_close_matches(word, people_words, n=1, cutoff=_NEAR)
