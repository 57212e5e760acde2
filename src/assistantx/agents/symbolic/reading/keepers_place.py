"""A colleague's place said as where a thing is taken from: "we're out of glue at the bench,
could you get a tube from Priya's cabinet", where the office's glue is a supply (owned by
nobody) kept at the parts cabinet that Priya looks after.

"from <colleague>'s <place word>" ("cabinet", "cupboard", "shelf", a word of a facility's
name, or the facility itself) names where the thing is kept, not whose it is. Read as a
possessive on the thing, the assistant went for the colleague's own glue, which they do not
have. So, for a thing the frames read as that colleague's:

- they have none of their own, and a facility they look after keeps it for anyone: the one
  kept there (the facility's supply, no owner asked);
- they have one of their own, and a facility they look after keeps it too: which is meant is
  asked (their own, or the one kept there);
- they have none of their own and keep none: where to get it is asked, never a fetch of a
  thing of theirs that does not exist.

A colleague who has one and keeps none: their own, as before ("a roll of tape from Tom's
drawer").

A thing the frames left to anyone, taken from the requester's own place ("bring Wang some paper
from my desk", "take a pen from my drawer to Hu") or a colleague's where the frames did not
make it theirs, is that person's own where they have one: the place says whose, and anyone's
paper sent the robot to another colleague's. Where they have none it stays as read. The place
words are English (``keeping_places``, ``closed_containers``, ``place_words`` in english.yaml)
and the words of the office's facility names.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Facility, Office
from assistantx.core.task_schema import Task

# the words that say where a thing is taken from ("from", "out of", "off")
_FROM = frozenset({"from", "off", "out"})
_PLACE_WORDS = (
    english.words("keeping_places")
    | english.words("closed_containers")
    | english.words("place_words")
)


@dataclass(frozen=True)
class KeepersPlace:
    """ "from Priya's cabinet": the colleague, and the facility named, if one is."""

    person: str
    facility: str | None  # the facility's id where its name (or a synonym) is said


def keepers_places(
    office: Office, tokens: Sequence[Token], mentions: Sequence[Mention], requester: str
) -> list[KeepersPlace]:
    """The places "from <colleague>'s <place word>" (or "from my <place word>", the
    requester's) the message says a thing comes from."""
    names: set[str] | None = None  # the words of the facilities' names, read when needed
    found: list[KeepersPlace] = []
    for n, m in enumerate(mentions):
        if not m.possessive or m.start == 0:
            continue
        if m.kind == "person" and len(m.ids) == 1:
            person = m.ids[0]
        elif m.kind == "self" and tokens[m.start].word == "my":
            person = requester
        else:
            continue
        if tokens[m.start - 1].word not in _FROM:
            if not (m.start > 1 and tokens[m.start - 1].word == "of"):
                continue
            if tokens[m.start - 2].word != "out":
                continue
        after = mentions[n + 1] if n + 1 < len(mentions) else None
        if after is not None and after.kind == "facility" and after.start == m.end:
            found.append(KeepersPlace(person, after.ids[0] if len(after.ids) == 1 else None))
            continue
        if m.end >= len(tokens):
            continue
        if names is None:  # most messages say no "from <colleague>'s": no scan on every parse
            names = {w for f in office.facilities for n in (f.name, *f.synonyms) for w in _words(n)}
        if _place_word(tokens[m.end].word, names):
            if after is not None and after.start == m.end and after.kind == "item":
                continue  # "from Tom's box file": a thing of theirs, not a place
            found.append(KeepersPlace(person, None))
    return found


def from_keepers_place(
    office: Office, tasks: Sequence[Task], places: Sequence[KeepersPlace]
) -> tuple[list[Task], str | None]:
    """The tasks with a thing read as the colleague's, said from their place, taken from the
    facility they keep it at; the question to ask where that is not one thing."""
    if not places:
        return list(tasks), None
    out: list[Task] = []
    for task in tasks:
        place = next((p for p in places if p.person == task.owner), None)
        item = task.item
        if task.kind != "transfer" or item is None:
            out.append(task)
            continue
        if place is None and task.owner is None:
            # "bring Wang some paper from my desk": anyone's, from a place of someone who has
            # one of their own (a place, not a facility named): theirs
            place = next(
                (p for p in places if p.facility is None and p.person in office.owners_of(item)),
                None,
            )
            if place is not None:
                task = task.model_copy(update={"owner": place.person})
        if place is None:
            out.append(task)
            continue
        name = office.item_type(item).name
        who = office.person(place.person).name
        kept = _kept_by(office, place, item)
        own = place.person in office.owners_of(item)
        if own and not kept:
            out.append(task)  # "a roll of tape from Tom's drawer": Tom's own
            continue
        if own:
            return [], (
                f"Which {name} do you mean: {who}'s own, or the {name} kept at the {kept[0].name}?"
            )
        if len(kept) != 1:
            there = " or ".join(f"the {f.name}" for f in kept)
            return [], (
                f"Where should I get the {name} from: {there}?"
                if kept
                else f"As far as I know, {who} has no {name} of their own and keeps none. "
                f"Where should I get the {name} from?"
            )
        facility = kept[0].id
        owner = None if office.kept_owner(item, besides=task.recipient) == facility else facility
        out.append(task.model_copy(update={"owner": owner}))
    return out, None


def _kept_by(office: Office, place: KeepersPlace, item: str) -> list[Facility]:
    """The facilities the colleague looks after that keep ``item`` for anyone (the one named,
    where one is)."""
    return [
        f
        for f in office.facilities
        if place.person in f.guards
        and place.facility in (None, f.id)
        and any(s.type == item and s.count != 0 for s in f.supplies)
    ]


def _place_word(word: str, facility_words: set[str]) -> bool:
    if word in _PLACE_WORDS or word in facility_words:
        return True
    return bool(set(language.lemmas(word).get("NOUN", ())) & _PLACE_WORDS)


def _words(name: str) -> list[str]:
    return language.words(name.lower())
