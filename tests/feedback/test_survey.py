"""One survey's state machine: answers, re-ask once, comment, reminder once, expiry."""

from __future__ import annotations

from assistantx.core.ports.messenger import ChatRef
from assistantx.feedback.answers import parse_reply
from assistantx.feedback.survey import Survey, SurveyPolicy, SurveyState

POLICY = SurveyPolicy(reminder_after_s=100, expire_after_s=1000)


def _survey() -> Survey:
    return Survey(
        instruction_id="ins-1", person="lee", chat=ChatRef(kind="dm", id="lee"), sent_at=0.0
    )


def _reply(survey: Survey, text: str, now: float = 1.0) -> str | None:
    parsed = parse_reply(text)
    assert survey.claims(text, parsed)
    return survey.apply(text, parsed, now, POLICY)


def test_answers_one_at_a_time_fill_the_open_questions_in_order() -> None:
    survey = _survey()
    answer = _reply(survey, "yes")
    assert answer is not None and answer.startswith("Got it (1: yes)")
    assert "2. Did it save you walking?" in answer and "1. Was" not in answer
    _reply(survey, "3 unsure")
    _reply(survey, "no")  # the first open question: 2
    assert survey.answers == {"success": "yes", "satisfied": "unsure", "walking": "no"}
    assert survey.state is SurveyState.OPEN
    answer = _reply(survey, "yes", now=5.0)
    assert survey.state is SurveyState.COMPLETE and survey.completed_at == 5.0
    assert answer is not None and "comment" in answer
    _reply(survey, "Thanks, the robot was fast")
    assert survey.comment == "Thanks, the robot was fast"
    assert not survey.accepts_replies(6.0, POLICY)  # the one comment is in


def test_nonsense_is_reasked_once_and_counted() -> None:
    survey = _survey()
    first = _reply(survey, "banana")
    assert first is not None and first.startswith("Sorry, I could not read")
    assert _reply(survey, "qwerty") is None  # no second re-ask: no loop with auto-responders
    assert survey.invalid_replies == 2 and survey.answers == {}
    _reply(survey, "all yes")
    assert survey.state is SurveyState.COMPLETE


def test_free_text_instead_of_answers_is_a_comment_and_asks_for_the_rest() -> None:
    survey = _survey()
    answer = _reply(survey, "The robot was late but it worked")
    assert survey.comment == "The robot was late but it worked"
    assert survey.invalid_replies == 0
    assert answer is not None and answer.startswith("Thank you for the comment")


def test_a_new_request_is_not_claimed() -> None:
    survey = _survey()
    text = "Could you bring me Zhang's stapler?"
    assert not survey.claims(text, parse_reply(text))
    survey.answers = {"success": "yes", "walking": "yes", "satisfied": "yes", "productivity": "no"}
    survey.state = SurveyState.COMPLETE
    assert not survey.claims(text, parse_reply(text))


def test_skip_and_opt_out() -> None:
    skipped = _survey()
    _reply(skipped, "skip")
    assert skipped.state is SurveyState.DECLINED
    assert not skipped.accepts_replies(2.0, POLICY)
    stopped = _survey()
    _reply(stopped, "stop surveys")
    assert stopped.state is SurveyState.OPTED_OUT
    assert not stopped.reminder_due(500.0, POLICY)


def test_one_reminder_then_expiry() -> None:
    survey = _survey()
    assert not survey.reminder_due(99.0, POLICY)
    assert survey.reminder_due(100.0, POLICY)
    text = survey.remind(100.0)
    assert "A reminder of the survey" in text and "stop surveys" in text
    assert not survey.reminder_due(500.0, POLICY)
    assert not survey.expire_if_due(999.0, POLICY)
    assert survey.expire_if_due(1000.0, POLICY)
    assert survey.state is SurveyState.EXPIRED
    assert not survey.accepts_replies(1001.0, POLICY)


def test_answered_survey_gets_no_reminder() -> None:
    survey = _survey()
    _reply(survey, "1 yes 2 yes 3 yes 4 yes")
    assert not survey.reminder_due(200.0, POLICY)


def test_invitation_lists_every_question_and_how_to_answer() -> None:
    survey = _survey()
    survey.task_text = "bring me Zhang's stapler"
    text = survey.invitation()
    for line in (
        "1. Was the task successful?",
        "2. Did it save you walking?",
        "3. Are you satisfied?",
        "4. Did it improve your productivity?",
        "5. Any comment? (optional)",
        '"stop surveys"',
        "bring me Zhang's stapler",
    ):
        assert line in text


def test_keyboard_mash_is_never_a_comment() -> None:
    survey = _survey()
    first = _reply(survey, "asdf qwerty zxcv")  # three "words", none a word
    assert first is not None and first.startswith("Sorry, I could not read that as survey")
    assert survey.comment is None and survey.invalid_replies == 1
    _reply(survey, "yes yes no yes asdfasdf")  # answers, then mash: the answers only
    assert survey.state is SurveyState.COMPLETE and survey.comment is None
    assert _reply(survey, "jkl") is None  # already re-asked once: silence
    assert survey.comment is None and survey.invalid_replies == 2
    _reply(survey, "Zu langsam")  # a comment in any language written in letters
    assert survey.comment == "Zu langsam"
