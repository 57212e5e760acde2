"""A machine named for the work it does: "copier", "photocopier", "scanner", "laminator" are
the doer nouns of "copy", "photocopy", "scan", "laminate". Where one facility offers two
services ("the printer" that also copies), the name the requester used for it ("run this
through the copier") says which of its services is asked: the one whose verb the name is
made from. The rule is English morphology (verb + "-er"/"-or", "y" → "i", a doubled last
consonant, a dropped "e"), applied to the office's own verbs and names, never a list."""

from __future__ import annotations

from assistantx.core import language

_SUFFIXES = ("er", "or", "r")


def is_doer_noun(noun: str, verb: str) -> bool:
    """Whether ``noun`` (one word) is the doer noun of ``verb`` ("copier" of "copy")."""
    noun, verb = language.fold(noun), language.fold(verb)
    for suffix in _SUFFIXES:
        if not noun.endswith(suffix) or len(noun) <= len(suffix) + 1:
            continue
        stem = noun[: -len(suffix)]
        if stem == verb or stem + "e" == verb:
            return True  # "printer", "laminator" (laminat + e)
        if stem.endswith("i") and stem[:-1] + "y" == verb:
            return True  # "copier"
        if len(stem) > 2 and stem[-1] == stem[-2] and stem[:-1] == verb:
            return True  # "scanner", "shredder"
    return False
