"""A thing sent to a colleague for the work the office knows by a verb: "can it go to Wang to
be fixed?", "can my contract go to Wang to be signed?", "take my mug to Wang to fix", "send my
mug to Wang for mending". The colleague is there for the work, not to keep the thing: the
clause is said as "could Wang fix it", which the reader already reads as the work asked of
that colleague (done by them where they keep the service, else said and asked) and the thing
back with the requester, unless the message names someone else to have it ("... and give it
to Ivo"). Read as "take X to P", the thing was worked on and handed to P (a wrong physical
action), or P was read as the one to receive it.

Only a colleague's name after "to", and only a verb of the office's own work or of a
colleague's work (``is_work_verb``, given the bare verb): "take my mug to Wang" and "take my
fixed mug to Wang" (no work said after the name) are left as said, and so is "to get it
fixed" (``taken_for_service``, which needs the requester's wanting it back)."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import language

_WORD = r"[^\W\d_][\w'-]*"
_THING = rf"(?P<thing>it|them|(?:my|our)(?:\s+{_WORD}){{1,4}}?)"
_WHO = rf"(?P<who>{_WORD}(?:\s+{_WORD})?)"
# "can it go to Wang to be fixed", "could my mug go over to Wang to be mended"
_GOES = re.compile(
    rf"\b(?:can|could|will|would|may)\s+{_THING}\s+go\s+(?:over\s+)?to\s+{_WHO}"
    rf"\s+to\s+be\s+(?P<done>{_WORD})\b",
    re.IGNORECASE,
)
# "take my mug to Wang to fix (it)", "send it to Wang for mending", "... for repair"
_SENT = re.compile(
    rf"\b(?:take|bring|carry|run|drop|send)\s+{_THING}\s+(?:over\s+)?to\s+{_WHO}"
    rf"\s+(?:to\s+(?P<verb>{_WORD})(?:\s+(?:it|them)\b)?|for\s+(?:a\s+|some\s+)?(?P<work>{_WORD}))",
    re.IGNORECASE,
)


def _unlisted_lemmas(word: str) -> frozenset[str]:
    """The bare verbs ``word`` is a form of where the dictionary does not know the verb (an
    office's own work: "rehair", "rehairing"): each stem whose inflections, by the rules,
    include the word ("rehairing" of "rehair", "taping" of "tape")."""
    stems = {word}  # the word itself, for a bare verb
    for end in ("ing", "ed", "es", "s"):
        if word.endswith(end) and len(word) > len(end) + 2:
            stem = word[: -len(end)]
            stems.update({stem, f"{stem}e", stem[:-1]})
    # a stem the word inflects, else the word as its own bare verb ("rehair")
    found = frozenset(s for s in stems - {word} if word in language.verb_forms(s))
    return found or frozenset({word})


def sent_for_service(
    text: str, is_person_word: Callable[[str], bool], is_work_verb: Callable[[str], bool]
) -> str:
    """``text`` with each thing sent to a colleague for a work said as that work asked of
    them ("take my mug to Wang to fix" → "could Wang fix my mug")."""

    def colleague(who: str) -> bool:
        return all(is_person_word(w) for w in who.split())

    def work_of(word: str, *, bare: bool) -> str | None:
        """The bare verb of the work ``word`` says: the verb itself, its past participle, or
        (``bare`` False) its -ing form."""
        w = word.lower()
        lemmas = language.verb_lemmas(w) or _unlisted_lemmas(w)
        if bare:  # the bare verb only: "to fixed" says no work asked
            return w if is_work_verb(w) and w in lemmas else None
        return next((v for v in sorted(lemmas) if is_work_verb(v)), None)

    def goes(m: re.Match[str]) -> str:
        verb = work_of(m.group("done"), bare=False)
        if verb is None or not colleague(m.group("who")):
            return m.group(0)
        if not language.is_past_participle(m.group("done").lower()):
            return m.group(0)  # "to be honest": no work done on the thing
        return f"could {m.group('who')} {verb} {m.group('thing')}"

    def sent(m: re.Match[str]) -> str:
        if not colleague(m.group("who")):
            return m.group(0)  # "to the office": no colleague who does the work
        said = m.group("verb")
        if said is not None:
            verb = work_of(said, bare=True)
        else:
            work = m.group("work")
            # "for mending": the -ing form's verb; "for repair": the verb said as its noun
            verb = work_of(work, bare=not work.lower().endswith("ing"))
        if verb is None:
            return m.group(0)  # "take my mug to Wang to drink from": no work of the office
        return f"could {m.group('who')} {verb} {m.group('thing')}"

    return _SENT.sub(sent, _GOES.sub(goes, text))
