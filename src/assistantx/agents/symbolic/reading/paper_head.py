"""A part noun that is itself the office's name of another paper heads the phrase: "photocopy
my rota *form*" where the office calls its electronic file "rota" and its paper "form".

``paper_parts`` reads a paper's name followed by a noun of its parts ("my CRF *pages*", "the
consent form *sheets*") as that paper, since pages or sheets of a paper are how the paper
itself is handled. Some of those nouns ("form", "copy") are also what an office calls one of
its papers. Where the part noun names such a paper of another type than the name before it,
the phrase is a compound of two of the office's things, and in English the head of a compound
is its last noun: the earlier name only says what the paper is about ("the rota form" is a
form about the rota). So the two are read apart, each its own item, and the reader's ordinary
rule for two item names in a row picks the head. A part noun the office does not name, or
that names the same type as the name before it ("my contract form"), stays a part.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from typing import Protocol


class _Said(Protocol):
    """What this rule reads of a mention: its kind, its ids and where it is said."""

    @property
    def kind(self) -> str: ...
    @property
    def ids(self) -> tuple[str, ...]: ...
    @property
    def start(self) -> int: ...
    @property
    def end(self) -> int: ...


def names_another_paper(
    mentions: Sequence[_Said], n: int, part_end: int, papers: Collection[str]
) -> bool:
    """Whether the part noun after item mention ``n`` (ending at ``part_end``) is, alone, the
    office's name of a paper of another type: the phrase's head, no part of mention ``n``."""
    m = mentions[n]
    if n + 1 >= len(mentions):
        return False
    head = mentions[n + 1]
    return (
        head.kind == "item"
        and head.start == m.end
        and head.end == part_end
        and len(head.ids) == 1
        and head.ids[0] in papers
        and head.ids[0] not in m.ids
    )
