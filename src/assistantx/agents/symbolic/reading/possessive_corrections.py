"""Whose one, said again after a pause: a colleague's bare possessive ("Zhang's", no noun of
its own) set off after the thing asked for corrects or picks that thing's owner; it is never
a second thing. "can I have a stapler, not Wang's, Zhang's": one stapler, Zhang's (the refused
one is left out; before, anyone's stapler AND Zhang's were fetched); "bring me Hu's stapler,
Gao's": a correction, Gao's stapler (before, both were fetched); "a stapler, Zhang's please":
Zhang's, as "a stapler, Zhang's" is read (before, anyone's AND Zhang's). "Seun's one" is the
same bare possessive with the thing's pro-form after it ("I need the moisture meter that lives
in the drying room, Seun's one": Seun's; before, anyone's). A bare possessive said right after
whom the thing was to come from replaces them ("a pen from Chen - actually Lee's": Lee's pen;
before, Chen's and Lee's were both fetched).

Only a possessive with nothing after it but "one" or a courtesy word ("please", "instead")
before a pause or the sentence's end corrects: "Zhang's too", "Zhang's scissors", "Zhang's is
broken", "Zhang's one is broken" say something else and are left alone; so is a refusal with
no choice after it ("Wang's stapler, not Zhang's"), and a choice among two owners said before
it. The choice left ("a stapler, Zhang's") is read by ``accepted_owner``, which runs after
this."""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

from assistantx.core import english

_REFUSALS = english.words("exclusion_openers") | {"no"}
_COURTESY = english.words("asking_words") | {"instead", "then"}
# "Seun's one": the pro-form of the thing said before, no second thing
_ONE = frozenset({"one", "ones"})
# "oh wait no": a sound said with the correction is part of it (fix169a class 4: "bring me
# Zhang's stapler, oh wait no, Wang's" left "oh wait no" behind, read as a withdrawal)
_MARKERS = english.entries("owner_correction_markers") + english.entries("correction_interjections")

# a pause, then words that mark a correction, right before the choice ("..., no wait, Dawn's")
_MARKED = re.compile(
    r"\s*[,:\-–—]\s*(?:(?:{m})(?:\s*,?\s*(?:{m}))*\s*[,:\-–—]?\s*)?$".format(
        m="|".join(r"\s+".join(map(re.escape, m.split())) for m in _MARKERS)
    ),
    re.IGNORECASE,
)
# the same words said with no pause before them, right before the choice ("bring me Wang's
# stapler no wait Zhang's"): the part starts at the first of them (fix201b class 1: before,
# "no wait" was left behind and read as a withdrawal of the corrected request)
_MARKED_UNPAUSED = re.compile(
    r"\s+(?:{m})(?:\s*,?\s*(?:{m}))*\s*[,:\-–—]?\s*$".format(
        m="|".join(r"\s+".join(map(re.escape, m.split())) for m in _MARKERS)
    ),
    re.IGNORECASE,
)
# words that name no thing: what a correction is said with
_SAID_WITH = (
    english.words("owner_correction_markers")
    | english.words("correction_interjections")
    | _REFUSALS
    | _COURTESY
)
_SENTENCE = re.compile(r"[^.!?;]+[.!?;]*|[.!?;]+")
_POSSESSIVE = re.compile(r"\b(?P<owner>[^\W\d_]+)['’]s\b")
_NEXT_WORD = re.compile(r"\s*(?P<word>[^\W\d_]+)")
# "if", "unless": a condition said after the possessive ends it, as a pause does
_CONDITIONS = frozenset({"if", "unless", "provided", "assuming", "when", "whenever"})
_PAUSES = ",:-–—"
_ENDS = ",;:.!?-–—"


@dataclass(frozen=True)
class _Owner:
    """A colleague's possessive in a sentence: where it is, and where its bare part stops
    (past the courtesy words after it); ``stop`` is None where a noun or another word
    follows it (it is whose thing, or says something else)."""

    start: int
    end: int
    name: str
    stop: int | None


def possessive_corrections(
    text: str, is_person: Callable[[str], bool], one_name: Callable[[str], bool] | None = None
) -> str:
    """``text`` with each sentence's bare possessive of a colleague that corrects or picks
    whose thing it asks for read as that thing's one owner (``is_person``: whether a word
    names a colleague; ``one_name``: whether words are one colleague's whole name, so that
    "Tom Hughes's" is corrected whole)."""
    whole = one_name or (lambda _: False)
    return "".join(_corrected(m.group(0), is_person, whole) for m in _SENTENCE.finditer(text))


