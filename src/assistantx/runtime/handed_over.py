"""Two ways English names whom a thing goes to without a receiving word, read for the consent
guard (``runtime.recipients``) as the reader reads them:

- "Mark needs my ruler, can you take it over": a giving verb whose object is the thing said
  again ("it", "them") and a particle of carrying across ("over", "round", "across") with no
  one after it: the thing goes to whoever was said to need it;
- "Will's calculator has died, can he have mine?": a subject pronoun asked to have the thing
  ("can he have", ``core.asked_to_have``) stands where a name asked to have it would, so it
  is a receiver as "could Will have mine?" is.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.core import english, language
from assistantx.core.asked_to_have import asked_to_have, caused_for

# the thing handed over, said again
_IT = frozenset({"it", "them"})
# carried across to someone ("take it over", "bring them round"); "down", "up" name a place
# more than a person and are left to ``recipients._one_handed``'s "one"
_ACROSS = frozenset({"over", "round", "across", "around"})
# verbs that carry a thing across only with such a particle ("carry it over", "pop it
# round", "walk them across"), not giving verbs of their own
_CARRYING = frozenset({"carry", "pop", "walk", "ferry"})
# "he", "she", "they": the ones that can be asked to have a thing ("can she have mine?");
# "I", "we", "you" are the requester's side, never a colleague
_SUBJECT_PRONOUNS = english.words("subject_pronouns") & frozenset({"he", "she", "they"})


def taken_across(words: Sequence[str], is_give: Callable[[str], bool]) -> bool:
    """Whether the folded ``words`` hand the thing said before across to nobody named: a
    giving verb, "it"/"them", then "over"/"round"/"across" that ends the phrase (no "to
    Hal" after it, which names its own receiver)."""
    for n in range(len(words) - 2):
        verb = words[n]
        carries = is_give(verb) or bool({verb, *language.verb_lemmas(verb)} & _CARRYING)
        if not (carries and words[n + 1] in _IT and words[n + 2] in _ACROSS):
            continue
        after = words[n + 3] if n + 3 < len(words) else ""
        if after not in ("to", "for"):
            return True
    return False


def subject_asked_to_have(before: str, pronoun: str, after: Sequence[str]) -> bool:
    """Whether ``pronoun`` is a colleague's subject pronoun asked to have the thing: "can he
    have mine?", "could she borrow it?", "can he get his badge laminated" (the words ``before``
    and ``after`` it, folded; the first three of ``after`` for a having, all for a causative)."""
    if pronoun not in _SUBJECT_PRONOUNS:
        return False
    return asked_to_have(before, after[:3]) or caused_for(before, after)
