"""A size or format word that selects the facility offering it ("get my plans printed big,
A1 if poss" where an A3 printer prints and a plotter makes large-format plots): the office's
own words for a facility (its name and synonyms, its operations' names, its products' names)
may say the size it works to ("A3 printer", "A0 plotter", "large-format plot"); a request's
size words ("A1", "big", "large format", "poster size") fit the facilities whose words say a
size that large. Where they fit exactly one facility, the request named that facility as if
by its name, and the operation chooser reads it so: its service where the verb is shared, a
question where the verb is another facility's ("Which do you mean: print or large-format
plot?"), never the verb's usual facility at a size it does not say it works to. A facility
whose words say no size fits none: the size words then choose nothing."""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from assistantx.core import english, language
from assistantx.core.office import Office

# An ISO paper size ("A0" ... "A6"): the smaller the number, the larger the sheet.
_PAPER = re.compile(r"^a([0-6])$")
# The largest paper size a large format covers: A2 and bigger.
_LARGE_FROM = 2
_LARGE = tuple(tuple(p.split()) for p in english.entries("large_sizes"))


@dataclass(frozen=True)
class Size:
    """What a request asks, or what a facility says it works to: the largest paper size said
    (its number, smaller is larger), and whether a large format is said."""

    paper: int | None
    large: bool

    @property
    def said(self) -> bool:
        return self.paper is not None or self.large


def size_of(words: Sequence[str]) -> Size:
    """The size ``words`` (folded, in order) say."""
    flat = [p for w in words for p in w.replace("-", " ").split()]
    papers = [int(m.group(1)) for w in flat if (m := _PAPER.match(w))]
    large = any(
        tuple(flat[k : k + len(phrase)]) == phrase
        for phrase in _LARGE
        for k in range(len(flat) - len(phrase) + 1)
    )
    return Size(min(papers) if papers else None, large)


def fits(asked: Size, works_to: Size) -> bool:
    """Whether a facility that works to ``works_to`` does the size ``asked``."""
    largest = works_to.paper if works_to.paper is not None else None
    if works_to.large:
        largest = 0 if largest is None else min(largest, 0)
    if largest is None:
        return False  # it says no size: no size word chooses it
    if asked.paper is not None and asked.paper < largest:
        return False  # "A1" of an A3 printer
    return not (asked.large and largest > _LARGE_FROM)  # "big" of an A3 printer


def facility_sizes(office: Office) -> dict[str, Size]:
    """Each facility whose own words say a size, with that size."""
    out: dict[str, Size] = {}
    for f in office.facilities:
        size = size_of(_words(_facility_names(office, f.id)))
        if size.said:
            out[f.id] = size
    return out


def sized_facility(sizes: dict[str, Size], words: Sequence[str]) -> str | None:
    """The one facility the size words of ``words`` fit, or None (no size said, or it fits
    none or several)."""
    asked = size_of(words)
    if not asked.said:
        return None
    fit = [f for f, size in sizes.items() if fits(asked, size)]
    return fit[0] if len(fit) == 1 else None


def _facility_names(office: Office, facility_id: str) -> Iterable[str]:
    f = office.facility(facility_id)
    yield from (f.name, *f.synonyms)
    for op_id in f.operations:
        yield office.operation(op_id).name
    for type_id in f.products:
        item = office.item_type(type_id)
        yield from (item.name, *item.synonyms)


def _words(names: Iterable[str]) -> list[str]:
    # each name on its own: a phrase never runs from one name into the next
    return [w for n in names for w in (*language.fold(n).replace("-", " ").split(), "|")]
