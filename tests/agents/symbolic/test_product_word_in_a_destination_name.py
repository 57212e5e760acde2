"""A product word inside the proper name of where a thing is sent ("post my parcel to Blue
Kettle Coffee on Mill Street in York", fix186a class 3): the capitalised name after "to" or
"at" is the destination, said as written, never a variant of the office's coffee asked for
(``screen.variant``). On ``helpers.post_and_coffee`` (a post desk and a coffee machine). A
variant asked for, capitalised or not, is asked about as before."""

from __future__ import annotations

import pytest

from helpers.post_and_coffee import post_and_coffee
from helpers.reading import frame_reader

_lee = frame_reader(post_and_coffee, "lee")


@pytest.mark.parametrize(
    ("text", "destination"),
    [
        (
            "please post my parcel to Blue Kettle Coffee on Mill Street in York",
            "Blue Kettle Coffee on Mill Street in York",
        ),
        ("ship my package to Bean Coffee Roasters", "Bean Coffee Roasters"),
        ("mail my letter to Espresso House in Leeds", "Espresso House in Leeds"),
        ("post my parcel to Mill Street Books in York", "Mill Street Books in York"),  # as before
    ],
)
def test_the_name_is_the_destination(text: str, destination: str) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.operation, t.item, t.owner, t.destination) for t in frame.tasks] == [
        ("post", "parcel", "lee", destination)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "could you make me a Blue Kettle coffee",
        "send a decaf coffee to Rosa",
        "bring an Irish Coffee to Rosa",
    ],
)
def test_a_variant_asked_is_asked_about(text: str) -> None:
    frame = _lee(text)
    assert frame.question is not None and "ordinary coffee" in frame.question, frame
