"""The lexicon's mention as the stages after it read it (``lexicon.Mention`` has these and
more): a kind, where it stands among the tokens, what it may name, and whether it was said
as a possessive. A structural type, so a stage needs no import of the lexicon."""

from __future__ import annotations

from typing import Protocol


class MentionView(Protocol):
    @property
    def kind(self) -> str: ...
    @property
    def start(self) -> int: ...
    @property
    def end(self) -> int: ...
    @property
    def ids(self) -> tuple[str, ...]: ...
    @property
    def possessive(self) -> bool: ...
