"""A fallback offered beside a request: "bring me a stapler, or if there isn't one, scissors",
"grab me the blue folder, failing that any folder", "a coffee please, or a water if the
machine's down", "bring me scissors - or a knife if you can't find any", "can I borrow Zhang's
stapler? if he's not in, Wang's will do". The speaker wants one thing, the first; the second
only where the first cannot be had. So the two are never fetched both (fix60d class 1): the
fallback is taken out of the request before the pieces are judged, and the evidence says it is
kept back, named, for the requester to fall back on (the first is asked first).

A fallback is said three ways after a thing of the office in a request: a lead of
``fallback_leads`` or "if" and a condition of absence (``fallback_absences``: "if there isn't
one", "if you can't find any"; or someone or something in a state of ``away``,
``conditions`` or ``fallback_states``: "if he's not in", "if the machine's down") and then the
second thing; "or" the second thing and that condition; or a sentence of its own after the
request that opens with that condition and accepts the second thing (``fallback_accepts``:
"..., Wang's will do"). A condition alone ("if Zhang's in, ask him to sign my form", "if
there's no paper in the printer, top it up") and two things joined by "and" or "or" with no
condition ("a stapler and scissors", "the stapler or the scissors") are read as before."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.core.task_schema import FALLBACK_MEANING, Evidence

_CLITICS = frozenset({"s", "re", "ll", "d", "ve"})


def _phrases(*keys: str) -> str:
    """The lists' phrases as an alternation, an apostrophe or space optional where English
    writes one ("isnt": "isn't", "isn t"; "there s": "there's")."""
    out = []
    for phrase in sorted((p for k in keys for p in english.entries(k)), key=len, reverse=True):
        said = ""
        for word in phrase.split():
            # "isnt": "isn't"; "there s", "they re": "there's", "they're"
            one = re.sub(r"nt$", r"n['’]?t", re.escape(word))
            joint = r"['’]?\s*" if word in _CLITICS else r"\s+"
            said = f"{said}{joint}{one}" if said else one
        out.append(said)
    return "|".join(out)


_STATE = _phrases("away", "conditions", "fallback_states")
# "if there isn't one", "if you can't find any", "if he's not in", "if the machine's down"
_ABSENT = (
    rf"if\s+(?:(?:{_phrases('fallback_absences')})\b"
    rf"|(?:[\w'’]+\s+){{0,3}}?[\w'’]*?(?:['’]s|\s+is|\s+are)\s+(?:{_STATE})\b)"
)
_END = r"(?=\s*(?:[.;!?\n]|$))"
_BREAK = r"\s*(?:[,;]|\s[-–—]+)?\s*"
# the first thing, then a lead (a condition of absence or "failing that") and the second
_LEAD = re.compile(
    rf"{_BREAK}(?:or\s+)?(?:(?:{_phrases('fallback_leads')})\b\s*,?|{_ABSENT}[^,.;!?\n]*,)"
    rf"\s*(?P<y>[^.;!?\n]+?){_END}",
    re.IGNORECASE,
)
# the first thing, then "or" the second and the condition
_TAIL = re.compile(
    rf"{_BREAK}\bor\s+(?P<y>[^,.;!?\n]+?)\s+{_ABSENT}[^.;!?\n]*?{_END}", re.IGNORECASE
)
# a sentence of its own: the condition, then the second thing accepted
_SENTENCE = re.compile(
    rf"(?<=[.;!?])\s*{_ABSENT}[^,.;!?\n]*,?\s+(?P<y>[^.;!?\n]+?)\s+"
    rf"(?:{_phrases('fallback_accepts')})\b[^.;!?\n]*{_END}",
    re.IGNORECASE,
)
_SENTENCE_START = re.compile(r"[.;!?\n]")
_ACCEPTED = re.compile(rf"\s+(?:{_phrases('fallback_accepts')})\b.*$", re.IGNORECASE | re.DOTALL)
# "..., otherwise I'll be late": what follows, said of someone, is no second thing
_SUBJECTS = english.words("subject_pronouns")


def fallback(office: Office, lex: Lexicon, text: str) -> tuple[str, list[Evidence]]:
    """``text`` with a fallback said after a request's thing taken out; the evidence names
    the fallback kept back. Unchanged where there is none."""
    for pattern in (_TAIL, _LEAD, _SENTENCE):
        for found in pattern.finditer(text):
            before = text[: found.start()]
            clause = _SENTENCE_START.split(before.rstrip(" .;!?"))[-1]
            second = _ACCEPTED.sub("", found.group("y").strip())
            said_second = language.words(second)
            if not said_second or said_second[0] in _SUBJECTS:
                continue
            first = _things(office, lex, clause) or _same_noun(clause, second)
            if not first:
                continue
            said = text[found.start() : found.end()].strip(" ,;-–—")
            rest = f"{before.rstrip(' ,;-–—')}{text[found.end() :]}".strip()
            meaning = (
                f"{FALLBACK_MEANING}{second!r} only if {first} cannot be had, "
                f"so not fetched now; {first} is asked first"
            )
            return rest, [Evidence(words=said, meaning=meaning)]
    return text, []


def _same_noun(clause: str, second: str) -> str:
    """The noun the fallback says again ("the blue folder, failing that any folder"): one
    kind of thing named twice, a fallback even where the office has none; "" where not."""
    said = language.words(second)
    return said[-1] if said and said[-1] in language.words(clause) else ""


def _things(office: Office, lex: Lexicon, clause: str) -> str:
    """The office's thing ``clause`` names last, by name ("stapler"); "" where none."""
    items = [m for m in lex.read(clause).mentions if m.kind == "item" and m.ids]
    if not items:
        return ""
    return office.item_type(items[-1].ids[0]).name
