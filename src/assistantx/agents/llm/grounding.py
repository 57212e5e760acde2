"""Is a model's reading grounded in what the requester said?

A small model asked to read "print my report and bring it to me" may answer with a tidy,
schema-valid task it copied from its prompt's example (a stapler from a colleague). A reading
is acted on only when every thing it names is found in the requester's own words, the
instruction and their answers to our questions: each task's item (by its name, a synonym or
the item type's id), each person other than the requester (by full name, alias or one name
word), and, for a service (print, copy, make coffee, heat), the service itself (one of its
verbs in any form, or its name, or what it makes). Matching is as tolerant as the embedded
reader's: case, diacritics, punctuation, titles and possessives are ignored, plurals match
singulars, and a small typo in a longer word still matches.
"""

from __future__ import annotations

import difflib
import unicodedata
from collections.abc import Iterable, Sequence

from assistantx.core import english, task_kinds
from assistantx.core.actions import Action, ForwardFile, SendQR
from assistantx.core.office import Office, Operation
from assistantx.core.task_schema import SHAPE_KIND, TaskKind
from assistantx.memory.names import normalize
from assistantx.memory.short_term import ShortTermMemory

# a typo in a word of at least this many letters still matches (the embedded reader's cut-off)
_TYPO_MIN_LETTERS = 5
_TYPO_CUTOFF = 0.85
_SERVICE_KINDS: frozenset[TaskKind] = frozenset(SHAPE_KIND.values())


def fold(text: str) -> str:
    """Lower case without diacritics: "Zhāng" and "ZHANG" are "zhang"."""
    decomposed = unicodedata.normalize("NFKD", text)
    return "".join(c for c in decomposed if not unicodedata.combining(c)).lower()


def singular(word: str) -> str:
    """The singular of a regular English plural ("copies" -> "copy", "boxes" -> "box")."""
    if len(word) > 4 and word.endswith("ies"):
        return word[:-3] + "y"
    if len(word) > 4 and word.endswith(("ses", "xes", "ches", "shes")):
        return word[:-2]
    if len(word) > 3 and word.endswith("s") and not word.endswith(("ss", "us")):
        return word[:-1]
    return word


def _words(text: str) -> list[str]:
    return [singular(w) for w in normalize(fold(text)).split()]


def _same(said: str, name: str) -> bool:
    if said == name:
        return True
    if min(len(said), len(name)) < _TYPO_MIN_LETTERS:
        return False
    return difflib.SequenceMatcher(None, said, name).ratio() >= _TYPO_CUTOFF


class RequestWords:
    """The requester's words (the instruction and their answers), searchable by name."""

    def __init__(self, office: Office, texts: Sequence[str]) -> None:
        self.office = office
        self._words = [w for text in texts for w in (*_words(text), "")]  # "" ends a text

    def says(self, phrase: str) -> bool:
        """Whether ``phrase`` occurs, word for word (each word tolerantly), in the words."""
        wanted = _words(phrase)
        if not wanted:
            return False
        n = len(wanted)
        return any(
            all(
                _same(said, name) for said, name in zip(self._words[i : i + n], wanted, strict=True)
            )
            for i in range(len(self._words) - n + 1)
        )

    def says_any(self, phrases: Iterable[str]) -> bool:
        return any(self.says(p) for p in phrases)

    def names_person(self, person_id: str) -> bool:
        person = self.office.person(person_id)
        return self.says_any((person_id, person.name, *person.aliases, *person.name.split()))

    def names_item_type(self, type_id: str) -> bool:
        item = self.office.item_type(type_id)
        return self.says_any((type_id.replace("_", " "), item.name, *item.synonyms))

    def services_said(self, kind: TaskKind) -> list[Operation]:
        """The office's services of ``kind`` the requester asked for: by one of their verbs
        (any form) or names, or by naming what they make ("a coffee")."""
        said = []
        for op in self.office.operations:
            if SHAPE_KIND.get(op.shape(self.office)) != kind:
                continue
            product = op.product is not None and self.names_item_type(op.product)
            if product or self.says_any((op.name, *op.verbs)) or _verb_forms_said(self, op.verbs):
                said.append(op)
        return said


