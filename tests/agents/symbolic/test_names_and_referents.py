"""Names and what a word refers to (blind rounds 34-36, written from analogues only; the
rounds' own offices and sentences were never read), in a joinery shed (``helpers.drill_shed``):

- a nickname or rank the office declares, as the subject of a request ("can the Major sign
  my form", "have the Chief sign it"): the colleague, never a choice with "the major sign";
  "have X sign Y" is a causative request, not a question;
- a lower-case name that is also a word after a party preposition ("a drill off miles"): the
  colleague; "miles away" stays words;
- a name word after a quantifier ("some guy left his lunch ..."): the word, a statement;
- "Mine." to "Whose document do you mean?": the requester's own;
- an outsider by role ("my client's certificate") or by title and surname ("the certificate for
  Mrs Kaur"): context, not a colleague to ask about;
- "it" after "X has a spare one": the one X has, taken to the person the statement was about.
"""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.drill_shed import drill_shed
from helpers.reading import frame_reader, parser_for

_frame = frame_reader(drill_shed, "sunny")


def _tasks(text: str, who: str = "sunny") -> list[tuple[str, str | None, str | None, str | None]]:
    frame = _frame(text, who)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.actor) for t in frame.tasks]


# -- A1: a declared nickname or rank as the subject of a request ---------------------------


@pytest.mark.parametrize(
    ("text", "actor"),
    [
        ("can the Major sign off my form", "dale"),
        ("could the Major sign my form when he's got a sec?", "dale"),
        ("have the Major sign my form", "dale"),
        ("have the Gaffer sign my form", "otis"),
        ("have the Chief stamp my form", "rhea"),
        ("have the Chief sign off my form when she's free", "rhea"),
        ("let the Gaffer sign my form", "otis"),
        ("can the Chief sign off my form", "rhea"),
        ("have Otis sign my form", "otis"),
        ("have Sister Ashby sign my form", "nell"),
        ("have Sister Ashby stamp my form please", "nell"),
        ("can Sister Ashby sign my form", "nell"),
    ],
)
def test_a_declared_nickname_is_the_doer(text: str, actor: str) -> None:
    tasks = _tasks(text)
    assert len(tasks) == 1 and tasks[0][1] == "form" and tasks[0][3] == actor, tasks


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("bring my form to the Major", "dale"),
        ("bring my form to the Major please", "dale"),
        ("take the certificate over to the Gaffer", "otis"),
    ],
)
def test_a_declared_nickname_after_the_is_the_recipient(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [t.recipient for t in frame.tasks] == [recipient], frame


def test_a_nickname_opening_a_statement_of_work_is_no_choice() -> None:
    frame = _frame("the Major needs to sign my form")
    assert frame.question is None or "Do you mean" not in frame.question, frame


@pytest.mark.parametrize("text", ["the major problem is my form", "bring my form to the major"])
def test_the_word_in_lower_case_is_no_nickname(text: str) -> None:
    frame = _frame(text)
    assert all(t.recipient != "dale" for t in frame.tasks), frame


@pytest.mark.parametrize(
    "text", ["have you got my form?", "have the forms been signed?", "the Major signed my form"]
)
def test_have_still_asks_or_tells(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame


# -- A2: a lower-case word-name after a party preposition ----------------------------------


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("can i borrow a drill off miles", "drill", "miles"),
        ("grab the tape measure off brook", "tape", "brook"),
        ("could you get me the drill off brook please", "drill", "brook"),
        ("grab the tape measure from brook", "tape", "brook"),
        ("can i borrow a drill off Miles", "drill", "miles"),
    ],
)
def test_a_word_name_after_off_is_the_colleague(text: str, item: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", item, owner)], frame


@pytest.mark.parametrize(
    "text", ["it's gone down to the brook", "the drill fell off the bench", "i live miles away"]
)
def test_the_word_stays_a_word(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame


# -- A3: a word-name after a quantifier is the word ----------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "some guy left his lunch in the fridge since last week and it stinks",
        "some guy left his lunch in the fridge",
        "Some guy left his lunch in the fridge, it stinks",
        "a guy left his lunch in the fridge and it stinks",
    ],
)
def test_some_guy_is_nobody_by_name(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None


def test_the_colleague_by_name_is_still_the_colleague() -> None:
    frame = _frame("could you bring Guy's lunch to me")
    assert [(t.item, t.owner) for t in frame.tasks] == [("lunchbox", "guy")], frame


# -- A4: "Mine." answers whose it is ------------------------------------------------------


@pytest.mark.parametrize("answer", ["Mine.", "my own", "it's mine", "mine", "Me", "my form"])
def test_mine_answers_whose(answer: str) -> None:
    parser = parser_for(drill_shed)
    asked = parser.parse("please bring a form to Otis", "sunny")
    assert asked.question == "Whose form do you mean?", asked
    frame = parser.parse_with_answers("please bring a form to Otis", "sunny", [answer])
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("form", "sunny", "otis")]


