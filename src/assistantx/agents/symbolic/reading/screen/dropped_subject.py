"""A sentence of chat that drops its subject "I" ("been at the machine all morning", "just
knocked coffee all over my keyboard", "can't leave the vat", "drew a blank on the rota"): the
speaker's own state or doing, so it gets its "I" back before the pieces are judged and is read
as the statement it is, never as a request naming a facility or an item ("heat a tea at the
machine", "a knocked coffee", "dye a lunch at the vat"). So does the speaker's own going
("Off to a site meeting in a min", "Heading to the bank"): "I'm" is put back and the going is
context, never an errand outside the office. Only a clause that opens so is
restored: "can't you ...", "just bring ..." and "just put it ..." (a past form that is also
the plain verb) are left as said.
"""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.english import phrases_pattern
from assistantx.core import english, language
from assistantx.core.task_schema import Evidence

# Where a clause opens: the message's start, or after a stop or a comma.
_OPENS = r"(^|[.!?;,]\s*|\n\s*)"
# "been ..." (not "been told"/"been asked", someone else's doing to the speaker)
_BEEN = re.compile(rf"{_OPENS}(been)\b(?!\s+(?:you|u|told|asked)\b)", re.IGNORECASE)
# "can't leave ...": a modal's negation and a verb, not "can't you/someone ..." (a request)
_CANT = re.compile(rf"{_OPENS}(can'?t|cannot|couldn'?t)\s+([a-z]+)\b", re.IGNORECASE)
# "just knocked ...": "just" and a past form
_JUST = re.compile(rf"{_OPENS}(just)\s+([a-z]+)\b", re.IGNORECASE)
_ASKED_OF = english.words("request_askees") | english.words("subject_pronouns")
# "drew a blank on the rota", "left my badge at home": a past form (never also the plain verb)
# opening a clause, with its object's determiner after it
_OBJECT_STARTS = "|".join(sorted(english.words("object_starts")))
_PAST = re.compile(rf"{_OPENS}([a-z]+)\s+(?=(?:{_OBJECT_STARTS})\b)", re.IGNORECASE)
# "drew blood from the mare", "chased payment all week": a past form opening a clause with a
# bare noun for its object, written in lower case (a capital after it is a surname: "Drew
# Stone needs ...") and no possessive
_PAST_BARE = re.compile(rf"{_OPENS}([A-Za-z]+)\s+(?=([a-z]+)\b(?!['’]))")
# "off to a site meeting ...", "popping out to the bank": the speaker's own going
_GOING = re.compile(
    rf"{_OPENS}((?:just\s+)?(?:{phrases_pattern('own_going_openers')}))\b", re.IGNORECASE
)
# "Drew up the report last night", "marked out the site yesterday": a past form and its
# particle opening a sentence that says the thing is done; a capital past form is no name then
_PARTICLES = "|".join(sorted(english.words("verb_particles")))
_PAST_PARTICLE = re.compile(
    rf"{_OPENS}([A-Za-z]+)\s+(?=(?:{_PARTICLES})\s+(?:{_OBJECT_STARTS})\b)", re.IGNORECASE
)
_DONE_TIMES = tuple(
    tuple(language.words(p))
    for p in (*english.entries("past_times"), *english.entries("done_times"))
)
# "got a stapler?" asks for one (have got: possession), whatever its tense
_ASKING_PASTS = frozenset({"got", "gotten"})


def _ends_asking(text: str, at: int) -> bool:
    """Whether the sentence going on at ``at`` ends with a question mark."""
    end = re.search(r"[.!?\n]", text[at:])
    return end is not None and end.group(0) == "?"


# "photocopy my invoice, need 1 for the files": after a request, "need" and a number with no
# noun of its own is how many of what was asked the speaker needs (never at the message's
# start, nor with a thing named: "need two pens" asks)
_NEED_COUNT = re.compile(
    r"([.!?;,]\s*|\n\s*)(need)\s+"
    r"(?=(?:\d+|one|two|three|four|five|a\s+couple)\s*(?:for\b|[.!?,;]|$))",
    re.IGNORECASE,
)


