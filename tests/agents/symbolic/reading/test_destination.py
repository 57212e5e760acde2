"""The destination of a service that sends outside, found once on the tokens: the requester's
own words after the service's verb phrase and "to", never a guess."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.destination import Outside, find_outside, verb_phrases
from assistantx.agents.symbolic.reading.tokens import gaps, tokenize

PHRASES = (*verb_phrases("fax", ["fax"]), *verb_phrases("courier", ["courier", "send out"]))


def _outside(text: str) -> Outside | None:
    tokens = tokenize(text)
    return find_outside(tokens, gaps(text, tokens), PHRASES)


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("fax my form to the county tax office", "the county tax office"),
        ("Fax it to 020 7946 0000 please", "020 7946 0000"),
        ("send this to Lee and fax my form to the bank. Thanks", "the bank"),
        ("faxed to Müller & Søn GmbH, asap", "Müller & Søn GmbH"),
        ("can you send out my plans to Ashdown & Reeve", "Ashdown & Reeve"),
    ],
)
def test_the_words_after_the_verb_and_to(text: str, where: str) -> None:
    found = _outside(text)
    assert found is not None and found.phrase == where


@pytest.mark.parametrize(
    "text", ["fax my form", "please fax my form, it has to go today", "fax my form to"]
)
def test_no_destination_is_none(text: str) -> None:
    found = _outside(text)
    assert found is not None and found.phrase is None and found.start is None


@pytest.mark.parametrize("text", ["take it to Lee", "send my plans to Lee"])
def test_no_send_out_phrase_is_none(text: str) -> None:
    """A phrase counts whole: "send" alone is no "send out"."""
    assert _outside(text) is None


def test_the_spans_are_the_tokens_of_the_verb_and_the_place() -> None:
    found = _outside("please send out my plans to the client")
    assert found is not None
    assert (found.operation, found.verb_start, found.verb_end) == ("courier", 1, 3)
    assert (found.start, found.end) == (6, 8) and found.holds(7) and not found.holds(5)


@pytest.mark.parametrize(
    ("text", "where"),
    [
        (
            "courier the parcel to Mrs Abernethy at 14 Rosebery Crescent, Edinburgh please",
            "Mrs Abernethy at 14 Rosebery Crescent, Edinburgh",
        ),
        ("fax my form to 3 Quay Street, Leeds LS1 4DY", "3 Quay Street, Leeds LS1 4DY"),
        (
            "send out my plans to Dr Okafor at the Old Manse, Pitlochry. Thanks",
            "Dr Okafor at the Old Manse, Pitlochry",
        ),
        ("courier it to 9 Mill Lane, Bath, asap", "9 Mill Lane, Bath"),
    ],
)
def test_an_address_goes_on_past_its_comma_to_the_clause_end(text: str, where: str) -> None:
    """A person at an address, with the town after a comma: the sender is told all of it."""
    found = _outside(text)
    assert found is not None and found.phrase == where


@pytest.mark.parametrize(
    ("text", "where"),
    [
        (
            "courier my contract to Bandai Namco, 5-37-8 Shiba, Minato-ku, Tokyo.",
            "Bandai Namco, 5-37-8 Shiba, Minato-ku, Tokyo",
        ),
        (
            "courier it to 3 Rue Cardinale, Aix-en-Provence please",
            "3 Rue Cardinale, Aix-en-Provence",
        ),
        (
            "courier it to 12 Sheep Street, Stratford-upon-Avon",
            "12 Sheep Street, Stratford-upon-Avon",
        ),
    ],
)
def test_a_hyphenated_place_name_s_lower_case_parts_belong_to_it(text: str, where: str) -> None:
    """ "Minato-ku", "Aix-en-Provence": the lower-case words glued on by a hyphen are the
    town's own; before, the address stopped at the comma before them."""
    found = _outside(text)
    assert found is not None and found.phrase == where


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("courier it to 9 Mill Lane, self-collect is fine", "9 Mill Lane"),
    ],
)
def test_a_hyphenated_lower_case_clause_is_no_town(text: str, where: str) -> None:
    found = _outside(text)
    assert found is not None and found.phrase == where


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("courier it to 9 Mill Lane, it has to go today", "9 Mill Lane"),
        ("fax my form to the county tax office, Frank", "the county tax office"),
        ("courier it to Ms Ito at 4 Elm Road, then tell me", "Ms Ito at 4 Elm Road"),
        ("fax it to 020 7946 0000, please", "020 7946 0000"),
    ],
)
def test_a_comma_before_another_clause_still_ends_the_destination(text: str, where: str) -> None:
    found = _outside(text)
    assert found is not None and found.phrase == where


@pytest.mark.parametrize(
    ("text", "where"),
    [
        (
            "the parcel needs to go out to the Kensington office, can you courier it",
            "the Kensington office",
        ),
        (
            "my form needs to go off to 3 Quay Street, Leeds. Can you fax it?",
            "3 Quay Street, Leeds",
        ),
    ],
)
def test_a_statement_before_an_it_request_says_where_it_goes(text: str, where: str) -> None:
    found = _outside(text)
    assert found is not None and found.phrase == where
    assert found.end is not None and found.end <= found.verb_start


@pytest.mark.parametrize(
    "text",
    [
        "I'm going to the bank, can you courier it",  # where the person goes
        "the parcel needs to go to the bank, can you courier my form",  # its own object
        "it needs to go to the bank. It's late. Can you fax it?",  # two sentences back
        "the form needs signing, can you fax it",  # no "to" at all
    ],
)
def test_no_statement_destination_without_it_or_from_a_person(text: str) -> None:
    found = _outside(text)
    assert found is not None and found.phrase is None