def test_not_mine_is_no_answer() -> None:
    parser = parser_for(drill_shed)
    frame = parser.parse_with_answers("please bring a form to Otis", "sunny", ["not mine"])
    assert frame.tasks == [], frame


def test_this_letter_is_the_requesters() -> None:
    assert _tasks("this referral letter needs signing by Otis") == [
        ("sign", "letter", "sunny", "otis")
    ]


# -- A5: an outsider by role or by title and surname --------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "could you bring my client's certificate to Otis",
        "my patient's certificate needs to go to Otis",
        "bring my customer's certificate to Otis",
        "the certificate for Mrs Kaur needs to go out to Otis",
        "take the certificate for Mrs Kaur to Otis",
        "the referral letter for Mr Dunn needs to go to Otis",
    ],
)
def test_an_outsider_is_context(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "sunny", "otis")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "take the certificate to Mrs Kaur",
        "bring Client's certificate to me",
    ],
)
def test_someone_named_to_find_is_still_asked_about(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame
    # a title and a name nobody has, handed the thing: an outsider, asked about as one
    # (round 139, test_titled_stranger.py); "Client's", no title: whom is meant
    asked = ("don't know anyone called", "I don't know who Mrs Kaur is")
    assert any(a in frame.question for a in asked), frame.question


def test_a_titled_stranger_a_thing_is_for_is_context_when_a_colleague_receives_it() -> None:
    # round 139: "for Mrs Kaur" says whom the drill is for; Otis is handed it
    frame = _frame("bring the drill for Mrs Kaur to Otis")
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "drill", "otis")]


# -- A6: "it" is the latest item that can be meant ----------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "Nell's headset died mid-session. Miles has a spare one, could you bring it to her?",
        "Nell's headset is broken. Miles has a spare one, can you grab it for her",
        "Nell's headset died. Miles has one, can you take it to Nell",
        "Nell's headset died. Miles has a spare, bring it to her",
        "Nell's headset died. Miles has got a spare one, bring it to her",
    ],
)
def test_it_is_the_spare_one(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "headset", "miles", "nell")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Miles has a drill. Brook has a drill. bring it to me",
        "Miles has a drill and Brook has a drill, bring it to me",
    ],
)
def test_two_of_a_kind_said_alike_pick_neither(text: str) -> None:
    """Near-miss: two colleagues said to have one each, neither by "one": "it" is not
    guessed as the later one's."""
    frame = _frame(text)
    assert [t.owner for t in frame.tasks if t.kind == "transfer"] in ([], [None]), frame


@pytest.mark.parametrize(
    "text",
    [
        "Nell's headset died. Miles has a spare battery, bring it to her",
        "Nell's headset died. Miles has a headset, bring it to her",
    ],
)
def test_no_one_said_moves_nothing_to_the_holder(text: str) -> None:
    """Near-miss: without "one" standing for the thing, Nell's headset never goes to Miles,
    and Miles's is not guessed."""
    frame = _frame(text)
    assert all(t.recipient != "miles" and t.owner != "miles" for t in frame.tasks), frame


def test_the_one_said_before_still_goes_where_said() -> None:
    frame = _frame("Nell's headset died, could you bring it to Miles")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("headset", "nell", "miles")]


async def test_end_to_end_the_colleague_off_whom_it_is_borrowed_is_asked() -> None:
    run = await run_instruction(drill_shed(), "sunny", "can i borrow a drill off brook")
    trace = run.stm.trace
    contacts = {getattr(r.action, "contact", None) for r in trace.actions()}
    assert "brook" in contacts and "miles" not in contacts, trace.summary
