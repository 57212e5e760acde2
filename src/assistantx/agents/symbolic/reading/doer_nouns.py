"""A machine named for the work it does: "copier", "photocopier", "scanner", "laminator" are
the doer nouns of "copy", "photocopy", "scan", "laminate". Where one facility offers two
services ("the printer" that also copies), the name the requester used for it ("run this
through the copier") says which of its services is asked: the one whose verb the name is
made from. The rule is English morphology (verb + "-er"/"-or", "y" → "i", a doubled last
consonant, a dropped "e"), applied to the office's own verbs and names, never a list.

The same morphology tells a doer noun the dictionary lacks from a name said in lower case
("the distributor": distribute + "-or"; "the reseller": resell + "-er"; never "the celestia"):
a word in use whose stem is a verb the dictionary knows is a common noun, someone by their
work (``is_made_doer_noun``). So is an "-ist" noun made from a noun or an adjective it knows
("stockist": stock + "-ist"; "cellist": cello; "stylist": style), seen in writing at all."""

from __future__ import annotations

from assistantx.core import language

_SUFFIXES = ("er", "or", "r")
# "-ist" makes a doer of a noun or an adjective ("stockist", "florist"): its stem as said, or
# with the vowel that "-ist" took the place of ("style", "cello", "flora", "economy")
_IST = "ist"
_IST_VOWELS = ("", "e", "o", "a", "y")
_IST_STEM = 3  # letters at least in the stem before "-ist" ("stock"; never "tw" of "twist")
_STEM_KINDS = frozenset({"NOUN", "ADJ"})


def _verbs_of(noun: str) -> tuple[str, ...]:
    """The verbs ``noun`` (folded) could be the doer noun of, by English morphology: its stem
    before "-er"/"-or"/"-r", as said, with a dropped "e", "i" for "y", or the last consonant
    doubled before "-er" undone."""
    found: list[str] = []
    for suffix in _SUFFIXES:
        if not noun.endswith(suffix) or len(noun) <= len(suffix) + 1:
            continue
        stem = noun[: -len(suffix)]
        found += [stem, stem + "e"]  # "printer", "laminator" (laminat + e)
        if stem.endswith("i"):
            found.append(stem[:-1] + "y")  # "copier"
        if suffix == "er" and len(stem) > 2 and stem[-1] == stem[-2]:
            found.append(stem[:-1])  # "scanner", "shredder"
    return tuple(found)


def is_doer_noun(noun: str, verb: str) -> bool:
    """Whether ``noun`` (one word) is the doer noun of ``verb`` ("copier" of "copy")."""
    return language.fold(verb) in _verbs_of(language.fold(noun))


def is_made_doer_noun(word: str) -> bool:
    """Whether ``word``, a lower-case word the dictionary lacks, is a doer noun made from a
    verb it knows ("distributor", "resellers"), and in use in writing: a common noun, never a
    name said in lower case ("celestia", "zhang")."""
    w = language.fold(word)
    if not w.isalpha() or language.lemmas(w):
        return False
    one = w[:-1] if w.endswith("s") else w  # "distributors"
    if _ist_noun(one) and language.zipf(w) > 0:
        return True
    if not language.is_word_form(w):
        return False
    return any(v in language.lemmas(v).get("VERB", ()) for v in _verbs_of(one))


def _ist_noun(noun: str) -> bool:
    """Whether ``noun`` (folded, singular) is "-ist" on a noun or adjective the dictionary
    knows ("stockist"; never "celestia", nor a name whose stem is no word)."""
    if not noun.endswith(_IST) or len(noun) < len(_IST) + _IST_STEM:
        return False
    stem = noun[: -len(_IST)]
    return any(_STEM_KINDS & set(language.lemmas(stem + v)) for v in _IST_VOWELS)
