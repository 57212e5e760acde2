"""A person said to be somewhere the office is not ("Kwame's at the dentist till 3 fyi", "Noor
is on a course this week", "Ramón's out on a delivery till 3"): away, like "Wang is away".
What follows the state (when they will be back, "fyi", "again") says nothing more about
where they are, so it is cut off before the state is read."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.core import english

# Where a person is said to be: "at the dentist", "in Leeds", "on a course".
_ELSEWHERE = frozenset({"at", "in", "on"})
# Words of the office's own places: "at his desk", "on the bench" are in the office.
_PLACES = english.words("place_words") | english.words("surface_words")
# What ends the state and tells no more of it: a time ("till 3", "until Friday", "today",
# "this week", "all day") or an aside ("fyi", "btw", "again", "ugh").
_TAIL = english.words("state_tails")
_OFFICE_THINGS = frozenset({"person", "item", "facility", "place"})
# A word of being gone before where: "*out* on a delivery", "*off* at the dentist", "*away* in
# Leeds" say where the person is gone, like "on a delivery" alone.
_GONE = frozenset({"out", "off", "away"})
# "*gone down to* the river", "*popped over to* the bank": a verb of going and its particles,
# then "to" where the person went.
_GOING = english.words("gone_verbs")
_PARTICLES = english.words("gone_particles")
_TO = frozenset({"to", "into"})
# "heading to the match", "off to the site visit in a bit", "on her way to the airport": still
# here, about to go (``leaving_soon``)
_LEAVING = tuple(
    sorted((tuple(p.split()) for p in english.entries("leaving_soon")), key=lambda p: -len(p))
)


def _gone_to(state: list[str]) -> list[str]:
    """ "gone down to the river" → "at the river": where a person went, as where they are."""
    if not state or state[0] not in _GOING:
        return state
    n = 1
    while n < len(state) and state[n] in _PARTICLES:
        n += 1
    if n < len(state) and state[n] in _TO:
        return ["at", *state[n + 1 :]]
    return state


def leaving_soon(state: list[str]) -> bool:
    """Whether the state says the person is about to go, not gone: "heading to the match",
    "off to the site visit in a bit", "on his way to the depot" (they are here till then, so
    a thing may still be taken to them); "off today", "gone to the bank" are away."""
    return any(state[: len(p)] == list(p) for p in _LEAVING)


def state_said(state: list[str]) -> list[str]:
    """The state without what follows it: "off sick till Thursday fyi" → "off sick"."""
    for n, word in enumerate(state):
        if n and word in _TAIL:
            return state[:n]
    return state


def away_elsewhere(state: list[str], lexed: Lexed, subject_end: int) -> bool:
    """Whether the state puts the person somewhere that is no place of this office: "at the
    dentist", "in Leeds", never "at his desk", nor a place, facility, item or person the
    office names (those are its own facts, read by the rule)."""
    state = _gone_to(state)
    if len(state) > 2 and state[0] in _GONE and state[1] in _ELSEWHERE:
        state = state[1:]  # "out on a delivery till 3": gone, on a delivery
    if len(state) < 2 or state[0] not in _ELSEWHERE:
        return False
    if set(state) & _PLACES:
        return False
    return not any(m.kind in _OFFICE_THINGS for m in lexed.mentions if m.start >= subject_end)
