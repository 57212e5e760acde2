"""Which one a place phrase names: "the parcel in the post room", "grab the kettle in the
kitchen", "the bike pump from the post desk" (the frames stage, once a clause's roles are
read).

An item said with no owner, then "in/at/from/on" and a place or facility of the office, is
the one kept there: the facility's supply (owned by nobody: its owner part is the facility),
the belonging a person keeps at a facility there (asked of its owner as usual), or the one on
the desk of whoever sits at a workstation named. Exactly one such item: that one. None, or
several: the requester is asked, never a guess at another one elsewhere (said with "a" or
"some", any one will do, as before).

Two readings come before asking. Several people keep one there and the requester is one of
them ("lunch from the fridge", where three keep a lunch): nobody asks for a colleague's lunch
without naming them, so it is the requester's own. None is kept there but a supply of the
kind is kept elsewhere, the thing said with no article ("need gloves at the nurses' station",
gloves in the store cupboard; "the kettle in the laundry" is still asked about): the place is
where it should be brought, not where it is; at the requester's own place that
is the requester, and elsewhere the requester is asked who there should get it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading._parties import Clause, Roles
from assistantx.agents.symbolic.reading.kept_items import items_kept_at
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.parts import ASKED, ASKED_END
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language
from assistantx.core.office import Office

# The words between an item and a place that make the place where the item is now.
_AT = frozenset({"in", "at", "from", "on", "inside"})
_ARTICLES = frozenset({"the", "a", "an"})
_INDEFINITE = frozenset({"a", "an", "some", "any", "another"})
_DETERMINERS = _ARTICLES | {"this", "that", "these", "those"}


@dataclass(frozen=True)
class PlacePhrase:
    """An item mention followed by a place phrase, and the items kept there."""

    item: Mention
    place: str  # the place's or facility's name, as the office writes it
    owners: tuple[str, ...]  # owner parts of the items of its type kept there
    definite: bool  # "the kettle in the kitchen" (not "a kettle from the kitchen")
    kind: str  # "facility" or "place"
    where: str  # the facility's or the place's id
    said: str  # the place phrase in the requester's words ("at the nurses station")
    bare: bool  # said with no article at all ("need gloves at ...", not "the gloves at ...")


def kept_owners(
    office: Office,
    tokens: Sequence[Token],
    clause: Clause,
    roles: Roles,
    requester: str,
    placed: dict[str, str],
) -> str | None:
    """Fill ``roles.owners`` for each object named with a place phrase and no owner (and
    ``placed``, item type → owner part, for a later "it" in another clause); the question to
    ask when "the <item>" names no such item there, or several, else None.

    The one found is left unnamed (owner None) when it is the one the planner takes anyway
    (``Office.kept_owner``). An indefinite "a/some <item> from <place>" asks nothing: with
    none or several there, any one will do, as before. A personal item of the requester's
    own, none kept there ("the document in the printer"), is theirs."""
    for phrase in place_phrases(office, tokens, clause, roles):
        item = phrase.item.id
        name = office.item_type(item).name
        if len(phrase.owners) == 1:
            if _another_of_ones_own(office, phrase, {requester, *roles.recipient}):
                # "need a tape measure in the lab", "Walker needs a muzzle at the daycare
                # desk": the own one there of whom it is for, so another one, there
                continue
            owner = placed[item] = phrase.owners[0]
            if owner != office.kept_owner(item, besides=requester):
                roles.owners[phrase.item.start] = owner
            continue
        if not phrase.definite:
            continue
        if not phrase.owners:
            personal = office.item_type(item).kind == "personal"
            if personal and requester in office.owners_of(item):
                roles.owners[phrase.item.start] = placed[item] = requester
                continue
            if phrase.bare and _supplied_elsewhere(office, item):
                if _own_place(office, phrase, requester):
                    continue  # "need gloves at my desk": brought to the requester
                there = _people_at(office, phrase)
                return (
                    f"{ASKED}{phrase.said}{ASKED_END} {language.plural(name).capitalize()} "
                    f"are kept elsewhere, so I can bring them to the {phrase.place}: who there "
                    f"should get them?{there}"
                )
            return (
                f"I don't know of {language.indefinite(name)} {name} kept at the "
                f"{phrase.place}. Which {name} do you mean, or whose is it?"
            )
        if requester in phrase.owners:
            # "lunch from the fridge", several lunches there and one the requester's
            roles.owners[phrase.item.start] = placed[item] = requester
            continue
        whose = " or ".join(_owner_name(office, o) for o in phrase.owners)
        return f"Which {name} at the {phrase.place} do you mean: {whose}?"
    return None


def place_phrases(
    office: Office, tokens: Sequence[Token], clause: Clause, roles: Roles
) -> list[PlacePhrase]:
    """The clause's objects of a physical type said with no owner and followed by a place
    phrase ("the kettle in the kitchen")."""
    out: list[PlacePhrase] = []
    ms = clause.mentions
    for n, m in enumerate(ms[:-2]):
        if m.kind != "item" or m.start in roles.owners or m.start in clause.modifiers:
            continue
        if office.item_type(m.id).kind not in ("belonging", "personal"):
            continue
        prep, where = ms[n + 1], ms[n + 2]
        if prep.start != m.end or tokens[prep.start].word not in _AT:
            continue
        if _ran_out_of(tokens, m.start):
            continue  # "out of cable ties on the bench": where they ran out, not where kept
        if any(t.word not in _ARTICLES for t in tokens[prep.end : where.start]):
            continue
        if where.kind == "facility":
            place = office.facility(where.ids[0]).name
        elif where.kind == "place":
            place = office.location(where.ids[0]).name.lower()
        else:
            continue
        definite = m.start == 0 or tokens[m.start - 1].word not in _INDEFINITE
        there = items_kept_at(office, where.kind, where.ids[0])
        kept = tuple(dict.fromkeys(k.owner for k in there if k.type_id == m.id))
        said = " ".join(t.text for t in tokens[prep.start : where.end])
        bare = m.start == 0 or tokens[m.start - 1].word not in _DETERMINERS
        out.append(PlacePhrase(m, place, kept, definite, where.kind, where.ids[0], said, bare))
    return out


def _another_of_ones_own(office: Office, phrase: PlacePhrase, receivers: set[str]) -> bool:
    """ "need a tape measure in the lab": the one kept there is the own one of whom it is for
    (the requester, or the colleague said to need it: "Walker needs a muzzle at the daycare
    desk"), with them (on their desk, in their room), and "a" one is asked: another one,
    anyone's, brought there, as for someone with none. Their own kept by a facility there ("a
    thermometer from the lab cabinet") is a fine reading, and so is "the tape measure in the
    lab"."""
    if phrase.definite or len(phrase.owners) != 1 or phrase.owners[0] not in receivers:
        return False
    return office.keeper(phrase.owners[0], phrase.item.id) is None


def _supplied_elsewhere(office: Office, item: str) -> bool:
    """Whether a facility keeps ``item`` in stock for anyone (owned by nobody)."""
    return any(s.type == item and s.count != 0 for f in office.facilities for s in f.supplies)


def _people_at(office: Office, phrase: PlacePhrase) -> str:
    """ " (Nell Amadi is there.)": who is at the place named, to answer with; "" if nobody."""
    at = office.facility(phrase.where).location if phrase.kind == "facility" else phrase.where
    names = [p.name for p in office.people if p.location == at]
    if not names:
        return ""
    return f" ({' or '.join(names)} {'is' if len(names) == 1 else 'are'} there.)"


def _own_place(office: Office, phrase: PlacePhrase, requester: str) -> bool:
    """Whether the place named is where the requester is (their workstation or room, or a
    facility there)."""
    at = office.person(requester).location
    if phrase.kind == "facility":
        return office.facility(phrase.where).location == at
    return phrase.where == at


def _ran_out_of(tokens: Sequence[Token], start: int) -> bool:
    """ "(we've run) out of cable ties on the packing bench": the item is what someone is
    out of, and the place after it is where they are without it, not where one is kept."""
    k = start
    while k > 0 and tokens[k - 1].word in _ARTICLES | _INDEFINITE:
        k -= 1
    return k >= 2 and tokens[k - 1].word == "of" and tokens[k - 2].word == "out"


def _owner_name(office: Office, owner: str) -> str:
    name = office.owner_name(owner)
    return f"{name}'s" if name is not None else f"the {office.facility(owner).name}'s"
