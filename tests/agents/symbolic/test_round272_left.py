"""What round 272 (a car rental returns bay, read last stop) left, each by its mechanism:

- "take him the jump pack from the valet cupboard": the place said after "from" keeps one
  colleague's jump pack, so it is theirs; the speaker's own was read only because they give it;
- "get Miles to sign my sheet, no wait hes at the area meeting today, ask Dolores instead":
  the reason why the one said will not do ("hes" typed without its apostrophe), then the
  colleague chosen ("ask Dolores instead"), is a correction, never a withdrawal."""

from __future__ import annotations

import functools
from pathlib import Path

import pytest
import yaml

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import load_office, parse_office
from helpers import office_builder as ob
from helpers.reading import frame_reader

_DEFAULT = Path(__file__).resolve().parents[3] / "dataset" / "office.yaml"


@functools.cache
def _kept_office() -> InstructionParser:
    """The default office where the only stapler kept anywhere is Lee's, in the meeting room,
    and Mao has one of her own that she may not know of."""
    raw = yaml.safe_load(_DEFAULT.read_text(encoding="utf-8"))
    for p in raw["people"]:
        p["owns"] = [o for o in p["owns"] if o["type"] != "stapler"]
        if p["id"] == "lee":
            kept = {"at": "meeting_room", "facility": "meeting_room"}
            p["owns"].append({"type": "stapler", "known": True, **kept})
        if p["id"] == "mao":
            p["owns"].append({"type": "stapler", "known": False})
    return InstructionParser(parse_office(raw, "default-one-stapler-kept"))


def _read(text: str) -> list[tuple[str, str | None, str | None, str | None]]:
    frame = _kept_office().parse(text, "mao")
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "owner", "to"),
    [
        ("can you take Wang the stapler from the meeting room", "lee", "wang"),
        (
            "Wang has forms to staple. Can you take her the stapler from the meeting room?",
            "lee",
            "wang",
        ),
        # must not change: the speaker's own said, or no place said; nobody's said, read as
        # anyone's as before
        ("can you bring me the stapler from the meeting room", None, "mao"),
        ("can you take Wang my stapler from the meeting room", "mao", "wang"),
        ("can you take Wang the stapler", "mao", "wang"),
    ],
)
def test_the_place_said_after_from_says_whose_it_is(text: str, owner: str | None, to: str) -> None:
    assert _read(text) == [("transfer", "stapler", owner, to)]


_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "signer"),
    [
        (
            "get wang to sign my contract, no wait she's at a meeting today, ask zhang instead",
            "zhang",
        ),
        ("get wang to sign my contract, no wait shes off today. try zhang", "zhang"),
        ("get wang to sign my contract, no wait hes at the area meeting, ask Gao instead", "gao"),
    ],
)
def test_a_reason_then_the_colleague_chosen_corrects_the_signer(text: str, signer: str) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.owner, t.actor, t.recipient) for t in frame.tasks] == [
        ("sign", "lee", signer, "lee")
    ], frame


def test_news_of_another_colleague_is_no_choice() -> None:
    # must not change: "Zhang needs one too" is news after the reason, the request withdrawn
    frame = _lee("bring me wang's stapler, no wait she's using it, Zhang needs one too")
    assert frame.tasks == [] and frame.decline is not None, frame


_BRANCH = ob.parsed(
    lambda: ob.office_file(
        "Rental branch",
        [
            ob.person("chase", "Chase Whitaker", "fuel_card", aliases=["Chase"]),
            ob.person("kwame", "Kwame Asante", "fuel_card", aliases=["Kwame"]),
        ],
        rooms=[ob.room("back", "Back office", 30.0, 6.0)],
        item_types=[ob.item("fuel_card", "fuel card", synonyms=["card"])],
        operations=[],
        facilities=[],
        home="back",
    )
)
_chase = frame_reader(_BRANCH, "chase")


@pytest.mark.parametrize(
    "text",
    [
        "get kwame's fuel card out of the key safe for me, need to fill up my own car before I "
        "go home",
        "can you grab kwame's fuel card, I'm filling my car for the weekend",
        "bring me kwame's fuel card pls, it's for personal use",
    ],
)
def test_a_workplace_card_for_a_private_use_is_declined(text: str) -> None:
    frame = _chase(text)
    assert frame.tasks == [], frame
    assert frame.decline is not None and "private" in frame.decline, frame
    assert "kwame" not in frame.decline.lower(), frame  # no id, no blame


def test_a_card_for_the_workplace_or_ones_own_is_no_misuse() -> None:
    # must not change: the workplace's own errand is fetched; the speaker's own card, for
    # their own car, is theirs to use (asked where it is, as before)
    frame = _chase("bring me kwame's fuel card, the van's empty")
    assert frame.decline is None and frame.question is None, frame
    assert [(t.item, t.owner) for t in frame.tasks] == [("fuel_card", "kwame")], frame
    own = _chase("bring me my fuel card, need to fill up my own car")
    assert own.decline is None and own.question == (
        "Where is your fuel card? As far as I know you have it with you."
    ), own
