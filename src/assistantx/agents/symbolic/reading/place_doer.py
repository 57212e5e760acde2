"""A room, a facility or a team said as who does a service: "tore the hem on my apron, can
laundry stitch it up?", "could the workshop patch my bag?", "can reprographics print it?".

After a modal the word in the subject's place is who is asked to do the work; where it is one
of the office's rooms or facilities (their names and synonyms), or an English word for a team
or a workroom (``team_words``, ``service_teams``), and the verb after it is one of the office's
own operations' verbs, it names where the work is done, not a modifier of the verb ("laundry
stitch" is no service): the request is the office's operation, asked of the robot and done at
that place ("can you stitch it up at the laundry?"), on the speaker's thing, brought back as
the operation's own reading has it. A phrasal particle after the verb or its object ("stitch
it up", "patch up my apron") is read by that reading as before. A colleague's name there is a
colleague asked (never rewritten), and a verb the office does not offer stays a service the
office cannot run ("can laundry dye it?": declined as before).
"""

from __future__ import annotations

import re

from assistantx.core import english
from assistantx.core.office import Office

_MODALS = ("can", "could", "will", "would")
_PARTICLES = english.words("verb_particles")


def _alternatives(phrases: set[str]) -> str:
    ordered = sorted(phrases, key=len, reverse=True)
    return "|".join(r"\s+".join(re.escape(w) for w in p.split()) for p in ordered)


class PlaceDoers:
    """The office's rooms, facilities and the English team words, and its operations' verbs,
    read where a place is said to do a service."""

    def __init__(self, office: Office) -> None:
        # what is said → where the work is done, said back ("laundry" → "the laundry"); a team
        # word the office has no room of names no place
        places: dict[str, str | None] = {}
        for team in (*english.entries("team_words"), *english.entries("service_teams")):
            places[team.lower()] = None
        for loc in office.locations:
            if loc.kind != "workstation":
                places[loc.name.lower()] = loc.name.lower()
        for f in office.facilities:
            for said in (f.name, *f.synonyms):
                places[said.lower()] = f.name.lower()
        verbs = {v.lower() for op in office.operations for v in op.verbs}
        self._places = places
        self._pattern = (
            re.compile(
                rf"\b(?P<modal>{'|'.join(_MODALS)})\s+(?:the\s+|our\s+)?"
                rf"(?P<place>{_alternatives(set(places))})\s+(?:please\s+)?"
                rf"(?P<verb>{_alternatives(verbs)})\b(?P<rest>[^?.!;,]*)",
                re.IGNORECASE,
            )
            if verbs and places
            else None
        )

    def __call__(self, text: str) -> str:
        """``text`` with each place asked to do a service of the office said as the service
        asked of the robot at that place."""
        if self._pattern is None:
            return text

        def asked(match: re.Match[str]) -> str:
            place = self._places.get(" ".join(match.group("place").lower().split()))
            rest = match.group("rest").rstrip()
            at = f" at the {place}" if place is not None else ""
            tail = match.group("rest")[len(rest) :]
            return f"{match.group('modal')} you {match.group('verb')}{rest}{at}{tail}"

        return self._pattern.sub(asked, text)
