"""Question: answered from the office file; one that may be a request is answered and met with
"Shall I ...?", carrying the request a yes would run."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import UNANSWERED
from assistantx.agents.symbolic.reading.screen.question import question, says_mine
from assistantx.agents.symbolic.reading.screen.terms import Terms
from reading.screen._judge import Judge


def test_who_has_an_item_is_answered_then_offered(judged: Judge) -> None:
    found = judged(question, "does anyone have a stapler?", "lee")
    assert found is not None and found.message.startswith("As far as I know, ")
    assert (found.shall, found.offer) == ("Shall I bring you one?", "bring me a stapler")


def test_whether_a_named_person_has_it_offers_theirs(judged: Judge) -> None:
    found = judged(question, "does Wang have a stapler?", "lee")
    assert found is not None
    assert found.message == "As far as I know, Wang Fang has a stapler."
    assert found.offer == "bring me Wang Fang's stapler"


def test_a_thing_the_office_lacks_is_said_so(judged: Judge) -> None:
    found = judged(question, "who has a tape measure?", "lee")
    assert found is not None
    assert found.message == "I don't know of any tape measure in this office."
    assert found.offer == ""


def test_a_question_with_nothing_to_answer_from_says_what_i_can_do(judged: Judge) -> None:
    found = judged(question, "what is the meaning of life?", "lee")
    assert found is not None and found.meaning == UNANSWERED


def test_a_request_put_as_a_question_is_no_question(judged: Judge) -> None:
    assert judged(question, "could you bring me a stapler?", "lee") is None


def test_my_item_is_the_askers_own_not_their_want(terms: Terms) -> None:
    assert says_mine(terms.lex.read("did anyone find my stapler"), "stapler")
    assert not says_mine(terms.lex.read("lend me a stapler"), "stapler")
