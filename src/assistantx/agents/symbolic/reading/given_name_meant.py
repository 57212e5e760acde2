"""A bare name that is one colleague's given name and another's family name means the one
whose given name it is, in an office that writes names the English way.

"need frank to sign my manifest", "take my keys to frank", "need grant's signature on my
expenses": where Frank O'Sullivan and Ingrid Frank both work, English speakers call a
colleague by the given name, and a family name alone is how one speaks of someone only with
a title ("Ms Frank", read as hers by ``surnames``). Outside testers of thirteen offices
written the English way expected the given-name colleague every time such a word stood bare
(rounds 100–124 in docs/understanding.md); none expected the family-name one. So the word
means the colleague whose given name it is, after everything else that decides it (an item
only one of them owns, a later sentence naming one, a title) has had its say.

Still asked: an office that writes family names first (``surnames.family_first``: "Yang" of
Yang Lei and Liu Yang, where the default office's testers wanted a question), a word that is
the given name of several, a word the office calls the family-name colleague by bare (their
own alias "Frank": the office says both answer to it), and a family name the office writes
after a rank ("Inspector Morgan" of Priya Morgan): where ranks go with family names, so does
speaking of a colleague by the family name alone (round 81's police station, where the
tester wanted "Morgan" asked). A title of address ("Ms Grant") is no rank: it is how one
addresses her, not how colleagues speak of her.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import replace

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.surnames import given_names
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language
from assistantx.core.office import Office
from assistantx.core.ranks import COURTESY_TITLES


class GivenNameMeant:
    """The office's given names, for settling a bare name several colleagues answer to."""

    def __init__(
        self,
        office: Office,
        key: Callable[[str], str],
        family: Mapping[str, set[str]],
        bare: Mapping[str, set[str]],
    ) -> None:
        self._given = given_names(office, key)
        # what each colleague is known to own: a thing unknown to the assistant (``known:
        # false``) never decides between namesakes
        self._owned = {p.id: {o.type for o in p.owns if o.known} for p in office.people}
        self._ranked = _ranked_family_names(office, key)
        self._family = family
        self._bare = bare
        self._key = key

    def settle(self, tokens: Sequence[Token], mentions: Sequence[Mention]) -> list[Mention]:
        """``mentions`` with each one-word name that is exactly one candidate's given name
        and only the family name of the others narrowed to that candidate."""
        out = list(mentions)
        for n, m in enumerate(out):
            if m.kind != "person" or len(m.ids) < 2 or m.end - m.start != 1:
                continue
            word = self._key(tokens[m.start].word)
            ids = set(m.ids)
            given = self._given.get(word, set()) & ids
            others = ids - given
            if len(given) != 1 or not others <= self._family.get(word, set()):
                continue
            if others & (self._bare.get(word, set()) | self._ranked.get(word, set())):
                continue  # the office calls the family-name colleague so too: asked
            if self._thing_says_otherwise(out, n, given):
                continue  # "frank's calculator" where only Ingrid Frank has one: hers
            out[n] = replace(m, ids=tuple(given))
        return out

    def _thing_says_otherwise(self, mentions: Sequence[Mention], n: int, given: set[str]) -> bool:
        """Whether the possessive name at ``n`` owns a thing (the next mention) that some of
        its other candidates own and the given-name one does not: the item decides."""
        m = mentions[n]
        if not m.possessive or n + 1 >= len(mentions) or mentions[n + 1].kind != "item":
            return False
        things = set(mentions[n + 1].ids)
        owners = {p for p in m.ids if self._owned.get(p, set()) & things}
        return bool(owners) and not owners & given


def _ranked_family_names(office: Office, key: Callable[[str], str]) -> dict[str, set[str]]:
    """Each family name the office writes after a rank in someone's own alias ("Inspector
    Morgan" of Priya Morgan) → those people; titles of address ("Ms Grant") are no rank."""
    found: dict[str, set[str]] = {}
    for p in office.people:
        name = language.fold(p.name).replace(".", " ").split()
        if len(name) < 2:
            continue
        for alias in p.aliases:
            said = language.fold(alias).replace(".", " ").split()
            if len(said) < 2 or said[-1] not in (name[0], name[-1]):
                continue
            rank = said[:-1]
            if any(w in COURTESY_TITLES or w in name for w in rank):
                continue
            if k := key(said[-1]):
                found.setdefault(k, set()).add(p.id)
    return found
