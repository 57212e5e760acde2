"""Speech acts on an office nobody wrote the reader for (``_survey_office``), by the failure
classes of blind round 6 (never its sentences): only a request moves the robot."""

from __future__ import annotations

import pytest
from _survey_office import REQUESTER, office
from _survey_office import read as _read
from symbolic_run import run_instruction

from assistantx.sim.office import SimOffice


@pytest.mark.parametrize(
    "text",
    [
        "could you brew me a cuppa? oh actually Hedda just brought me one, thanks anyway",
        "Make me a cup of tea please. Oh actually Wren already made me one, thanks anyway!",
        "copy my report please... oh actually Priya already did it, thanks anyway",
        "bring me a ruler - oh actually Wren just lent me hers",
        "can I get a cup of tea? oh actually someone else already got me one",
        "bring me a ruler. oh actually I already have one",
    ],
)
def test_a_request_had_already_from_someone_else_is_withdrawn(text: str) -> None:
    tasks, question, decline = _read(text)
    assert tasks == [] and question is None, (tasks, question)
    assert decline and decline.startswith("OK"), decline


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        # what someone did, told as context, or news that is not the thing asked for
        ("bring Hedda a ruler, she just asked for one", [("transfer", "ruler", None, "hedda")]),
        ("bring me a ruler, Wren just lent hers to Bill", [("transfer", "ruler", None, REQUESTER)]),
        (
            "Wren lent me her umbrella, please return it to her; it's on my desk",
            [("transfer", "umbrella", "wren", "wren")],
        ),
    ],
)
def test_news_that_does_not_have_the_thing_leaves_the_request(
    text: str, wanted: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(text)[0] == wanted


async def test_a_product_had_already_is_never_made() -> None:
    run = await run_instruction(
        office(),
        REQUESTER,
        "could you make me a cup of tea? oh actually Hedda just brought me one, thanks anyway",
    )
    assert run.sim.world.holder == SimOffice(office()).world.holder
    assert run.actions == [] or not any("operate" in a for a in run.actions), run.actions


@pytest.mark.parametrize(
    "text",
    [
        "I might need to borrow Ciaran's ruler later, I'll let you know",
        "might need a calculator later if Bill is out, will let you know",
        "I may need Hedda's laser measure tomorrow if the client agrees; I'll let you know",
        "I'll probably need a calculator later",
        "Could I maybe borrow Ciaran's ruler later? I'll let you know",
    ],
)
def test_a_need_that_may_come_later_is_answered_not_met_now(text: str) -> None:
    tasks, question, decline = _read(text)
    assert tasks == [] and question is None, (tasks, question)
    assert decline and "tell me when" in decline.lower(), decline


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        ("I need a ruler", [("transfer", "ruler", None, REQUESTER)]),
        (
            "can you bring me a ruler? I might need it later",
            [("transfer", "ruler", None, REQUESTER)],
        ),
        (
            "bring me Ciaran's ruler, I'll let you know if I need more",
            [("transfer", "ruler", "ciaran", REQUESTER)],
        ),
    ],
)
def test_a_need_for_now_beside_a_later_one_is_still_read(
    text: str, wanted: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(text)[0] == wanted


@pytest.mark.parametrize(
    "text",
    [
        "Can you even carry a cup of tea without spilling it?",
        "can you actually make tea?",
        "could you really carry an umbrella up the stairs?",
        "can you bring me a ruler without dropping it?",
        "can you even lift a calculator?",
    ],
)
def test_a_doubt_about_what_the_assistant_can_do_is_answered_and_offered(text: str) -> None:
    tasks, question, _ = _read(text)
    assert tasks == [], tasks
    assert question and question.startswith("Yes, I can") and "Shall I" in question, question


@pytest.mark.parametrize(
    "text", ["could you possibly bring me a ruler?", "can you bring me a ruler?"]
)
def test_a_polite_request_is_still_one(text: str) -> None:
    assert _read(text)[0] == [("transfer", "ruler", None, REQUESTER)]


@pytest.mark.parametrize(
    "text",
    [
        "wish this place had a kettle upstairs",
        "wish we had a laser measure here",
        "shame there's no laser measure in the studio",
        "pity there's no second copier",
        "too bad there's no kettle up here",
        "would be nice to have tape in the studio",
    ],
)
def test_a_regret_about_what_the_place_lacks_is_answered_in_words(text: str) -> None:
    tasks, question, decline = _read(text)
    assert tasks == [] and question is None, (tasks, question)
    assert decline and decline.startswith("Noted"), decline


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        ("wish me luck, bring me a ruler", [("transfer", "ruler", None, REQUESTER)]),
        (
            "shame about the rain, can you bring me Wren's umbrella",
            [("transfer", "umbrella", "wren", REQUESTER)],
        ),
        ("would be nice to have a ruler on my desk", [("transfer", "ruler", None, REQUESTER)]),
    ],
)
def test_a_request_beside_a_regret_or_for_the_speaker_is_still_read(
    text: str, wanted: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(text)[0] == wanted


@pytest.mark.parametrize(
    "text",
    [
        "never mind, found the calculator in my drawer, thanks",
        "bring me a ruler. Never mind! Found the ruler under my desk.",
        "never mind, found my umbrella in the studio, cheers",
    ],
)
def test_a_withdrawal_with_its_reason_drops_the_request(text: str) -> None:
    tasks, question, decline = _read(text)
    assert tasks == [] and question is None, (tasks, question)
    assert decline and decline.startswith("OK"), decline


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        (
            "never mind, found the calculator in my drawer, but could you bring me a ruler",
            [("transfer", "ruler", None, REQUESTER)],
        ),
        (
            "never mind the ruler. bring me a calculator instead",
            [("transfer", "calculator", None, REQUESTER)],
        ),
    ],
)
def test_a_request_after_a_withdrawal_and_its_reason_is_read(
    text: str, wanted: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(text)[0] == wanted


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        (
            "I hope you don't mind fetching me Ciaran's ruler",
            [("transfer", "ruler", "ciaran", REQUESTER)],
        ),
        ("hope you won't mind brewing me a cuppa", [("produce", "tea", None, REQUESTER)]),
        (
            "if you wouldn't mind photocopying my drawing",
            [("copy", "document", REQUESTER, REQUESTER)],
        ),
    ],
)
def test_a_request_hedged_as_a_hope_is_read(
    text: str, wanted: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(text)[0] == wanted


def test_the_speakers_own_willingness_is_no_request() -> None:
    tasks, question, decline = _read("I don't mind fetching it myself")
    assert tasks == [] and question is None and decline, (tasks, question)


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        ("I have faith in you bring me a ruler", [("transfer", "ruler", None, REQUESTER)]),
        (
            "I have every confidence in you please bring me Wren's umbrella",
            [("transfer", "umbrella", "wren", REQUESTER)],
        ),
        (
            "I'm so grateful to you fetch me the calculator",
            [("transfer", "calculator", None, REQUESTER)],
        ),
        ("🙏🙏 brew me a cuppa", [("produce", "tea", None, REQUESTER)]),
    ],
)
def test_a_request_after_an_aside_in_the_same_sentence_is_read(
    text: str, wanted: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(text)[0] == wanted


@pytest.mark.parametrize(
    "text",
    [
        "I have one copy left",
        "Hedda brought me a ruler",
        "thank you so much for bringing me the ruler",
    ],
)
def test_a_statement_or_thanks_with_a_task_word_is_no_request(text: str) -> None:
    tasks, question, decline = _read(text)
    assert tasks == [] and question is None and decline, (tasks, question)


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        ("Tea time soon. Could you bring me a ruler?", [("transfer", "ruler", None, REQUESTER)]),
        (
            "I need to pay the bill. Could you bring me a calculator?",
            [("transfer", "calculator", None, REQUESTER)],
        ),
        (
            "The bill is due today. Can you bring me a calculator?",
            [("transfer", "calculator", None, REQUESTER)],
        ),
        (
            "Mark my words, it will rain. Can you bring me Wren's umbrella?",
            [("transfer", "umbrella", "wren", REQUESTER)],
        ),
    ],
)
def test_a_context_sentence_does_not_spoil_the_request_after_it(
    text: str, wanted: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(text)[0] == wanted


@pytest.mark.parametrize(
    "text", ["I need you to scan my drawing. Bring me a ruler", "I need to pay the bill"]
)
def test_a_service_the_office_lacks_asked_of_the_assistant_is_still_declined(text: str) -> None:
    tasks, _, decline = _read(text)
    assert tasks == [] and decline and "can't" in decline, decline


@pytest.mark.parametrize(
    "text",
    [
        "I might need to borrow Ciaran's ruler later if the client calls, I'll let you know",
        "Can you even carry Hedda's laser measure without dropping it?",
    ],
)
async def test_a_later_need_or_a_doubt_moves_nothing_and_asks_no_owner(text: str) -> None:
    run = await run_instruction(office(), REQUESTER, text)
    assert run.sim.world.holder == SimOffice(office()).world.holder
    owners = {"ciaran", "hedda"}
    assert not [m.text for m in run.sim.messenger.sent if m.chat.id in owners]


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        (
            "would you be able to fetch me Ciaran's ruler?",
            [("transfer", "ruler", "ciaran", REQUESTER)],
        ),
        ("would you be able to brew me a cuppa?", [("produce", "tea", None, REQUESTER)]),
    ],
)
def test_would_you_be_able_to_is_a_polite_request(
    text: str, wanted: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(text)[0] == wanted


def test_are_you_able_to_with_doubt_is_answered_and_offered() -> None:
    tasks, question, _ = _read("are you able to carry a cup of tea without spilling it?")
    assert tasks == [] and question and question.startswith("Yes, I can"), question


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        (
            "if Hedda's not using her laser measure, could you bring it over to me?",
            [("transfer", "laser", "hedda", REQUESTER)],
        ),
        (
            "If Wren isn't using her umbrella, could you borrow it for me?",
            [("transfer", "umbrella", "wren", REQUESTER)],
        ),
    ],
)
def test_a_condition_beside_a_request_in_its_sentence_is_the_requests_own(
    text: str, wanted: list[tuple[str, str | None, str | None, str]]
) -> None:
    """A condition is information only when no request stands beside it: "if X isn't using
    her Y, could you bring it over?" asks for X's Y (X is asked, and her answer is the
    condition); the condition's item is the request's "it"."""
    assert _read(text)[0] == wanted


def test_a_condition_with_a_statement_beside_it_stays_information() -> None:
    tasks, question, decline = _read("if Bill ever needs a ruler, Wren has one")
    assert tasks == [] and question is None, (tasks, question)
    assert decline and decline.startswith("Noted"), decline


@pytest.mark.parametrize(
    "text",
    [
        "don't bother to bring me a ruler, Wren lent me hers",
        "please don't trouble yourself fetching me a calculator",
        "no need to bother bringing me the laser measure",
        "do not worry about copying my report",
    ],
)
def test_a_negation_passed_on_by_bother_or_trouble_moves_nothing(text: str) -> None:
    """A negated verb that only passes the negation on ("don't bother to ...", "don't trouble
    yourself ...") negates the errand after it: nothing is fetched or made."""
    tasks, question, _ = _read(text)
    assert tasks == [] and question is None, (tasks, question)


def test_dont_forget_to_still_asks_for_the_errand() -> None:
    assert _read("don't forget to bring me a ruler")[0] == [("transfer", "ruler", None, REQUESTER)]
