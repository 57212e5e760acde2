"""A file someone already has, where the office also makes files: in an office whose scan to
PDF makes the office's own file type, "Wang's budget file" and "the budget file off Wang"
name the colleague's file, forwarded, and "print my report and send the file to Wang" says
the printed file again. Read as the product, each made a new file by scanning the
requester's paper (a wrong physical action). The office's product is the file nobody owns
yet; "a file of my contract" and "scan my contract and send the file" still make one."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention


def colleagues_file(owner: str | None, requester: str) -> bool:
    """Whether a file (of a type the office also makes) is said to be a colleague's
    ("Wang's file", "off Wang"): a possessive or a source that is not the requester."""
    return owner is not None and owner != requester


def file_again(m: Mention, mentions: Sequence[Mention], previous_item: str | None) -> bool:
    """Whether file ``m`` is "the file" said right after a task on a file of its type: only
    an article before it (a word the reader keeps no mention of, so no owner) and no "of"
    after it ("a file of my contract" is made from the paper)."""
    if previous_item != m.ids[0]:
        return False
    before = [b for b in mentions if b.end <= m.start]
    after = [a for a in mentions if a.start >= m.end]
    bare = not before or before[-1].end < m.start  # "send the file": the article between
    made_of = bool(after) and after[0].kind == "word" and after[0].ids[:1] == ("of",)
    return bare and not made_of
