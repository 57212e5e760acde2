"""A state said with "'s" for "is" or "has" ("UV bulb's gone", "the kettle's broken", "scanner's
down again", "hall clock's stopped"): the "'s" is the verb, not a possessive, so the clause is
read as the statement it is ("the bulb is gone", "the clock has stopped"), never as a request
about a thing belonging to the bulb. Only a word of state or a past participle that ends its
clause counts ("Zhang's broken stapler" owns a stapler, and stays), a past participle with its
object after it ("the printer's eaten another manifest"), or a change of state with what it
became ("the fridge light's gone amber again")."""

from __future__ import annotations

import re

from assistantx.core import english, language
from assistantx.core.task_schema import Evidence

# the one-word states of a thing ("broken", "gone", "down") and what may follow one and end
# the clause ("again", "today", "btw")
_STATES = frozenset(
    entry
    for key in ("conditions", "facility_faults")
    for entry in english.entries(key)
    if " " not in entry
)
# ... and where the state came from ("my cup's dirty *from* lunch")
_TAILS = english.words("state_tails") | frozenset(
    {"already", "completely", "totally", "again", "too", "from"}
)
# what may follow a participle and still end its clause: "asked for ..." goes on
_PARTICIPLE_TAILS = frozenset(
    {
        "again",
        "already",
        "now",
        "btw",
        "fyi",
        "lol",
        "though",
        "too",
        "completely",
        "and",
        "but",
        "so",
    }
)
# a particle that makes a participle a thing's state of being used up ("the foil's run out",
# "the glue's dried up", "the ink's run dry"): the "'s" is "has"
_USED_UP_PARTICLES = english.words("used_up_particles")
# a determiner after a participle opens its object ("the printer's eaten *another* manifest",
# "Zhang's broken *the* stapler", "someone's eaten *half* my lunch"): a possessive's adjective
# never has one after it, so the "'s" is "has"
_OBJECT_DETERMINERS = (
    english.words("object_starts") | english.words("object_quantifiers") | frozenset({"another"})
)
# a change of state said with its result ("the light's gone amber", "screen's turned blue"):
# the word after it says what the thing became, and the clause is still a statement
_BECOME = frozenset({"gone", "turned", "become", "grown"})
_PRONOUNS = english.words("subject_pronouns") | frozenset(
    {"that", "this", "there", "here", "what", "who", "where", "let", "he", "she", "mine", "yours"}
)
# where someone is, said with "'s" ("Chen's back from the offsite", "Ida's off to the sim
# tomorrow", "Wang's away till Monday"): the word, then the end of the clause or one of the
# words that go on saying where or when; "Zhang's back brace" (a noun after it) owns a brace
_WHEREABOUTS = english.words("contracted_whereabouts")
_WHEREABOUTS_TAILS = english.words("contracted_whereabouts_tails") | _TAILS
# an adverb between the "'s" and the state ("the sun's finally out", "scanner's still down")
_ADVERBS = "|".join(sorted(english.words("contracted_adverbs")))
_CONTRACTED = re.compile(
    rf"\b(?P<subject>[^\W\d_]+)['’]s\s+(?P<adverb>(?:{_ADVERBS})\s+)?(?P<state>[a-z]+)\b"
    r"(?P<rest>\s*(?:[^\W\d_]+)?)",
    re.IGNORECASE,
)


# what may end an ongoing state of a thing ("my stapler's playing up", "the binder's falling
# apart"): a particle of the phrasal verb
_ONGOING_TAILS = _TAILS | frozenset({"up", "apart", "about", "out", "off", "again"})


def _state_of_a_thing(subject: str, state: str, after: str, things: frozenset[str]) -> bool:
    """ "my laptop's flat", "the stapler's playing up": after the name of one of the office's
    things, an adjective or a verb's "-ing" that ends its clause, or an "-ing" with no noun
    after it, says how the thing is; a thing owns no "flat" and no "playing", so the "'s" is
    "is". A noun after it ("the laptop's charger") is still its part, and a person's "'s"
    ("Zhang's flat") is read as before."""
    if subject.lower() not in things:
        return False
    read = language.lemmas(state)
    ongoing = state.endswith("ing") and "VERB" in read
    if not ongoing and "ADJ" not in read:
        return False
    if not after or after in (_ONGOING_TAILS if ongoing else _TAILS):
        return True
    if ongoing and after not in things and not language.is_noun(after):
        # "my bow's squeaking like mad", "the tap's dripping when I ...": a verb's "-ing"
        # goes on with how or when, never a noun; a noun after it is its part ("the
        # laptop's charging cable")
        return True
    # "the stapler's working fine now", "the ruler's totally fine": an adverb of how it
    # works; a thing of the office after it ("the printer's working copy") is its part
    return "ADV" in language.lemmas(after) and after not in things


