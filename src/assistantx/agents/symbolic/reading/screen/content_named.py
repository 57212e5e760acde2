"""A file is named by what it is about: "Wang's budget planning file", "my quarter end file".
The words before a file's name say which one (its topic), never a kind of it the office does
not make; read as a variant where a scan makes the office's files, the screen asked "a budget
planning electronic file is not something this office makes" and scanned the requester's
paper instead of forwarding the owner's file.

What is a file comes from the office file only: an electronic item type (forwarded, not
carried). A physical product keeps its kinds ("day labels" where the label printer makes
labels, "iced tea" where the urn makes tea: asked), and a whole name the office lists ("pdf
file") is read by the lexicon as that name, before any of this."""

from __future__ import annotations

from assistantx.core.office import Office


def named_by_content(office: Office, item_type: str) -> bool:
    """Whether the words before ``item_type``'s name describe what the thing is about."""
    return office.item_type(item_type).kind == "electronic"
