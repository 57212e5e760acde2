"""A second request joined to a "would you mind <verb>-ing" one by "and" is said in -ing too:
"would you mind taking my poster to be laminated, and *getting* my form signed by Harriet?"
asks two things, as "could you laminate my poster and *get* my form signed" does.

In English "mind" takes a gerund, and the verbs joined to that gerund by "and" are its
conjuncts: each is a request under the same lead-in. The reader knows a request by its verb,
and a verb in -ing elsewhere says what is under way ("I'm getting a coffee"), so after "and"
the gerund was read as no verb at all and its object fell to the first request ("not sure
what to do with the document"). So, only in a sentence whose lead-in is "mind" followed by a
gerund, a gerund after "and" ("and then", "and also") that takes an object ("my", "the",
"a", ...) is said as its plain verb, the form the reader reads as the second request.

A clause with a subject of its own in between ("would you mind bringing me a pen, I'm
drawing and labelling the boxes") is no conjunct of the request: nothing after it changes. A
gerund before a noun ("and packing tape") describes the noun, no verb: kept as said.

The same lead-in put to anyone at all ("would someone mind heating up my lunch", "would
anyone mind fetching ...") asks for the work as "could someone heat up my lunch" does; the
reader knows "mind" as a lead-in only after "you", and read "mind heating" as a verb nothing
offers (declined). There the gerund after "mind" is said as its plain verb and "mind" goes,
the joined gerunds too ("would someone heat up my lunch"); "would anyone mind if I ...",
"I don't mind waiting" have no such lead-in and stay as said.
"""

from __future__ import annotations

import re

from assistantx.core import english, language

# "would you mind bringing ...", "do you mind taking ...": the lead-in and its gerund
_MIND = re.compile(r"\bmind\s+[^\W\d_]+ing\b", re.IGNORECASE)
# the end of a sentence: a conjunct joins inside one
# "would someone mind heating ...": a modal, whom it is put to (anyone at all), "mind" and a
# gerund taking an object
_MODALS = "|".join(sorted(english.words("request_modals") - {"mind"}))
_ANYONE = "|".join(sorted(english.words("request_askees") & english.words("unnamed_doers")))
_ANYONE_MIND = re.compile(
    rf"\b(?P<modal>{_MODALS})\s+(?P<who>{_ANYONE})\s+mind\s+(?P<doing>[^\W\d_]+ing)\b",
    re.IGNORECASE,
)
_SENTENCE_END = re.compile(r"[.?!;]")
_OBJECT_STARTS = english.words("object_starts") | english.words("pronouns") | {"me", "us"}
_JOINED = re.compile(
    r"\band\s+(?:(?:then|also)\s+)?(?P<doing>[^\W\d_]+ing)\s+(?P<next>[^\W\d_]+)",
    re.IGNORECASE,
)
# a clause's own subject ("I'm", "we", "she"): what follows is no conjunct of the request
_SUBJECTS = (english.words("subject_pronouns") - {"it", "you", "u", "ya"}) | {
    "im",
    "ive",
    "id",
    "ill",
    "were",
    "theyre",
    "hes",
    "shes",
}


def joined_gerunds(text: str) -> str:
    """``text`` with each gerund joined by "and" to a "mind <verb>-ing" request said as its
    plain verb ("..., and getting my form signed" → "..., and get my form signed"); a "mind
    <verb>-ing" put to anyone at all said as its plain verb ("would someone mind heating my
    lunch" → "would someone heat my lunch")."""
    text = _anyone_minding(text)
    out: list[str] = []
    at = 0
    for lead in _MIND.finditer(text):
        if lead.start() < at:
            continue
        end = _SENTENCE_END.search(text, lead.end())
        stop = end.start() if end else len(text)
        out.append(text[at : lead.end()])
        out.append(_conjuncts(text[lead.end() : stop]))
        at = stop
    out.append(text[at:])
    return "".join(out)


def _anyone_minding(text: str) -> str:
    """``text`` with each "<modal> someone mind <verb>-ing" said "<modal> someone <verb>", its
    joined gerunds plain too, up to the end of the sentence."""
    for lead in reversed(list(_ANYONE_MIND.finditer(text))):
        plain = _plain(lead.group("doing").lower())
        if plain is None:
            continue
        end = _SENTENCE_END.search(text, lead.end())
        stop = end.start() if end else len(text)
        said = f"{lead.group('modal')} {lead.group('who')} {plain}"
        text = text[: lead.start()] + said + _conjuncts(text[lead.end() : stop]) + text[stop:]
    return text


def _conjuncts(rest: str) -> str:
    """``rest`` of a sentence after its "mind <verb>-ing", its joined gerunds said plain,
    up to a clause with a subject of its own."""
    said = rest
    for joined in reversed(list(_JOINED.finditer(rest))):
        before = re.findall(r"[^\W\d_']+(?:'[^\W\d_]+)?", rest[: joined.start()])
        if any(w.lower().replace("'", "") in _SUBJECTS for w in before):
            continue
        plain = _plain(joined.group("doing").lower())
        if plain is None or joined.group("next").lower() not in _OBJECT_STARTS:
            continue
        said = said[: joined.start("doing")] + plain + said[joined.end("doing") :]
    return said


def _plain(word: str) -> str | None:
    """The one verb ``word`` is the -ing form of, or None (no gerund, or several verbs)."""
    if not language.is_present_participle(word):
        return None
    verbs = sorted(v for v in language.verb_lemmas(word) if word in language.verb_forms(v))
    return verbs[0] if len(verbs) == 1 else None