def _named_thing(verb: str, state: str, after: str, things: frozenset[str]) -> bool:
    """ "Owen's forecast", "Ada's cast", "Rob's set": a past participle that is also the name
    of one of the office's things is the thing owned, unless what follows is the object a
    verb takes ("the model's cast another part") or a particle of being used up; a state word
    ("broken", "gone") or a word of whereabouts keeps its own reading."""
    if verb != "has" or state not in things or state in _STATES or state in _WHEREABOUTS:
        return False
    return after not in _OBJECT_DETERMINERS and after not in _USED_UP_PARTICLES


def contracted_is(text: str, things: frozenset[str] = frozenset()) -> tuple[str, list[Evidence]]:
    """``text`` with "X's <state>" written "X is <state>" (or "X has <participle>") where
    the state ends its clause; ``things``: the office's words that end a thing's name, whose
    adjectives and ongoing states are read so too (``_state_of_a_thing``)."""
    found: list[Evidence] = []

    def expand(match: re.Match[str]) -> str:
        subject, state = match.group("subject"), match.group("state").lower()
        after = match.group("rest").strip().lower()
        if subject.lower() in _PRONOUNS:
            return match.group(0)
        verb = "is" if state in _STATES else "has" if language.is_past_participle(state) else ""
        tails = (
            _TAILS if verb == "is" else _PARTICIPLE_TAILS | _OBJECT_DETERMINERS | _USED_UP_PARTICLES
        )
        if state in _WHEREABOUTS:
            verb, tails = "is", _WHEREABOUTS_TAILS
        read = language.lemmas(after) if after else {}
        # an adjective, never a place or a direction ("Zhang's gone home": he is away)
        if state in _BECOME and "ADJ" in read and "ADV" not in read:
            verb, tails = "has", frozenset({after})  # "light's gone amber": what it became
        if _named_thing(verb, state, after, things):
            return match.group(0)  # "can I get Owen's forecast?": the forecast is his
        if not verb and _state_of_a_thing(subject, state, after, things):
            verb, tails = "is", frozenset({after})
        if not verb or (after and after not in tails):
            return match.group(0)  # "Zhang's broken stapler": a possessive
        said = f"{subject} {verb} {state}"
        if after in _USED_UP_PARTICLES:
            said += f" {after}"  # "foil has run out"
        found.append(Evidence(words=match.group(0).strip(), meaning=said))
        adverb = match.group("adverb") or ""
        return f"{subject} {verb} {adverb}{match.group('state')}{match.group('rest')}"

    text, unmarked = _unmarked_is(text, things)
    return _CONTRACTED.sub(expand, text), [*unmarked, *found]


# "my probes dead": chat drops the apostrophe of "probe's"; a thing's word with an "s" stuck
# on, then a one-word state that ends the clause, is the thing and "is"
_UNMARKED = re.compile(
    r"\b(?P<owner>my|our|the|your|his|her|their)\s+(?P<subject>[^\W\d_]+?)s\s+"
    r"(?P<state>[a-z]+)\b(?=\s*(?:$|[.,;:!?\-–—]|\b(?:again|already|now|today)\b))",
    re.IGNORECASE,
)


def _unmarked_is(text: str, things: frozenset[str]) -> tuple[str, list[Evidence]]:
    """``text`` with "my probes dead" written "my probe is dead": the singular is one of the
    office's things' words, the state one of a thing's ("dead", "broken", "flat") ending its
    clause; a plural said as such ("my probes are dead") has its verb, and stays."""
    found: list[Evidence] = []

    def expand(match: re.Match[str]) -> str:
        subject, state = match.group("subject"), match.group("state").lower()
        if subject.lower() not in things or state not in _STATES:
            return match.group(0)
        said = f"{match.group('owner')} {subject} is {match.group('state')}"
        found.append(Evidence(words=match.group(0), meaning=said))
        return said

    return _UNMARKED.sub(expand, text), found
