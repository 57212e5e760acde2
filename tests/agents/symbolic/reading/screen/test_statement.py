"""Statement: context beside a request, with the items and people it names."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.statement import stated_items, statement
from assistantx.agents.symbolic.reading.screen.terms import Terms
from reading.screen._judge import Judge, Read


def test_a_statement_is_context_with_its_items_and_whose(judged: Judge) -> None:
    found = judged(statement, "my data cable is too short", "lee")
    assert found is not None and found.verdict == "statement"
    assert found.context == ("data_cable|my",)


def test_an_item_a_person_has_is_theirs(terms: Terms, message: Read) -> None:
    msg = message("Wang has a stapler")
    assert stated_items(terms, msg.pieces[0], "lee") == ["stapler|Wang Fang's"]


def test_a_fragment_before_a_request_is_context(judged: Judge) -> None:
    found = judged(statement, "Lunch time soon. Could you bring me a pen?", "lee")
    assert found is not None and found.meaning == "context beside the request"


def test_a_request_is_no_statement(judged: Judge) -> None:
    assert judged(statement, "bring me a pen", "lee") is None
