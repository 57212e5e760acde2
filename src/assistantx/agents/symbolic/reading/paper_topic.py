"""A paper or file "for" a name nobody in the office has, read as what it is about: "print
off the pre-plan for Kestrel Mills and give it to Eilidh". After a paper, a file or a made
copy, "for <Capitalised name>" says whom it is for only where the name could be someone's;
it says what the paper is about (a client, a site) where the name ends in the noun of a kind
of place or firm ("Kestrel *Mills*", "Riverside *House*", "Acme *Ltd*", "Mill *Road*"), or
where the message names, after it, a colleague who gets it ("... and give it to Eilidh").
Asking who "Kestrel" is then loses the whole request. A name alone with nobody else named
("print my file for Kestrel") is still asked: it may be a colleague the office lacks."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.named_place import place_head
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english

# The last word of a firm's or an address's name ("Acme Ltd", "Mill Road"): it names a firm
# or a street, never a person.
_FIRM_OR_STREET = english.words("firm_suffixes") | english.words("street_words")
# The words that hand a thing to the person after them ("give it to Eilidh", "for Wang").
_TO = frozenset({"to", "for"})
# The kinds of thing a "for <name>" can be about: papers, files and what is made of them.
_PAPERS = frozenset({"personal", "electronic", "product"})


def about_a_name(
    tokens: Sequence[Token], mentions: Sequence[Mention], first: int, kind: str
) -> bool:
    """Whether the capitalised name whose first word is ``mentions[first]`` (after "for" and
    a thing of ``kind``) says what the thing is about."""
    if kind not in _PAPERS:
        return False
    last = first
    while (
        last + 1 < len(mentions)
        and mentions[last + 1].kind == "word"
        and mentions[last + 1].start == mentions[last].end
        and mentions[last + 1].text[:1].isupper()
        and not mentions[last].possessive
    ):
        last += 1
    end_word = tokens[mentions[last].end - 1].word
    if last > first and (place_head(end_word) or end_word in _FIRM_OR_STREET):
        return True  # "Kestrel Mills", "Acme Ltd": a place's or firm's own name
    return any(_handed_to(tokens, m) for m in mentions[last + 1 :])


def _handed_to(tokens: Sequence[Token], m: Mention) -> bool:
    """Whether ``m`` is a colleague the thing is handed to ("to Eilidh", "for Wang")."""
    return (
        m.kind == "person" and not m.possessive and m.start > 0 and tokens[m.start - 1].word in _TO
    )
