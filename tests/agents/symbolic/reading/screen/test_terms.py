"""The office's terms as the screen asks them: who and what a piece names, the request verbs,
an unknown thing's words, a place, and what the office lets the assistant do."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.screen.terms import Terms, listed


def test_named_lists_the_people_and_items_a_reading_names_in_order(terms: Terms) -> None:
    lexed = terms.lex.read("give Zhang's pen to Wang")
    assert terms.named(lexed, "person") == ["zhang", "wang"]
    assert terms.named(lexed, "item") == ["pen"]
    assert terms.named(lexed, "facility") == []


def test_an_item_word_after_a_possessive_is_the_item_not_a_verb(terms: Terms) -> None:
    assert terms.named(terms.lex.read("keep away from Mao's seal"), "item") == ["seal"]


def test_a_request_verb_is_a_task_word_or_a_service_verb_before_its_object(terms: Terms) -> None:
    assert terms.request_verb(split_words("bring me a pen"), 0)
    assert terms.request_verb(split_words("scan my contract"), 0)
    assert not terms.request_verb(split_words("scan twice"), 0)  # no object after it
    assert not terms.request_verb(split_words("the pen"), 0)


def test_an_unknown_thing_is_the_words_after_its_article(terms: Terms) -> None:
    assert terms.unknown_thing(split_words("who has a tape measure for me")) == "tape measure"
    assert terms.unknown_thing(split_words("who is here")) == ""


def test_a_place_is_a_facilitys_location_or_a_location_named(terms: Terms) -> None:
    assert terms.place(terms.lex.read("Zhang is at the printer")) == "print_room"
    assert terms.place(terms.lex.read("Zhang is in the kitchenette")) == "kitchenette"
    assert terms.place(terms.lex.read("Zhang is out")) is None


def test_capabilities_say_what_the_office_file_offers(terms: Terms) -> None:
    said = terms.capabilities()
    assert said.startswith("What I can do here: fetch and deliver things like stapler")
    assert "pass on files" in said and "printer" in said


def test_listed_joins_with_commas_and_a_final_and() -> None:
    assert listed(["a"]) == "a"
    assert listed(["a", "b", "c"]) == "a, b and c"
