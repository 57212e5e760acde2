"""An adverb between a named subject and its verb (class 79a-1): "Rose really needs an
umbrella" asked "Shall I bring Rose Adeyemi's umbrella to you?" (the wrong way round), "Wang
also wants a coffee" made one for the speaker, "Zhang definitely has to sign my contract"
was a statement. The adverb (lemminflect's: a word known only as an adverb) is read away
between the name and its finite verb or modal, so each reads as it does without it."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.subject_adverbs import is_plain_adverb
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, frame_reader

_READERS = {
    default_office: frame_reader(default_office, "mao"),
    harbour_office: frame_reader(harbour_office, "will"),
}


def _read(office: OfficeOf, text: str) -> tuple[str | None, list[tuple[str, str, str | None]]]:
    frame = _READERS[office](text)
    return frame.question, [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("office", "text", "plain", "question"),
    [
        (
            harbour_office,
            "Rose really needs an umbrella",
            "Rose needs an umbrella",
            "Shall I bring an umbrella to Rose Adeyemi?",
        ),
        (
            harbour_office,
            "Hope urgently needs a calculator",
            "Hope needs a calculator",
            "Shall I bring a calculator to Hope Mensah?",
        ),
        (
            default_office,
            "Wang badly needs a stapler",
            "Wang needs a stapler",
            "Shall I bring a stapler to Wang Fang?",
        ),
        (
            default_office,
            "Wang also wants a coffee",
            "Wang wants a coffee",
            "Shall I get coffee for Wang Fang?",
        ),
        # variants with other words and names (one of them also a modal: May)
        (
            harbour_office,
            "Grace desperately needs a highlighter",
            "Grace needs a highlighter",
            "Shall I bring a highlighter to Grace Huang?",
        ),
        (
            harbour_office,
            "May really needs a ruler",
            "May needs a ruler",
            "Shall I bring a ruler to May Okafor?",
        ),
        (
            harbour_office,
            "Mark probably wants a tea",
            "Mark wants a tea",
            "Shall I get tea for Mark Lindqvist?",
        ),
        (
            default_office,
            "Lee seriously needs a coffee",
            "Lee needs a coffee",
            "Shall I get coffee for Lee Ming?",
        ),
    ],
)
def test_a_need_with_an_adverb_is_the_named_persons(
    office: OfficeOf, text: str, plain: str, question: str
) -> None:
    assert _read(office, text) == (question, [])
    assert _read(office, plain) == (question, [])


@pytest.mark.parametrize(
    ("text", "plain"),
    [
        ("Zhang definitely has to sign my contract", "Zhang has to sign my contract"),
        ("Chen absolutely has to sign my contract", "Chen has to sign my contract"),
        ("Zhang really must sign my contract", "Zhang must sign my contract"),
    ],
)
def test_an_obligation_with_an_adverb_is_the_named_persons_work(text: str, plain: str) -> None:
    signer = plain.split()[0].lower()
    assert _read(default_office, text) == _read(default_office, plain)
    frame = _READERS[default_office](text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("sign", "document", "mao")]
    assert frame.tasks[0].actor == signer


@pytest.mark.parametrize(
    ("office", "text", "task"),
    [
        (
            harbour_office,
            "Rose really needs an umbrella, can you bring her one",
            ("transfer", "umbrella", "rose"),
        ),
        (
            default_office,
            "Chen really needs a coffee, can you make her one",
            ("produce", "coffee", "chen"),
        ),
    ],
)
def test_a_need_with_an_adverb_then_asked_gets_the_person_another(
    office: OfficeOf, text: str, task: tuple[str, str, str]
) -> None:
    """ "... can you bring her one": another one for her, not her own taken from her."""
    frame = _READERS[office](text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [task]
    assert frame.tasks[0].owner != task[2]


def test_the_speakers_own_need_with_an_adverb_is_unchanged() -> None:
    assert _read(default_office, "I really need a stapler") == (
        None,
        [("transfer", "stapler", "mao")],
    )


def test_a_word_that_is_also_a_verb_stays() -> None:
    """ "Wang still has my stapler": said of where it is; "still" is also a verb, kept."""
    frame = _READERS[default_office]("Wang still has my stapler")
    assert frame.tasks == [] and frame.question is None and frame.decline is not None


def test_an_adverb_with_no_verb_after_the_name_stays() -> None:
    """ "bring Rose now": Rose is no subject; nothing is read away."""
    assert _read(harbour_office, "bring Rose an umbrella now") == (
        None,
        [("transfer", "umbrella", "rose")],
    )
    question, tasks = _read(harbour_office, "bring Rose now")
    assert tasks == [] and question is not None


@pytest.mark.parametrize(
    ("word", "plain"),
    [
        ("really", True),
        ("urgently", True),
        ("also", True),
        ("just", True),
        ("still", False),  # also a verb
        ("to", False),  # a preposition ("from Pat to May")
        ("back", False),  # also a noun and a verb
        ("now", False),  # also a noun
        ("never", False),  # denies the verb
        ("hardly", False),
        ("hope", False),
        ("may", False),
        ("will", False),
    ],
)
def test_which_words_are_plain_adverbs(word: str, plain: bool) -> None:
    assert is_plain_adverb(word) is plain
