"""Blind rounds 20 to 22, class 2 (its clipped verb and its place): "vac my prep" clips the
office's compound verb "vac pack" / "vacuum seal"; "then send my trimmings to the digester"
is the digester's own operation on them, though the other clause's verb is said. On sentences
of our own against a kitchen no sentence was written for."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.clipped_verbs import ClippedVerbs
from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.tokens import tokenize
from helpers.airside_kitchen import airside_kitchen
from helpers.reading import frame_reader

_frame = frame_reader(airside_kitchen, "odile")

_SEAL = ("vac_seal", "prep", "odile", "odile")
_DIGEST = ("digest", "trimmings", "odile", "odile")
_VAC_THEN_DIGEST = "vac my prep then send my trimmings to the digester"


def _ops(text: str) -> list[tuple[str | None, str | None, str | None, str]]:
    return [(t.operation, t.item, t.owner, t.recipient) for t in _frame(text).tasks]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("vac my prep", [_SEAL]),
        ("can you vac my prep please", [_SEAL]),
        (_VAC_THEN_DIGEST, [_SEAL, _DIGEST]),
        ("vac my prep and send my trimmings to the digester", [_SEAL, _DIGEST]),
        ("send my trimmings to the digester then vac my prep", [_DIGEST, _SEAL]),
        ("vacuum seal my prep then send my trimmings to the digester", [_SEAL, _DIGEST]),
    ],
)
def test_a_clipped_compound_verb_and_a_facility_named_for_its_item(
    text: str, expected: list[tuple[str | None, str | None, str | None, str]]
) -> None:
    assert _ops(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "vacuum seal my trimmings",  # the verb said, on an item it does not take
        "vacuum seal my trimmings at the digester",  # one clause: the verb is its own
    ],
)
def test_a_verb_on_an_item_it_does_not_take_is_still_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None


@pytest.mark.parametrize(
    "text",
    [
        "vacuum my prep",  # an English verb (a cleaner's): not read as the clip; asked
        "va my prep",  # too short to say which
        "thanks for vaccing my prep",
        "don't vac my prep",
    ],
)
def test_no_clipped_verb_where_it_does_not_fit(text: str) -> None:
    assert _frame(text).tasks == []


@pytest.mark.parametrize(
    ("text", "at", "verb"),
    [
        ("vac my prep", 0, "vacuum seal"),  # its first compound verb, as declared
        ("vacu the prep", 0, "vacuum seal"),  # clips "vacuum" of "vacuum seal"
        ("blas my prep", 0, "blast chill"),
        ("vac it", 0, None),  # no object opener after it: not in a verb's place
        ("vacuum my prep", 0, None),  # an English word
        ("va my prep", 0, None),  # under three letters
    ],
)
def test_read_needs_a_clip_of_one_operation_in_a_verbs_place(
    text: str, at: int, verb: str | None
) -> None:
    office = airside_kitchen()
    clipped = ClippedVerbs.from_office(office, Lexicon.from_office(office).verb_phrases.forms)
    tokens = tokenize(text)
    read = clipped.read(tokens, lambda word: False)
    assert (read[at].word if read[at].word != tokens[at].word else None) == verb


def test_a_first_word_two_operations_share_is_left_unread() -> None:
    clipped = ClippedVerbs({"vacuum": "a", "vac": "b"}, {"a": "vacuum seal", "b": "vac pack"})
    assert clipped.read(tokenize("vac my prep"), lambda word: False)[0].word == "vac"


async def test_the_prep_is_sealed_and_the_trimmings_digested() -> None:
    run = await run_instruction(airside_kitchen(), "odile", _VAC_THEN_DIGEST)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    done = [
        (r.action.operation, r.action.item)  # type: ignore[union-attr]
        for r in run.stm.trace.actions()
        if r.action.type == "send_qr" and r.action.operation  # type: ignore[union-attr]
    ]
    assert done == [("vac_seal", "prep:odile"), ("digest", "trimmings:odile")]