def _verb_forms_said(words: RequestWords, verbs: Iterable[str]) -> bool:
    """ "printed", "copying", "heated": a verb's past and -ing forms."""
    forms = []
    for verb in verbs:
        stem = verb[:-1] if verb.endswith("e") else verb
        forms += [f"{stem}ed", f"{stem}ing", f"{verb}d"]
    return words.says_any(forms)


def ungrounded(
    words: RequestWords,
    requester: str,
    kind: TaskKind,
    item_type: str | None,
    people: Iterable[str | None],
) -> str | None:
    """What of one task the requester never said, in words for the model; None: grounded.

    A service's own input or product needs no word of its own: "print my report" prints a
    file, whatever the requester calls it."""
    for person in people:
        if person is not None and person != requester and not words.names_person(person):
            return f"the request never mentions {words.office.person(person).name!r}"
    item_said = item_type is not None and words.names_item_type(item_type)
    if kind in _SERVICE_KINDS:
        services = words.services_said(kind)
        if not services:
            return f"the request never asks for {kind}"
        if item_said or any(item_type in (op.input, op.product) for op in services):
            return None
    if item_type is None:
        return "the request never says which item"
    if not item_said:
        return f"the request never mentions {words.office.item_type(item_type).name!r}"
    return None


# -- the actions a model proposes (the LLM reasoner and the baselines) -------------------
UNSURE_QUESTION = (
    "Sorry, I'm not sure what you need. What should I do, with which item, and for whom?"
)


def _person_verbs(kind: str | None) -> frozenset[str] | None:
    """The words that say a person-to-person task ("signed", "stamp"): the reader's cue words
    for it, or the words of its entry in the table of kinds; None: not such a kind."""
    if kind is None or kind not in task_kinds.person_kinds():
        return None
    said = english.word_table("cues").get(kind)
    return said if said is not None else frozenset(task_kinds.kind(kind).words)


def request_words(office: Office, stm: ShortTermMemory) -> RequestWords:
    """The instruction and the requester's answers so far."""
    return RequestWords(office, [stm.text, *stm.requester_answers()])


def ungrounded_action(words: RequestWords, requester: str, action: Action) -> str | None:
    """What of one grounded action (names already ids) the requester never asked for; None:
    grounded, or an action that hands nothing over (talk, moves, waits, stop).

    A locker code hands an item over or has work done on it: its item must be said (or be
    what a requested service takes or makes), its work asked for, and whoever collects it
    must be the requester or a person they named. Who gives an item need not be named: the
    robot finds the owner of "a stapler" in memory."""
    match action:
        case SendQR(contact=contact, item=item, purpose=purpose):
            type_id = item.partition(":")[0]
            # what the code does to its item, as a task kind (deposit/collect: a transfer)
            spec = task_kinds.of_purpose(purpose)
            kind = spec.id if spec is not None else None
            verbs = _person_verbs(kind)
            if verbs is not None:
                if not words.says_any(verbs):
                    return f"the request never asks to {kind} anything"
                return None
            if kind is not None:
                return ungrounded(words, requester, kind, type_id, ())
            if purpose == "collect" and contact != requester and not words.names_person(contact):
                return f"the request never mentions {words.office.person(contact).name!r}"
            if purpose == "produce" or not words.names_item_type(type_id):
                return _unserved(words, type_id)
            return None
        case ForwardFile(target=target):
            person = any(p.id == target for p in words.office.people)
            if person and target != requester and not words.names_person(target):
                return f"the request never mentions {words.office.person(target).name!r}"
            return None
    return None


def _unserved(words: RequestWords, type_id: str) -> str | None:
    """None when a service the requester asked for takes or makes ``type_id``."""
    for kind in sorted(_SERVICE_KINDS):
        if any(type_id in (op.input, op.product) for op in words.services_said(kind)):
            return None
    return f"the request never mentions {words.office.item_type(type_id).name!r}"
