"""A consequence's "so" without its comma starts the ask after a statement
(``reading/consequence_boundary``): "my stapler is broken so can I borrow Wang's" borrows
Wang's stapler as it does with the comma, never "Noted" nor "Who should get your stapler?".
The degree adverb ("I'm so tired"), "do so", "so that ...", "so do I" and a "so" that opens
the text stay as said."""

from __future__ import annotations

import pytest
from _offices import parser

from assistantx.agents.symbolic.reading.consequence_boundary import consequence_boundaries

_DEFAULT = [
    ("my stapler is broken so can I borrow Wang's", ("stapler", "wang")),
    ("my stapler's broken so could I borrow Wang's stapler", ("stapler", "wang")),
    ("my stapler is broken, so can I borrow Wang's", ("stapler", "wang")),  # the comma said
    ("my stapler is broken so yeah can I borrow Wang's", ("stapler", "wang")),
    ("my pen ran out so that's why can you bring me Chen's pen", ("pen", "chen")),
    ("I lost my scissors so please bring me Sun's", ("scissors", "sun")),
    ("my pen died so would you fetch me Hu's pen", ("pen", "hu")),
]
_HARBOUR = [
    ("my calculator is dead so can I borrow Will's", ("calculator", "will")),
    ("my ruler snapped so anyway could you bring me Mark's ruler", ("ruler", "mark")),
    ("forgot my brolly so may I borrow Rose's", ("umbrella", "rose")),
]


@pytest.mark.parametrize(("text", "wanted"), _DEFAULT)
def test_an_unmarked_so_starts_the_ask_on_the_default_office(
    text: str, wanted: tuple[str, str]
) -> None:
    frame = parser("default").parse(text, "lin")
    assert frame.question is None and frame.decline is None
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", *wanted, "lin")
    ]


@pytest.mark.parametrize(("text", "wanted"), _HARBOUR)
def test_an_unmarked_so_starts_the_ask_on_harbour(text: str, wanted: tuple[str, str]) -> None:
    frame = parser("harbour").parse(text, "may")
    assert frame.question is None and frame.decline is None
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", *wanted, "may")
    ]


@pytest.mark.parametrize(
    ("text", "read"),
    [
        (
            "my stapler is broken so can I borrow Wang's",
            "my stapler is broken, so can I borrow Wang's",
        ),
        ("it broke so yeah, could you bring one", "it broke, so could you bring one"),
        ("it broke, so anyway please bring one", "it broke, so please bring one"),
        ("I'm so tired", "I'm so tired"),  # the degree adverb
        ("it's so broken", "it's so broken"),
        ("the printer jammed, please do so can you", "the printer jammed, please do so can you"),
        ("bring me a pen so that I can sign", "bring me a pen so that I can sign"),
        ("Wang needs a pen and so do I", "Wang needs a pen and so do I"),  # nothing asked after
        ("so can you bring me a pen", "so can you bring me a pen"),  # opens the text
        ("bring me a pen so I can sign", "bring me a pen so I can sign"),  # a purpose
    ],
)
def test_only_a_so_before_an_ask_gets_its_comma(text: str, read: str) -> None:
    assert consequence_boundaries(text) == read


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("so can you bring me a pen", "transfer"),  # a request as it was
        ("bring me a pen so I can sign the form", "transfer"),
    ],
)
def test_neighbours_keep_their_reading(text: str, kind: str) -> None:
    frame = parser("default").parse(text, "lin")
    assert frame.question is None
    assert [t.kind for t in frame.tasks] == [kind]


@pytest.mark.parametrize("text", ["I'm so tired", "it's so broken", "my stapler is so broken"])
def test_a_degree_so_asks_nothing(text: str) -> None:
    frame = parser("default").parse(text, "lin")
    assert not frame.tasks
