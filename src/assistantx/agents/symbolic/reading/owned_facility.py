"""A facility's name said as someone's belonging: "take my kettle to Mark, then fetch me a
ruler" where the kettle is the kitchen's, owned by nobody. The lexicon reads "kettle" as the
facility, so the frames read its service (a tea made for Mark): a wrong physical action, since
the requester spoke of a thing of theirs to move, and a facility is nobody's and never moves.

The rule is about English and the office's own data: a possessive ("my", "Grace's") straight
before a facility's name (a name the lexicon reads as a facility, so no item type anyone owns
goes by it) names no service of the facility. The part is asked about before anything moves
(``parts.unread_part``), quoting the phrase; the answer takes its place, and the clear part is
done after it. "make Mark a tea", "get Mark a tea from the kettle" say no owner of the kettle
and keep their reading.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office

# The possessives that say whose a thing is: the requester's own ("my") or a colleague's.
_OWNERS = frozenset({"self", "person"})
_COMMON = english.words("common")


def owned_facility(
    mentions: Sequence[Mention], tokens: Sequence[Token], office: Office
) -> str | None:
    """The first phrase "my/Grace's <facility>" as said; None when there is none. "from
    Priya's cabinet", Priya one who looks after it, names the facility as where a thing comes
    from (``keepers_place``), no thing of hers."""
    for before, m in itertools.pairwise(mentions):
        if m.kind != "facility" or before.end != m.start:
            continue
        if _keepers_own(office, tokens, before, m):
            continue
        if before.kind in _OWNERS and before.possessive and not runs_into_a_noun(tokens, m):
            return " ".join(t.text for t in tokens[before.start : m.end])
    return None


# the words before "<colleague>'s <facility>" that make it where a thing is taken from
_FROM = frozenset({"from", "off", "of"})


def _keepers_own(office: Office, tokens: Sequence[Token], owner: Mention, m: Mention) -> bool:
    """ "from Priya's cabinet" where Priya looks after the cabinet: the place, named by its
    keeper."""
    if owner.kind != "person" or owner.start == 0 or tokens[owner.start - 1].word not in _FROM:
        return False
    return any(p in office.facility(f).guards for f in m.ids for p in owner.ids)


def runs_into_a_noun(tokens: Sequence[Token], m: Mention) -> bool:
    """Whether a facility's name runs on into a noun ("my hydro session plan", "her kitchen
    rota"): it describes the thing, which is what is owned, not the facility."""
    if m.end >= len(tokens):
        return False
    after = tokens[m.end]
    word = after.word
    if not word.isalpha() or after.after_pause or word in _COMMON:
        return False
    # a noun, or a word the dictionary has no verb for ("rota"): what the phrase names
    return language.is_noun(word) or not language.verb_lemmas(word)
