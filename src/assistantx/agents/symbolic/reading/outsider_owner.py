"""An owner named in a possessive who is nobody of the office: "the chiropodist's invoice
needs stamping", "something to check Mrs Baker's sats with", "write Mr Jones's address".

Two ways English names a person the office does not know, with no list of such people:

- a common noun in lower case after a determiner ("the chiropodist's", "this plumber's"):
  it says what the person is, and no colleague is called by an ordinary noun. The words
  English uses for the office's own people ("boss", "colleague", "manager": the ``titles``
  data) and any word of the office's own names for its people and groups ("the judge's
  keys" where someone is "the Judge's Clerk") are no outsider: they still ask who is meant.
- a title and a surname the office does not have, owning something that is no item of the
  office ("Mrs Baker's sats", "Mr Jones's address"): what is said of the person is context
  for the request, never a colleague to look up. Owning an item of the office ("Mr Smith's
  stapler") it is still asked about: the robot could only get it from a colleague.

Either way the owner is no one to ask about; what they own, when it is a paper to work on,
is the speaker's in hand (the existing reading of "my client's certificate")."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office

# the determiners a kind of person is named after ("the", "this", "my", "a")
_DETERMINERS = frozenset({"my", "our", "the", "this", "that", "a", "an", "your"})
# how many describing words may stand between the determiner and the person's noun
_DESCRIBING = 2
# the words an office names its own people with ("the boss's", "my colleague's"): no outsider
_TITLE_WORDS = english.words("titles")
_OFFICE_PEOPLE = _TITLE_WORDS | frozenset(
    {"coworker", "co-worker", "teammate", "team", "owner", "supervisor", "secretary"}
)
# a title before a surname ("Mrs Baker"), the outsider's form of address
_TITLES = frozenset({"dr", "mr", "mrs", "ms", "mx", "miss", "prof", "professor", "doctor"})


def office_people_words(office: Office) -> frozenset[str]:
    """Every word of the office's names and aliases for its people and groups, folded."""
    said = [*(p.name for p in office.people), *(a for p in office.people for a in p.aliases)]
    said += [g.name for g in office.groups]
    # "the Judge's Clerk": the possessive's word alone ("judge"), before its apostrophe goes
    return frozenset(w for s in said for w in language.words(language.fold(s).replace("'s", " ")))


def common_noun_owner(
    word: str,
    said: str,
    before: str,
    office_words: frozenset[str],
    *,
    purpose: bool = False,
) -> bool:
    """Whether the possessive ``said`` (its folded ``word``), after the word ``before``,
    names a kind of person: a lower-case common noun after a determiner, not one of the
    words for the office's own people (English's, or the office's ``office_words``).

    ``purpose``: the phrase opens with "for" ("... for the owner's file"), saying what the
    thing is for. There the relational words ("owner", "supervisor"), which elsewhere mean a
    colleague of the thing or the team ("give it back to the owner"), say whose the file
    is, a kind of person as much as "the client's"; English's titles ("boss", "manager")
    and the office's own names still mean its people."""
    if not said[:1].islower() or before not in _DETERMINERS:
        return False
    office_people = _TITLE_WORDS if purpose else _OFFICE_PEOPLE
    if word in office_people or word in office_words:
        return False
    return language.is_noun(word)


def described_before(tokens: Sequence[Token], at: int) -> tuple[str, int] | None:
    """The determiner before the possessive at token ``at`` and where it stands, past one
    or two lower-case words that describe the person ("a *new* starter's", "our *external*
    contractor's"); None where no such words stand between them."""
    k = at - 1
    while k >= 0 and at - k <= _DESCRIBING and _describes(tokens[k]):
        k -= 1
    if k == at - 1 or k < 0 or tokens[k].word not in _DETERMINERS:
        return None
    return tokens[k].word, k


def _describes(token: Token) -> bool:
    """A lower-case word that may describe a person before their noun ("new", "external")."""
    word = token.word
    return (
        token.text[:1].islower()
        and not token.possessive
        and not token.opens
        and word.isalpha()
        and word not in _DETERMINERS
        and "ADJ" in language.lemmas(word)
    )


def clause_opening_owner(
    word: str, said: str, opens_clause: bool, office_words: frozenset[str]
) -> bool:
    """Whether the possessive ``said`` (its folded ``word``) opening a later clause with no
    determiner names a kind of person: "..., visitor's pen just ran out". A reason clause
    typed in haste drops its article, yet a lower-case common noun still says what the
    person is, never who: a colleague's name or alias ("wang's") and the words for the
    office's own people ("boss's") are no outsider and are still looked up."""
    if not opens_clause or not said[:1].islower():
        return False
    if word in _OFFICE_PEOPLE or word in office_words:
        return False
    return language.is_noun(word)


def titled_outsider(before: str) -> bool:
    """Whether a possessive name the office does not have, after ``before``, is an outsider
    said as context: a title opens it ("Mrs Baker's"). Called only where the name owns no
    item of the office ("Mrs Baker's sats"), so nothing is to be got from them."""
    return before in _TITLES
