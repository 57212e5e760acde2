"""A numbered street line is a name in any language: a small word in lower case between two of
its capitalised words ("Rua *do* Almada 120", "Unter *den* Linden 5", "Avenida *da* Liberdade
12") joins them, so the whole outside address (name, street, town) is where a send-out goes,
never its first part alone. A request of its own after the place ("..., and bring me a
stapler") is still no part of it, and a lower-case clause after a comma is still none."""

from __future__ import annotations

import pytest

from helpers.courier_room import courier_room
from helpers.reading import frame_reader

_frame = frame_reader(courier_room, "kit")


@pytest.mark.parametrize(
    ("text", "place"),
    [
        (
            "please courier my invoice to Fábrica Têxtil Alves, Rua do Almada 120, Porto",
            "Fábrica Têxtil Alves, Rua do Almada 120, Porto",
        ),
        (
            "send my form by courier to Müller GmbH, Unter den Linden 5, Berlin",
            "Müller GmbH, Unter den Linden 5, Berlin",
        ),
        (
            "courier my contract to Casa Lopes, Avenida da Liberdade 12, Lisboa",
            "Casa Lopes, Avenida da Liberdade 12, Lisboa",
        ),
        # the number first, its small words before the street's name (round 153)
        (
            "Please courier my invoice to Mme Girard, 14 rue de Seine, Paris.",
            "Mme Girard, 14 rue de Seine, Paris",
        ),
        (
            "courier my contract to Studio Bleu, 3 place du Marché, Lyon",
            "Studio Bleu, 3 place du Marché, Lyon",
        ),
        # the class's other shapes, which held already
        (
            "courier my contract to Bayside Clinic, 4 Coffee Lane, Leeds",
            "Bayside Clinic, 4 Coffee Lane, Leeds",
        ),
        (
            "send my contract by courier to Müller GmbH, Hauptstraße 5, Köln",
            "Müller GmbH, Hauptstraße 5, Köln",
        ),
    ],
)
def test_the_whole_address_is_the_destination(text: str, place: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.operation, t.destination) for t in frame.tasks] == [("courier", place)], frame


def test_a_request_after_the_place_is_its_own() -> None:
    frame = _frame("courier my contract to Bayside Clinic, and bring me a stapler")
    assert frame.question is None, frame
    assert [t.destination for t in frame.tasks if t.operation == "courier"] == ["Bayside Clinic"]
    assert any(t.kind == "transfer" and t.recipient == "kit" for t in frame.tasks), frame


def test_a_lower_case_clause_after_a_numbered_line_is_no_part_of_it() -> None:
    # "it has to go today" is a clause: no capitalised words around its small words
    frame = _frame("courier my contract to Acme Ltd, 4 Mill Road, it has to go today")
    assert [t.destination for t in frame.tasks] == ["Acme Ltd, 4 Mill Road"], frame
