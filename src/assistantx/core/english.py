"""English words that no office defines, from the package's data file ``data/english.yaml``.

Function words, titles, pronouns, generic verbs and the cue words of the task schema's
person-to-person kinds are the same in every office, so they are data of the package, not
code: the parser, the request screen, the name matcher and the simulator's reader all read
them from here. The office's own words (people, items, facilities, operations) come from the
office file. The file is read once, on first use.
"""

from __future__ import annotations

import functools
import re
from pathlib import Path

import yaml

WORDS_FILE = Path(__file__).resolve().parents[1] / "data" / "english.yaml"


@functools.cache
def _raw() -> dict[str, object]:
    # libyaml's loader when present: the pure-Python one spent most of a CLI command's start
    # on this one file.
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    raw = yaml.load(WORDS_FILE.read_text(encoding="utf-8"), Loader=loader)
    if not isinstance(raw, dict):
        raise TypeError(f"{WORDS_FILE}: expected a mapping of word lists")
    return {str(k): v for k, v in raw.items()}


@functools.cache
def entries_of() -> dict[str, tuple[str, ...]]:
    """Every list of the file, by key, entries as written (lower case)."""
    found: dict[str, tuple[str, ...]] = {}
    for key, listed in _raw().items():
        if isinstance(listed, dict):
            continue  # a table (``wording``, ``word_table``)
        if not isinstance(listed, list):
            raise TypeError(f"{WORDS_FILE}: {key}: expected a list")
        for entry in listed:
            if not isinstance(entry, str):  # YAML reads a bare off/on/no as a boolean
                raise TypeError(f"{WORDS_FILE}: {key}: {entry!r} is not a string; quote it")
        found[key] = tuple(listed)
    return found


@functools.cache
def wording(key: str) -> dict[str, str]:
    """A wording table of the file: token → the English it is said with."""
    table = _raw().get(key)
    if not isinstance(table, dict) or not all(isinstance(v, str) for v in table.values()):
        raise KeyError(f"{WORDS_FILE}: no wording table {key!r} (a mapping of strings)")
    return {str(k): str(v) for k, v in table.items()}


def entries(key: str) -> tuple[str, ...]:
    """The entries (words or phrases) listed under ``key``, in the file's order."""
    try:
        return entries_of()[key]
    except KeyError as exc:
        raise KeyError(f"{WORDS_FILE}: no list {key!r}") from exc


def alternation(*keys: str) -> str:
    """The phrases listed under ``keys`` as one regular-expression alternation, longest first
    (so "could use" is tried before "could"), the words of a phrase joined by any spaces."""
    phrases = sorted((p for k in keys for p in entries(k)), key=len, reverse=True)
    return "|".join(r"\s+".join(re.escape(w) for w in p.split()) for p in phrases)


def words(key: str) -> frozenset[str]:
    """The single words listed under ``key`` (a phrase gives each of its words)."""
    return frozenset(w for entry in entries(key) for w in entry.split())


def kind_words(kind: str) -> tuple[str, ...]:
    """The words that ask for a person-to-person task kind of the schema ("sign", "seal")."""
    return entries(f"kind_{kind}")


@functools.cache
def phrase_table(key: str) -> dict[str, tuple[str, ...]]:
    """A table of phrase lists of the file: a name → the phrases said for it, as written."""
    table = _raw().get(key)
    if not isinstance(table, dict) or not all(
        isinstance(v, list) and all(isinstance(w, str) for w in v) for v in table.values()
    ):
        raise KeyError(f"{WORDS_FILE}: no phrase table {key!r} (a mapping of string lists)")
    return {str(k): tuple(v) for k, v in table.items()}


@functools.cache
def word_table(key: str) -> dict[str, frozenset[str]]:
    """A table of word lists of the file: token (a cue's task kind) → its words."""
    table = _raw().get(key)
    if not isinstance(table, dict) or not all(
        isinstance(v, list) and all(isinstance(w, str) for w in v) for v in table.values()
    ):
        raise KeyError(f"{WORDS_FILE}: no word table {key!r} (a mapping of string lists)")
    return {str(k): frozenset(w for e in v for w in e.split()) for k, v in table.items()}
