"""An operation named by a noun phrase, on a community radio station no sentence was written
for (``helpers.radio_station``; the blind round's office and sentences were never read): "my
poster needs a lamination", "this contract could use a legal review" ask for the operation on
the thing, and "sort it / handle it / deal with it" after it refers back to it; a statement, a
question or a negation with the same nouns moves nothing."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.operation_nouns import operation_nouns, read_as_verbs
from assistantx.agents.symbolic.reading.tokens import tokenize
from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.radio_station import radio_station
from helpers.reading import frame_reader

_frame = frame_reader(radio_station, "wren")


@pytest.mark.parametrize(
    ("text", "who", "item", "operation"),
    [
        ("my poster needs a lamination", "wren", "poster", "laminate"),
        ("my poster could use a lamination, can you sort it", "wren", "poster", "laminate"),
        ("my poster needs a lamination, deal with it", "wren", "poster", "laminate"),
        ("my contract needs a legal review, can you handle it", "basil", "contract", "vet"),
        ("this contract needs a legal review", "basil", "contract", "vet"),
        ("the contract needs legal review, handle it", "basil", "contract", "vet"),
        ("my contract could do with a review, can you get that done", "basil", "contract", "vet"),
        ("my script needs a proofread before 5, can you sort it", "wren", "script", "proof"),
        ("my script should get a proofreading, deal with it", "wren", "script", "proof"),
        ("my script needs a proofread, handle it", "wren", "script", "proof"),
    ],
)
def test_an_operation_named_by_a_noun_is_asked_for(
    text: str, who: str, item: str, operation: str
) -> None:
    frame = _frame(text, who)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.operation, t.recipient) for t in frame.tasks] == [(item, operation, who)]


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("the lamination on my poster is peeling", "wren"),
        ("I did a review of my script", "wren"),
        ("my contract got a legal review yesterday", "basil"),
        ("does my contract need a legal review?", "basil"),
        ("who does the legal review?", "basil"),
        ("my contract doesn't need a legal review", "basil"),
        ("my poster doesn't need a lamination", "wren"),
    ],
)
def test_the_same_nouns_outside_a_need_ask_for_nothing(text: str, who: str) -> None:
    frame = _frame(text, who)
    assert not frame.tasks, (text, frame)


def test_the_nouns_come_from_the_office_file() -> None:
    """A nominalization of a declared verb the dictionary knows ("lamination") and the head
    noun of a display name ("legal review" of the operation asked for by "vet"); the verbs'
    own forms ("proofread", "proofreading") are the lexicon's already."""
    assert Lexicon.from_office(radio_station()).operation_nouns == {
        "lamination": "laminate",
        "review": "vet",
    }


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("my poster needs a lamination", "laminate"),
        ("it could use a quick final review", "vet"),
        ("my poster has a lamination", "lamination"),  # no need said before it
        ("I wrote a review", "review"),
        ("it needs Ana's review", "review"),  # a person's: not a modifier word
    ],
)
def test_only_a_noun_after_a_need_is_read_as_the_verb(text: str, read: str) -> None:
    nouns = {"lamination": "laminate", "review": "vet"}
    tokens = read_as_verbs(tokenize(text), nouns, lambda w: w not in ("ana", "my", "a"))
    assert tokens[-1].word == read


async def test_the_poster_is_laminated_and_comes_back() -> None:
    run = await run_instruction(
        radio_station(), "wren", "my poster could use a lamination, can you sort it"
    )
    assert run.stm.trace.outcome == "done"
    assert "poster:wren" in run.sim.world.heated
    assert run.sim.world.holder["poster:wren"] == "wren"


def test_a_thing_an_operation_is_named_after_stays_the_thing() -> None:
    """Blind round 28's class: an operation named "pack a cool box", whose product is the
    cool box, must not make "box" its noun: "I need a cool box" read "box" as the packing and
    fetched the office's cool pack instead (8 wrong hand-overs)."""

    def cold_room() -> Office:
        return ob.parsed(
            lambda: ob.office_file(
                "cold room",
                (ob.person("ines", "Ines Varga"), ob.person("otto", "Otto Brandt")),
                rooms=[ob.room("cold", "Cold room", 4.0, 20.0)],
                item_types=[
                    ob.item("cool_box", "cool box", "product", synonyms=["cool bag"]),
                    ob.item("ice_pack", "ice pack", synonyms=["cool pack"]),
                ],
                operations=[
                    ob.operation("pack", "pack", name="pack a cool box", product="cool_box")
                ],
                facilities=[
                    ob.facility(
                        "packing_bench",
                        "packing bench",
                        at="cold",
                        guards=["otto"],
                        operations=["pack"],
                        products=["cool_box"],
                        supplies=[{"type": "ice_pack", "count": 4}],
                    )
                ],
                home="cold",
            )
        )()

    office = cold_room()
    assert "box" not in operation_nouns(office, lambda w: False)
    frame = frame_reader(cold_room, "ines")(
        "I need a cool box for the insulin going out today, can one be packed for me?"
    )
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("produce", "cool_box", "ines")
    ], frame
