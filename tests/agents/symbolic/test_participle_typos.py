"""Issue #23, fixer fix151c class 1: a service's past participle typed with "-ed" clipped to
"d" ("get my invoice signd by Zhang pls", "need my letter stampd by Zhang", "get my tech pack
signd by Priya") is that participle (``participle_typos``), found by edit distance against the
office's own service words: before, "signd" was as near "sign" as "signed" and was left
unread, so the request lost its service and the reader asked whom the paper was for."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.core.office import load_office
from helpers.atelier import atelier
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_default = frame_reader(load_office, "lee")
_harbour = frame_reader(harbour_office, "will")
_atelier = frame_reader(atelier, "mara")


@pytest.mark.parametrize(
    ("text", "kind", "actor"),
    [
        ("can u get my form signd by Wang", "sign", "wang"),
        ("get my invoice signd by Zhang pls", "sign", "zhang"),
        ("need my letter stampd by Zhang", "seal", "zhang"),
        ("pls get my agreement signd by Dr. Zhang asap", "sign", "zhang"),
    ],
)
def test_default_office_clipped_participles(text: str, kind: str, actor: str) -> None:
    frame = _default(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks] == [
        (kind, "document", "lee", "lee", actor)
    ], frame


@pytest.mark.parametrize(
    ("typed", "spelled"),
    [
        ("can u get my form scand pls", "can u get my form scanned pls"),
        ("need my badge laminatd by noon", "need my badge laminated by noon"),
    ],
)
def test_harbour_read_as_spelled(typed: str, spelled: str) -> None:
    # "scand": one edit from "scan", two from "scanned"; the final "d" says the participle
    frame, meant = _harbour(typed), _harbour(spelled)
    assert frame.tasks and frame.tasks == meant.tasks, frame


def test_atelier_signd_then_photocopy() -> None:
    frame = _atelier("could u get my tech pack signd by Priya, then photocopy it for me")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("sign", "spec_sheet", "mara", "mara"),
        ("copy", "spec_sheet", "mara", "mara"),
    ], frame
    assert frame.tasks[0].actor == "priya", frame


@pytest.mark.parametrize(
    ("office", "typed", "meant"),
    [
        (load_office, "signd", "signed"),
        (load_office, "stampd", "stamped"),
        (load_office, "printd", "printed"),
        (harbour_office, "scand", "scanned"),
        (harbour_office, "scannd", "scanned"),
        (harbour_office, "laminatd", "laminated"),
    ],
)
def test_the_clipped_word_is_the_participle(office: object, typed: str, meant: str) -> None:
    lex = Lexicon.from_office(office())  # type: ignore[operator]
    assert [t.word for t in lex.tokens(f"have it {typed} by noon")][2] == meant


@pytest.mark.parametrize(
    ("text", "word"),
    [
        # neighbours: a verb's place keeps the verb asked for; a real word is never a typo
        ("printd my file", "print"),
        ("get my form signed by Wang", "signed"),
        ("the sand by Wang's desk", "sand"),
        ("my form is on the stand by Wang", "stand"),
    ],
)
def test_neighbours_keep_their_word(text: str, word: str) -> None:
    lex = Lexicon.from_office(load_office())
    assert word in [t.word for t in lex.tokens(text)]


async def test_end_to_end_signd_is_signed_and_handed_back() -> None:
    run = await run_instruction(load_office(), "lee", "get my invoice signd by Zhang pls")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    handed = [(e.detail["item"], e.detail["to"]) for e in run.sim.world.handovers()]
    assert handed[-1] == ("document:lee", "lee"), handed