def subject_restored(text: str, things: frozenset[str] = frozenset()) -> tuple[str, list[Evidence]]:
    """``text`` with "I" back before a clause that opens with "been", "can't" + a verb,
    "just" + a past form, a past form and its object ("drew a blank"; a bare noun too, "drew
    blood", unless a name of the office's ``things`` follows: "printed file for Ana" asks for
    one),
    or (after a request) "need" + a number; "I'm" before the speaker's own going ("off to
    ...")."""
    found: list[Evidence] = []

    def been(match: re.Match[str]) -> str:
        found.append(Evidence(words=match.group(2), meaning="I've been (the speaker)"))
        return f"{match.group(1)}I've {match.group(2)}"

    def cant(match: re.Match[str]) -> str:
        verb = match.group(3).lower()
        if verb in _ASKED_OF or not language.verb_lemmas(verb):
            return match.group(0)  # "can't you bring it", "can't someone ...": asked
        found.append(Evidence(words=match.group(0).strip(" ,.;"), meaning="I can't (the speaker)"))
        return f"{match.group(1)}I {match.group(2)} {match.group(3)}"

    def just(match: re.Match[str]) -> str:
        verb = match.group(3).lower()
        if not language.is_past_verb(verb) or verb in language.verb_lemmas(verb):
            return match.group(0)  # "just bring it", "just put it there": asked
        found.append(Evidence(words=match.group(0).strip(" ,.;"), meaning="I just (the speaker)"))
        return f"{match.group(1)}I {match.group(2)} {match.group(3)}"

    def need(match: re.Match[str]) -> str:
        found.append(Evidence(words=match.group(2), meaning="I need (the speaker)"))
        return f"{match.group(1)}I {match.group(2)} "

    def past(match: re.Match[str]) -> str:
        verb = match.group(2).lower()
        if not language.is_past_verb(verb) or verb in language.verb_lemmas(verb):
            return match.group(0)  # "put the box ...", "bring the ...": asked, or no verb
        if verb in _ASKING_PASTS or "AUX" in language.lemmas(verb):
            return match.group(0)  # "got a light meter?", "did my proof go out?": asked
        if _ends_asking(match.string, match.end()):
            return match.group(0)  # "left the keys in your office?": a question
        found.append(Evidence(words=match.group(0).strip(" ,.;"), meaning="I (the speaker) did"))
        return f"{match.group(1)}I {verb} "

    def past_bare(match: re.Match[str]) -> str:
        noun = match.group(3)
        said = " ".join(language.words(match.string[match.end() :])[:4])
        if any(f"{said} ".startswith(f"{thing} ") for thing in things):
            return match.group(0)  # "printed file for Ana", "signed form": a thing asked for
        if not language.is_noun(noun) or noun in _ASKED_OF or noun.endswith("s"):
            return match.group(0)  # "drew needs ...": a verb's -s form, or a plural
        if set(language.lemmas(noun)) - {"NOUN", "VERB"}:
            return match.group(0)  # a word that is also a pronoun, adverb, adjective ...
        return past(match)

    def going(match: re.Match[str]) -> str:
        if _ends_asking(match.string, match.end()):
            return match.group(0)  # "heading to the kitchen?": asked of the robot
        found.append(Evidence(words=match.group(2), meaning="I'm (the speaker) going"))
        return f"{match.group(1)}I'm {match.group(2)}"

    def past_particle(match: re.Match[str]) -> str:
        end = re.search(r"[.!?\n]", match.string[match.end() :])
        said = language.words(
            match.string[match.end() : match.end() + end.start() if end else None]
        )
        if not any(
            said[n : n + len(time)] == list(time) for time in _DONE_TIMES for n in range(len(said))
        ):
            return match.group(0)  # "Drew up the road ...", no time it was done: as said
        return past(match)

    text = _PAST.sub(past, text)
    text = _PAST_PARTICLE.sub(past_particle, text)
    text = _PAST_BARE.sub(past_bare, text)
    text = _BEEN.sub(been, text)
    text = _CANT.sub(cant, text)
    text = _NEED_COUNT.sub(need, text)
    text = _GOING.sub(going, text)
    return _JUST.sub(just, text), found
