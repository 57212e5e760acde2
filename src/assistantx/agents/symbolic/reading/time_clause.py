"""A clause of time with a subject of its own says when, never what to do: "my report needs
printing *before I sign off tonight*, can you sort it?", "bring me a stapler *before Wang
prints the contracts*". Its verbs ("sign", "prints") are what the speaker or someone else
does then, not work asked of the robot, so the clause is taken out before the request is read
(before, "sign" was read as a signing task and the reader asked who should sign).

The clause opens with a conjunction of time (before, after, until, till, when, once, while,
whilst, as soon as) and a subject that is not the robot: "I", "he", "we" (or their contractions), a
colleague's name or "the <noun>" followed by a verb in -s or -ed or an auxiliary ("the agent
arrives", "Wang has"). It runs to the next pause or sentence end, or to where an ask opens
("can you", "please", "then"); a third person's clause also ends at "and" before a verb not
agreeing with that subject ("... before Wang prints the contracts and take my report ...").

Left alone: "before lunch, get Wang to sign my contract" (a time phrase, no clause); "when
you're at the printer, grab my printout" and "once you've printed it ..." (the robot is the
subject: what it does then is asked of it); "before it goes to Acme" (read by
``event_clause``); a name with no verb after it ("after Wang, give it to Zhang")."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english

# the conjunctions of time, longest first so "as soon as" is one
_OPENERS: tuple[tuple[str, ...], ...] = (
    ("as", "soon", "as"),
    ("before",),
    ("after",),
    ("until",),
    ("till",),
    ("when",),
    ("once",),
    ("while",),  # "watch my desk while I grab a coffee": the speaker's own errand meanwhile
    ("whilst",),
)
# The subjects that are people other than the robot. "you" is the robot (what it does then is
# asked of it) and "it"/"they"-as-thing clauses are ``event_clause``'s; "ill"/"id" are words.
_PRONOUNS = frozenset(
    {
        "i",
        "he",
        "she",
        "we",
        "they",
        "i'm",
        "im",
        "i've",
        "ive",
        "i'll",
        "i'd",
        "he's",
        "hes",
        "he'll",
        "she's",
        "shes",
        "she'll",
        "we're",
        "we've",
        "we'll",
        "they're",
        "theyre",
        "they've",
        "they'll",
    }
)
# A single person's subject: its verb agrees in -s ("Wang prints", "he signs").
_THIRD_SINGULAR = frozenset({"he", "she", "he's", "hes", "he'll", "she's", "shes", "she'll"})
# The auxiliaries and verbs in -s/-ed that show a noun before them is a subject.
_AUXILIARIES = frozenset(
    {"is", "was", "has", "had", "will", "can", "could", "does", "did", "gets", "got", "goes"}
)
# Where an ask opens after the clause: a request modal with the robot, a polite word, "then".
_MODALS = frozenset(english.words("request_modals"))
_ASKED = frozenset({"you", "u", "ya"})
_ASK_WORDS = frozenset({*english.words("polite"), "then", "so"})
_DETERMINERS = frozenset(english.words("determiners"))

_TOKEN = re.compile(r"[\w'’]+|[^\w\s]")
_PAUSES = frozenset({",", ".", ";", ":", "!", "?", "-", "–", "—", "(", ")"})


def _verb_like(word: str) -> bool:
    """Whether ``word`` is a verb a subject before it agrees with ("prints", "arrived",
    "has"): an auxiliary, or a word in -s (not "-ss", not a possessive) or -ed."""
    if word in _AUXILIARIES:
        return True
    if word.endswith("ed") and len(word) > 3:
        return True
    return word.endswith("s") and not word.endswith(("ss", "'s", "’s")) and len(word) > 2


def without_time_clauses(
    text: str, is_person: Callable[[str], bool], is_task_word: Callable[[str], bool]
) -> str:
    """``text`` without each clause of time whose subject is someone other than the robot
    and whose words hold a task's word ("before I sign off tonight", "before Wang prints the
    contracts"). ``is_person``: whether a word is a colleague's name; ``is_task_word``: whether
    a word is one of the office's task words (a clause without one, "when Ciaran is back",
    asks for nothing and may name whom "his" is later: it is kept)."""
    found = [(m.group(0), m.start(), m.end()) for m in _TOKEN.finditer(text)]
    words = [w.lower().replace("’", "'") for w, _, _ in found]
    cuts: list[tuple[int, int]] = []
    n = 0
    while n < len(words):
        end = _clause_end(words, n, lambda k: is_person(found[k][0]))
        if end is None:
            n += 1
            continue
        if any(is_task_word(w) for w in words[n:end]):
            cuts.append((found[n][1], found[end - 1][2]))
        n = end
    for start, stop in reversed(cuts):
        text = text[:start].rstrip() + " " + text[stop:].lstrip()
    return re.sub(r"^\s*[,;]\s*|\s+(?=[,.;!?])", "", text.strip()) if cuts else text


def _clause_end(words: list[str], n: int, is_person: Callable[[int], bool]) -> int | None:
    """The index just past the clause of time opening at ``words[n]``, or None when none
    opens there. ``is_person``: whether the word at an index, as written (a name's capital
    tells "Rose" from "rose"), is a colleague's name."""
    opener = next((o for o in _OPENERS if tuple(words[n : n + len(o)]) == o), None)
    if opener is None:
        return None
    s = n + len(opener)
    if s >= len(words):
        return None
    single: bool
    if words[s] in _PRONOUNS:
        verb = s + 1
        single = words[s] in _THIRD_SINGULAR
    elif words[s] == "the" and s + 2 < len(words) and _verb_like(words[s + 2]):
        verb = s + 2  # "the agent arrives"
        single = True
    elif is_person(s) and s + 1 < len(words) and _verb_like(words[s + 1]):
        verb = s + 1  # "Wang prints", a name of one or two words is read by its first
        single = True
    else:
        return None
    if verb >= len(words) or words[verb] in _PAUSES:
        return None  # "after him," or a subject with nothing after it: no clause
    k = verb
    while k < len(words):
        w = words[k]
        if w in _PAUSES or w in _ASK_WORDS:
            break
        if w in _MODALS and k + 1 < len(words) and words[k + 1] in _ASKED:
            break  # "... can you sort it?"
        if w == "and" and k + 1 < len(words) and single and _command(words[k + 1]):
            break  # "before Wang prints them and take ...": a command of its own
        k += 1
    return k


def _command(word: str) -> bool:
    """Whether ``word`` after "and" in a single person's clause opens a command: not a verb
    agreeing with that person ("and signs"), nor a noun phrase ("and the invoices")."""
    return not _verb_like(word) and word not in _DETERMINERS
