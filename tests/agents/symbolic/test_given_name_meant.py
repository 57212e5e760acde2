"""A bare name that is one colleague's given name and another's family name means the one
whose given name it is, in an office written the English way (``given_name_meant``). Outside
testers of English-named offices wrote "need grant's signature on my expenses", "could frank
sign off my declaration?", "can u get miles to sign my carnet" (Grant Oyelaran beside Siobhán
Grant, Frank O'Sullivan beside Ingrid Frank, Miles O'Connell beside Dylan Miles) and expected
the given-name colleague each time; the reader asked which. Analogues on harbour, with Ray
Castillo renamed Frank Osei and Faith Oduya renamed Ingrid Frank."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import HARBOUR_FILE
from helpers.reading import frame_reader
from helpers.renamed_offices import renamed


@functools.cache
def _two_franks(family_aliases: tuple[str, ...] = ("Ingrid",)) -> Office:
    return renamed(
        HARBOUR_FILE,
        (("ray", "Frank Osei", ()), ("faith", "Ingrid Frank", family_aliases)),
        "harbour with Frank Osei and Ingrid Frank",
    )


def _read(text: str, requester: str = "may", aliases: tuple[str, ...] = ("Ingrid",)) -> TaskFrame:
    return frame_reader(lambda: _two_franks(aliases), requester)(text)


def _understood(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.owner, t.recipient, t.actor) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "need frank to sign my contract",
        "could frank sign off my form?",
        "Frank needs to sign my contract, can you sort it?",
    ],
)
def test_the_given_name_colleague_signs(text: str) -> None:
    assert _understood(_read(text)) == [("sign", "may", "may", "ray")]


@pytest.mark.parametrize(
    ("text", "requester", "owner"),
    [
        ("take my tape to frank, his ran out", "may", "may"),
        ("frank needs my ruler, can you take it over", "mark", "mark"),
    ],
)
def test_the_given_name_colleague_receives(text: str, requester: str, owner: str) -> None:
    [(kind, got_owner, recipient, _)] = _understood(_read(text, requester))
    assert (kind, got_owner, recipient) == ("transfer", owner, "ray")


def test_an_item_only_the_family_name_colleague_owns_is_still_asked() -> None:
    # Ingrid Frank has a calculator, Frank Osei none: the given name does not take it from
    # her, and the thing alone does not say whose (as before this rule)
    frame = _read("can I borrow frank's calculator")
    assert frame.tasks == []
    assert frame.question == "Who do you mean by 'frank': Ingrid Frank or Frank Osei?"
    # his own thing is his
    assert _understood(_read("can I borrow frank's umbrella"))[0][1] == "ray"


def test_a_title_of_address_goes_with_the_family_name() -> None:
    assert _understood(_read("give my tape to Ms Frank"))[0][2] == "faith"


def test_her_own_bare_alias_frank_is_hers() -> None:
    # the office says Ingrid Frank is called "Frank" (and Frank Osei has no alias): as before
    assert _understood(_read("take my tape to frank", aliases=("Ingrid", "Frank")))[0][2] == "faith"


def test_a_rank_before_her_family_name_is_asked() -> None:
    # "Sergeant Frank": where ranks go with family names, so does the family name alone
    frame = _read("take my tape to frank", aliases=("Ingrid", "Sergeant Frank"))
    assert frame.tasks == []
    assert frame.question == "Who do you mean by 'frank': Ingrid Frank or Frank Osei?"


def test_a_given_name_two_share_is_asked() -> None:
    office = renamed(
        HARBOUR_FILE,
        (
            ("ray", "Frank Osei", ()),
            ("pat", "Frank Nowak", ()),
            ("faith", "Ingrid Frank", ("Ingrid",)),
        ),
        "harbour with three Franks",
    )
    frame = frame_reader(lambda: office, "may")("take my tape to frank")
    assert frame.tasks == [] and frame.question is not None
    assert frame.question.startswith("Who do you mean by 'frank'")


def test_an_office_with_family_names_first_still_asks() -> None:
    # the default office writes family names first: "Yang" is Yang Lei's family name and
    # Liu Yang's given name, and its testers wanted a question
    frame = frame_reader(_default, "lin")("take my book to Yang")
    assert frame.tasks == []
    assert frame.question == "Who do you mean by 'Yang': Liu Yang or Yang Lei?"


def _default() -> Office:
    from helpers.dataset_offices import default_office

    return default_office()
