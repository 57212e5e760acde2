"""A service's past participle typed with its "-ed" clipped to "d" ("signd", "stampd",
"scand", "printd", "laminatd"): read as that participle ("signed"), not as the bare verb.

Chat drops the "e" of "-ed" (and with it the doubled consonant of "scanned"), so the typed word
is as near the verb ("sign") as its participle ("signed"), or nearer the verb ("scand" is one
edit from "scan", two from "scanned"); the typo step alone then leaves it unread or reads it
as the verb, and "get my form signd by Wang" loses its service. The word's final "d" says
which form was meant: a typed word that is a service verb of the office plus "d", or that
verb's "-ed" participle with its "e" dropped, is that participle. The verbs and their
participles are the office's own service words (the lexicon's cue words, every form of them),
found by the same edit distance as any typo, never a list of misspellings.
"""

from __future__ import annotations

from collections.abc import Collection

from assistantx.core import language


def participle_meant(word: str, verbs: Collection[str]) -> str | None:
    """The past participle among ``verbs`` (the office's service words, every form) that
    ``word`` is a clipped "-ed" of, or None. Only a word ending in a bare "d" is read so (a
    word that ends in "ed" is left to the ordinary typo step, which finds "scaned" well)."""
    if not word.endswith("d") or word.endswith("ed") or not word.isalpha():
        return None
    meant: set[str] = set()
    for near in language.closest(word, verbs):
        for lemma in {near, *language.verb_lemmas(near)}:
            past = language.past_participle(lemma)
            if past not in verbs or not past.endswith("ed"):
                continue
            # "sign" + d, or "signed" with its "e" dropped ("scanned" → "scannd")
            if word in (f"{lemma}d", f"{past[:-2]}d"):
                meant.add(past)
    # two services' participles equally meant is a typo the ordinary step leaves alone
    return meant.pop() if len(meant) == 1 else None