# the word right before a possessive ("*Tom* Hughes's"): a given name said with the surname
_WORD_BEFORE = re.compile(r"(?P<word>[^\W\d_]+)\s+$")


def _owners(
    sentence: str, is_person: Callable[[str], bool], one_name: Callable[[str], bool]
) -> list[_Owner]:
    out: list[_Owner] = []
    for m in _POSSESSIVE.finditer(sentence):
        if not is_person(f"{m.group('owner')}'s"):
            continue
        start = m.start()
        before = _WORD_BEFORE.search(sentence[:start])
        if before is not None and one_name(f"{before.group('word')} {m.group(0)}"):
            start = before.start("word")  # "Tom Hughes's": the whole name is whose
        out.append(_Owner(start, m.end(), m.group("owner"), _bare_stop(sentence, m.end())))
    return out


def _bare_stop(sentence: str, at: int) -> int | None:
    """Past the courtesy words after ``at``, where a pause, "but" or the sentence's end
    comes; None where another word comes first."""
    while True:
        word = _NEXT_WORD.match(sentence, at)
        if word is None:
            rest = sentence[at:].lstrip()
            return at if not rest or rest[0] in _ENDS else None
        said = word.group("word").lower()
        if said == "but" or said in _CONDITIONS:
            return at  # "Sun's if she's around": the condition is when, no thing of Sun's
        if said not in _COURTESY and said not in _ONE:
            return None
        at = word.end()


def _words_before(sentence: str, at: int) -> list[str]:
    return [w.lower() for w in re.findall(r"[^\W\d_]+", sentence[:at])]


def _refused(sentence: str, owner: _Owner) -> bool:
    """Whether the bare possessive is refused: a refusal word right before it, no pause
    between ("not Wang's"; "no, Zhang's" picks Zhang's)."""
    head = sentence[: owner.start]
    said = re.search(r"([^\W\d_]+)\s+$", head)
    return owner.stop is not None and said is not None and said.group(1).lower() in _REFUSALS


def _opened(sentence: str, owner: _Owner) -> bool:
    """Whether the possessive opens a part of its own: after a pause, "but", or words that
    mark a correction ("no, Zhang's", "sorry I mean Zhang's")."""
    head = sentence[: owner.start].rstrip()
    if head and head[-1] in _PAUSES:
        return True
    said = " ".join(_words_before(sentence, owner.start))
    return said.endswith(" but") or any(said.endswith(f" {m}") for m in _MARKERS)


def _corrected(
    sentence: str, is_person: Callable[[str], bool], one_name: Callable[[str], bool]
) -> str:
    owners = _owners(sentence, is_person, one_name)
    chosen = [
        o
        for o in owners
        if o.stop is not None and not _refused(sentence, o) and _opened(sentence, o)
    ]
    if len(chosen) != 1:
        return sentence
    choice = chosen[0]
    refused = [o for o in owners if _refused(sentence, o)]
    if not _thing_before(sentence, min(o.start for o in [*refused, choice])):
        # "Bring me Lee's stapler. Not Lee's, Lin's.": the thing is in another sentence, read
        # by the corrections across sentences (``screen``)
        return sentence
    if refused:
        # "a stapler, not Wang's, Zhang's please": the refused one left out, the choice kept
        out = sentence
        for o in sorted(refused, key=lambda r: -r.start):
            out = _without_refusal(out, o)
        return _corrected(out, is_person, one_name)
    said_before = [o for o in owners if o.stop is None and o.end <= choice.start]
    assert choice.stop is not None
    if len(said_before) == 1:
        if said_before[0].name.lower() == choice.name.lower():
            return sentence
        # "bring me Hu's stapler, Gao's": the one thing, Gao's
        first = said_before[0]
        cut = _reason_start(sentence, first.end, _part_start(sentence, choice.start))
        return (
            sentence[: first.start]
            + f"{choice.name}'s"
            + sentence[first.end : cut]
            + sentence[choice.stop :]
        )
    cut = _part_start(sentence, choice.start)
    source = _source_before(sentence, cut, is_person)
    if not said_before and source is not None and not sentence[source.end() : cut].strip():
        # "a pen from Chen - actually Lee's": whose it is, said right after whom it was to
        # come from, replaces them (before, both were fetched); "a pen from Chen and a
        # stapler, Zhang's" is the stapler's owner, read as before
        return (
            sentence[: source.start("name")]
            + choice.name
            + sentence[source.end("name") : cut]
            + sentence[choice.stop :]
        )
    if not said_before:
        # "a stapler, Zhang's please", "a stapler, no, Zhang's": the choice, as "a stapler,
        # Zhang's" is read (the courtesy and the correction's words said with it left out)
        head = _MARKED.sub(", ", sentence[: choice.start], count=1)
        bare = _BARE_THING.search(head)
        if bare is not None and not set(bare.group("thing").lower().split()) & _NOT_THING:
            # "no wait, scissors - Sun's": a new thing said bare, then whose: Sun's scissors
            # (before, anyone's scissors and Sun's were both read)
            said = f"{choice.name}'s {bare.group('thing')}"
            return head[: bare.start("thing")] + said + sentence[choice.stop :]
        return head + sentence[choice.start : choice.end] + sentence[choice.stop :]
    return sentence


