"""Namesakes told apart by a word of one's name said later: "drop the copy with Rosa at
reception - Álvarez, not Lindqvist", "give my contract to Rosa, the Álvarez one", "... to
Rosa, not Lindqvist". Where a name several colleagues share is said alone, a part set off
after it in the same sentence (by a comma or a dash) that says only words of the namesakes'
other names (with "not", "the", "one", or the shared name again: "Yang's book - Yang Lei, not
Liu") picks the one it names, or the one left when it names
the others with "not". The name is then read as that colleague's full name and the part left
out, as "drop the copy with Rosa Álvarez at reception" is read. Before, the shared name was
asked about though the message said which.

A part that names nobody among the namesakes ("to Rosa, not Wang") or leaves several is left
alone: the name is asked about, as before."""

from __future__ import annotations

import re

from assistantx.core import english, language
from assistantx.core.office import Office

# the words a part that picks a namesake may say besides the names ("the Álvarez one please")
_GLUE = frozenset({"the", "one", "not", "no", "but", "and", "only", "i", "mean"}) | (
    english.words("asking_words")
)
_REFUSALS = frozenset({"not", "no"})
# the words after a refusal that turn to whom is meant ("not Lindqvist but Álvarez")
_TURNS = frozenset({"but", "mean"})
_SENTENCE = re.compile(r"[^.!?;\n]+[.!?;\n]*|[.!?;\n]+")
_POSSESSIVE = re.compile(r"['’]s$", re.IGNORECASE)
_PAUSE = re.compile(r"\s*(?:[,:]|\s[-–—]+)\s*")


class NamesakeSurnames:
    """The office's shared name words, with the other words of each namesake's names."""

    def __init__(self, office: Office) -> None:
        words_of: dict[str, set[str]] = {}  # a person → the words of their names
        for p in office.people:
            words_of[p.id] = {
                language.fold(w) for name in (p.name, *p.aliases) for w in language.words(name)
            }
        holders: dict[str, list[str]] = {}
        for pid, said in words_of.items():
            for w in said:
                holders.setdefault(w, []).append(pid)
        self._full = {p.id: p.name for p in office.people}
        # a name word several share → each holder's words that none of the others has
        self._shared: dict[str, dict[str, set[str]]] = {}
        for word, pids in holders.items():
            if len(pids) < 2:
                continue
            own = {
                pid: words_of[pid] - {w for o in pids if o != pid for w in words_of[o]}
                for pid in pids
            }
            self._shared[word] = own

    def __call__(self, text: str) -> str:
        """``text`` with each shared name a later part picks said as that one's full name."""
        if not self._shared:
            return text
        return "".join(self._picked(m.group(0)) for m in _SENTENCE.finditer(text))

    def _picked(self, said_whole: str) -> str:
        body = said_whole.rstrip(".!?;\n")  # the sentence's own end kept as it was
        return self._picked_in(body) + said_whole[len(body) :]

    def _picked_in(self, sentence: str) -> str:
        for said in language.WORD.finditer(sentence):
            # "Yang's book - Yang Lei, not Liu": the name of a possessive is the name said
            name = _POSSESSIVE.sub("", said.group(0))
            own = self._shared.get(language.fold(name))
            if own is None or self._followed_by_own(sentence, said.end(), own):
                continue
            if _preceded_by_own(sentence[: said.start()], own):
                continue  # "- Liu Yang, not Lei": the full name, said in the part itself
            rest = sentence[said.end() :]
            pauses = list(_PAUSE.finditer(rest))
            chosen: set[str] = set()
            refused: set[str] = set()
            cut: list[tuple[int, int]] = []
            opener: tuple[int, int] | None = None
            for n, pause in enumerate(pauses):
                end = pauses[n + 1].start() if n + 1 < len(pauses) else len(rest)
                part = rest[pause.end() : end]
                named = _part_names(part, own, language.fold(name))
                if named is None:
                    # "- no wait, Liu Yang, not Lei": the words that open the naming part go
                    # with it (left behind alone, "no wait" withdrew the whole request)
                    opener = (pause.start(), end) if _only_correcting(part) else None
                    continue
                chosen |= named[0]
                refused |= named[1]
                if opener is not None:
                    cut.append(opener)
                    opener = None
                cut.append((pause.start(), end))
            if not cut:
                continue
            left = (chosen or set(own)) - refused
            if len(left) != 1:
                continue
            (pid,) = left
            kept = rest
            for start, end in reversed(cut):
                kept = kept[:start] + kept[end:]
            whose = said.group(0)[len(name) :]  # the possessive's "'s", kept as said
            return sentence[: said.start()] + self._full[pid] + whose + kept
        return sentence

    @staticmethod
    def _followed_by_own(sentence: str, at: int, own: dict[str, set[str]]) -> bool:
        """Whether the shared name is said with a word of one namesake's own right after it
        ("Rosa Álvarez"): it names that one already."""
        nxt = language.WORD.match(sentence, at + len(sentence[at:]) - len(sentence[at:].lstrip()))
        return nxt is not None and any(language.fold(nxt.group(0)) in w for w in own.values())


def _part_names(
    part: str, own: dict[str, set[str]], shared: str
) -> tuple[set[str], set[str]] | None:
    """The namesakes a part picks and refuses, where it says nothing but their own words and
    the glue ("Álvarez", "the Álvarez one", "not Lindqvist"); None otherwise. The shared name
    said again with one's own word ("Yang's book - Yang Lei, not Liu") is that one's full
    name: the shared word says nothing more, the other word picks."""
    words = [language.fold(w) for w in language.words(part)]
    if not words:
        return None
    chosen: set[str] = set()
    refused: set[str] = set()
    refusing = False  # "not Yang Lei": the refusal holds for the whole name after it
    for w in words:
        if w in _REFUSALS or w in _TURNS:
            refusing = w in _REFUSALS
            continue
        if w in _GLUE or w == shared:
            continue
        pids = {pid for pid, said in own.items() if w in said}
        if len(pids) != 1:
            return None
        (refused if refusing else chosen).update(pids)
    return (chosen, refused) if chosen or refused else None


# the words of a part that only says a correction follows ("no wait", "oh wait no", "sorry")
_CORRECTING = frozenset({"no", "wait", "oh", "sorry", "actually", "i", "mean", "oops", "er"})


def _only_correcting(part: str) -> bool:
    words = [language.fold(w) for w in language.words(part)]
    return bool(words) and all(w in _CORRECTING for w in words)


def _preceded_by_own(before: str, own: dict[str, set[str]]) -> bool:
    """Whether the word right before the shared name (with only a space between) is a word of
    one namesake's own ("Liu Yang"): the two say that one's full name already."""
    last = re.search(r"(\w[\w'’]*)\s+$", before)
    return last is not None and any(language.fold(last.group(1)) in w for w in own.values())
