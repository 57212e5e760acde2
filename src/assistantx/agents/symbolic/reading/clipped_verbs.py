"""An operation's compound verb said by its first word alone, or that word clipped: "vac my
prep" for "vac pack" / "vacuum seal", as cooks say it.

The office declares compound verbs ("vacuum seal", "vac pack"), which the lexicon joins into
one token (``verb_phrases``). Said short, the first word is no English word ("vac"), or an
English word that is not the verb asked for ("vacuum" is a cleaner's): the first is read here,
the second is left alone. A word is read as the operation's verb only where:

- it is no dictionary word and no word of the office;
- it is the first word of a declared compound verb, or a clip of one (three letters or more,
  its start), of one operation only (two operations' words are left unread, to be asked);
- it stands in a verb's place: a word that opens an object follows it ("vac *my* prep").

The token then reads as that operation's compound verb, and everything after the lexicon sees
the verb it names. Nothing here knows an office's words: they all come from its file.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.memory.names import normalize

_OBJECT_STARTS = english.words("object_starts")
_SHORTEST = 3


@dataclass(frozen=True)
class ClippedVerbs:
    firsts: Mapping[str, str]  # the first word of a compound verb -> its operation
    bases: Mapping[str, str]  # an operation -> its first compound verb, as declared

    @classmethod
    def from_office(cls, office: Office, phrases: Mapping[str, str]) -> ClippedVerbs:
        """``phrases``: the forms of the office's compound verbs -> their operation."""
        bases: dict[str, str] = {}
        ops: dict[str, set[str]] = {}
        for op in office.operations:
            for verb in op.verbs:
                key = normalize(verb.replace("-", " "))
                if phrases.get(key) == op.id:
                    bases.setdefault(op.id, key)
                    ops.setdefault(key.split()[0], set()).add(op.id)
        firsts = {first: next(iter(found)) for first, found in ops.items() if len(found) == 1}
        return cls(firsts, bases)

    def read(self, tokens: Sequence[Token], known: Callable[[str], bool]) -> list[Token]:
        """``tokens`` with each clipped compound verb in a verb's place read as the verb."""
        out = list(tokens)
        for n, t in enumerate(tokens):
            nxt = tokens[n + 1] if n + 1 < len(tokens) else None
            if nxt is None or nxt.opens or nxt.word not in _OBJECT_STARTS:
                continue
            verb = self._clipped(t.word, known)
            if verb is not None:
                out[n] = replace(t, word=verb)
        return out

    def _clipped(self, word: str, known: Callable[[str], bool]) -> str | None:
        """The compound verb ``word`` clips, if it clips one operation's only."""
        if len(word) < _SHORTEST or not word.isalpha() or known(word):
            return None
        if language.is_english_word(word):
            return None
        ops = {op for first, op in self.firsts.items() if first.startswith(word)}
        return self.bases[next(iter(ops))] if len(ops) == 1 else None