# A thing said bare (no article, one to three words) as its own part, right before the pause
# the choice follows ("no wait, *scissors*, "): the possessive is that thing's
_BARE_THING = re.compile(r"(?:^|[,:;!?\-–—]\s*)(?P<thing>[^\W\d_]+(?:\s+[^\W\d_]+){0,2}),\s*$")
# words that make the part no bare thing: an article or a word of its own ("a stapler, Zhang's"
# is read by ``accepted_owner``; "no wait, Zhang's" names nothing)
_NOT_THING = english.words("determiners") | _SAID_WITH | {"i", "you", "it", "me", "can", "could"}


# "from Chen", "from Chen Jie": whom the thing is to come from (a name, no possessive)
_SOURCE = re.compile(r"\bfrom\s+(?P<name>[^\W\d_]+(?:\s+[^\W\d_]+)?)\b(?!['’])", re.IGNORECASE)


def _source_before(
    sentence: str, at: int, is_person: Callable[[str], bool]
) -> re.Match[str] | None:
    """The last "from <colleague>" before ``at`` (the name's one or two words), if any."""
    found = None
    for m in _SOURCE.finditer(sentence, 0, at):
        name = m.group("name")
        if is_person(f"{name}'s"):
            found = m
        elif " " in name and is_person(f"{name.split()[0]}'s"):
            found = re.compile(r"\bfrom\s+(?P<name>[^\W\d_]+)").match(sentence, m.start())
    return found


def _part_start(sentence: str, at: int) -> int:
    """Where the part the possessive at ``at`` opens begins: at its pause, before the words
    that mark it a correction ("..., no wait, Dawn's"), or at those words where no pause
    comes before them ("... no wait Dawn's")."""
    marked = _MARKED.search(sentence[:at]) or _MARKED_UNPAUSED.search(sentence[:at])
    return marked.start() if marked is not None else at


# a pause, then words that mark a correction, opening a part said before the choice ("...,
# no wait she's using it on the filing, Zhang's then")
_MARKED_OPENING = re.compile(
    r"\s*[,:\-–—]\s*(?:{m})\b".format(
        m="|".join(r"\s+".join(map(re.escape, m.split())) for m in _MARKERS)
    ),
    re.IGNORECASE,
)


def _reason_start(sentence: str, start: int, cut: int) -> int:
    """Where the correction starts, between the thing's owner said first (ending at
    ``start``) and the choice's part (at ``cut``): at a pause and words that mark a
    correction, where a part of its own (why the first owner will not do) stands between
    them ("Wang's stapler, no wait she's using it on the filing, Zhang's then": that part
    goes with the correction; before, it was left behind and read as withdrawing all)."""
    marked = _MARKED_OPENING.search(sentence, start, cut)
    if marked is None or not sentence[marked.end() : cut].strip(" ,:-–—"):
        return cut
    return marked.start()


def _thing_before(sentence: str, at: int) -> bool:
    """Whether a word other than a correction's own comes before ``at`` in the sentence: the
    thing asked for is said there, not in a sentence before ("actually, no, Chen's")."""
    return any(w not in _SAID_WITH for w in _words_before(sentence, at))


def _without_refusal(sentence: str, owner: _Owner) -> str:
    """``sentence`` without "not Wang's" and the pause or "but" after it; a pause left
    dangling before the sentence's end goes too."""
    assert owner.stop is not None
    start = sentence.rfind(" ", 0, owner.start - 1) + 1  # the refusal word
    joined = re.match(r"\s*(?:[,:]|[-–—])?\s*(?:but\b\s*)?", sentence[owner.stop :])
    end = owner.stop + (joined.end() if joined is not None else 0)
    out = sentence[:start] + sentence[end:]
    out = re.sub(r"([,:])\s*[,:]", r"\1", out)
    return re.sub(r"\s*[,:]\s*(?=[.!?;]*\s*$)", "", out)
