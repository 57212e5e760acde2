"""A product said after whose it is, made only from something put in ("plot my genoa panels",
"print my rota printout"), is made from the speaker's own file: the words between say what it
is about, never a kind the office does not make (round 249: "plot my genoa panels and take
them down to Zosia" asked whether "ordinary cut panels" would do). A product with no owner
said ("a budget printout"), a finish ("my colour printout") and a product made from nothing
("my iced coffee", "my oat latte") keep the variant's question."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    "text", ["print my budget printouts", "print me my rota printout", "print our budget printout"]
)
def test_an_owned_product_made_from_a_file_is_printed(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("print", "file", "lee", "lee")
    ], frame


@pytest.mark.parametrize(
    ("text", "variant"),
    [
        ("can I get a budget printout", "a budget printout"),
        ("print my colour printout", "a colour printout"),
        ("can I get my iced coffee", "an iced coffee"),
        ("can you make my oat latte", "an oat coffee"),
    ],
)
def test_without_an_owner_or_with_a_finish_the_variant_is_asked(text: str, variant: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert f"but {variant} is not something this office makes" in frame.question, frame
