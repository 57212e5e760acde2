"""A question about a thing at a place ("any wipes in the kitchenette?", "are there gloves
at the post desk?"): answered about what the office file says is kept there, never with who
in the office has one elsewhere as if the place had not been said.

What is kept at a place is the office's own data: the supplies of a facility that stands
there, the owners' things kept there (an owner's entry ``at`` the place, or their desk being
the place), and what a facility there makes. Nothing kept there is said as such; who has one
elsewhere follows as before (``question.item_question``)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.agents.symbolic.reading.screen.terms import listed
from assistantx.core import english, language, wording
from assistantx.core.office import Office

_AT = english.words("location_prepositions")


def place_asked(lexed: Lexed) -> tuple[str, str] | None:
    """The place a question names after "in"/"at"/"by" ("in the kitchenette"): its location
    id and the preposition said. A facility ("any paper in the printer?") asks about the
    facility, answered as before."""
    tokens = lexed.tokens
    for m in lexed.mentions:
        if m.kind != "place" or len(m.ids) != 1 or m.possessive:
            continue
        at = m.start - 1
        if at > 0 and tokens[at].word == "the":
            at -= 1
        if at < 0 or tokens[at].word not in _AT:
            continue
        return m.id, tokens[at].word
    return None


def kept_at(office: Office, item: str, place: str, said: str) -> tuple[str, bool]:
    """The answer about ``item`` at ``place`` (said after ``said``), and whether any is kept
    there."""
    t = office.item_type(item)
    at = office.location(place)
    # a room is "the kitchenette"; a workstation is named by its number ("desk 11")
    where = f"{said} {at.name}" if at.kind == "workstation" else f"{said} the {at.name}"
    here = [f for f in office.facilities if f.location == place]
    stocked = [f for f in here if (s := f.supply(item)) is not None and s.count != 0]
    if stocked:
        return f"{wording.there_is(t.name, mass=t.mass)} in the {stocked[0].name} {where}.", True
    makers = [f for f in here if item in f.products]
    if makers:
        return (
            f"The {makers[0].name} {where} makes {wording.them_or_it(t.name, mass=t.mass)}.",
            True,
        )
    keepers = [
        office.person(p).name
        for p in office.owners_of(item, known_only=True)
        if _kept_there(office, p, item, place)
    ]
    if keepers:
        has = "keeps" if len(keepers) == 1 else "keep"
        one = wording.a_thing(t.name, mass=t.mass)
        return f"As far as I know, {listed(keepers[:4])} {has} {one} {where}.", True
    return f"I don't know of {language.indefinite(t.name)} {t.name} kept {where}.", False


def _kept_there(office: Office, person: str, item: str, place: str) -> bool:
    """Whether ``person``'s ``item`` is kept at ``place``: said so, or on their desk there."""
    own = next((o for o in office.person(person).owns if o.type == item), None)
    if own is None:
        return False
    return (own.at or office.person(person).location) == place
