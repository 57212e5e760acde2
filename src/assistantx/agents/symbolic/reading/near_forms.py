"""Near forms of the office's own verbs, read as those verbs (the lexicon stage, once typos
are corrected): "fire-proof" or "fire proofed" for the declared "fireproof", "flameproofing"
for it too, "dying" for "dye".

Derived from the office's verbs only, never listed per office:

- a one-word verb made of two English words ("fireproof", "waterproof") said as two words
  or with a hyphen, each form of it ("fire-proofed");
- the same compound with its first word swapped for one English uses alike in compounds
  (``english.yaml``: ``compound_parts_alike``, "fire"/"flame");
- a verb whose -ing form keeps its final "e" ("dyeing") said with the "e" dropped as most
  verbs drop it ("dying"), a common misspelling, where that form is no form of another
  verb of the office.

A near form never replaces a word that already names something of the office.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.memory.names import normalize


@dataclass(frozen=True)
class NearForms:
    """Typed word sequences → the office verb form each stands for."""

    forms: dict[tuple[str, ...], str]
    longest: int

    @classmethod
    def from_office(cls, office: Office, inflect: Callable[[str], set[str]]) -> NearForms:
        verbs = {normalize(v) for op in office.operations for v in op.verbs}
        own = {f for v in verbs for f in inflect(v)}
        forms: dict[tuple[str, ...], str] = {}
        for verb in sorted(v for v in verbs if " " not in v and v.isalpha()):
            for form in sorted(inflect(verb)):
                for said in _compound_forms(verb, form):
                    forms.setdefault(said, form)
                dropped = _e_dropped(verb, form)
                if dropped is not None and dropped not in own:
                    forms.setdefault((dropped,), form)
        forms = {k: v for k, v in forms.items() if " ".join(k) not in own}
        return cls(forms, max((len(k) for k in forms), default=0))

    def join(self, tokens: Sequence[Token], known: Callable[[str], bool]) -> list[Token]:
        """``tokens`` with each near form read as the office's verb form; a word that is
        already a word of the office (``known``) is left as it is."""
        if not self.forms:
            return list(tokens)
        out: list[Token] = []
        n = 0
        while n < len(tokens):
            size, form = self._at(tokens, n, known)
            if size == 0:
                out.append(tokens[n])
                n += 1
                continue
            parts = tokens[n : n + size]
            out.append(
                Token(
                    text=" ".join(t.text for t in parts),
                    word=form,
                    possessive=parts[-1].possessive,
                    typed=" ".join(t.typed or t.word for t in parts),
                    opens=parts[0].opens,
                    after_pause=parts[0].after_pause,
                )
            )
            n += size
        return out

    def _at(self, tokens: Sequence[Token], n: int, known: Callable[[str], bool]) -> tuple[int, str]:
        for size in range(min(self.longest, len(tokens) - n), 0, -1):
            parts = tokens[n : n + size]
            if any(t.opens for t in parts[1:]) or any(t.possessive for t in parts[:-1]):
                continue
            form = self.forms.get(tuple(t.word for t in parts))
            if form is None or (size == 1 and known(parts[0].word)):
                continue
            return size, form
        return 0, ""


def _compound_forms(verb: str, form: str) -> list[tuple[str, ...]]:
    """The ways ``form`` of a compound ``verb`` ("fireproof") may be said: its two words
    apart ("fire proofed"; a hyphen splits as a space does), and with its first word swapped
    for one alike ("flameproofed", "flame proofed")."""
    out: list[tuple[str, ...]] = []
    for cut in range(3, len(verb) - 2):
        head, tail = verb[:cut], verb[cut:]
        if not (language.is_english_word(head) and language.is_english_word(tail)):
            continue
        if not form.startswith(head):
            continue
        rest = form[len(head) :]
        for first in (head, *_alike(head)):
            out.append((first, rest))
            if first != head:
                out.append((first + rest,))
    return out


def _alike(word: str) -> tuple[str, ...]:
    for entry in english.entries("compound_parts_alike"):
        group = entry.split()
        if word in group:
            return tuple(w for w in group if w != word)
    return ()


def _e_dropped(verb: str, form: str) -> str | None:
    """ "dyeing" → "dying": the -ing form of a verb that keeps its final "e", with the "e"
    dropped as most verbs drop it."""
    if verb.endswith("e") and not verb.endswith("ee") and form == f"{verb}ing":
        return f"{verb[:-1]}ing"
    return None
