"""Round 175's reader classes, by mechanism, on sentences of our own against the default
office, harbour (whose colleagues have word names: Grace, Mark, Rose, May, Will) and harbour
with a stapler May and Rose own (the dataset's harbour has none):

- a word name written in lower case as the subject of a negated auxiliary ("grace hasn't
  approved ...") is the colleague, and a later "her"/"him" refers to them;
- "the <file> from me" is the speaker's, sent to the one who needs it;
- "<person> has to sign (off) my <paper>. could you take it to her and bring it back?" is
  that person's signing, the paper back to the speaker;
- "for the <noun> <task word>-ing at <time>" names an occasion, never work asked; an
  adjective before a titled colleague's thing keeps the thing theirs.
"""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import Office, load_office, parse_office
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import HARBOUR_FILE, harbour_office
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml


def _harbour_with_staplers() -> Office:
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    raw["item_types"].append({"id": "stapler", "name": "stapler", "purposes": ["staple"]})
    for p in raw["people"]:
        if p["id"] in ("may", "rose"):
            p["owns"].append({"type": "stapler", "known": True})
    return parse_office(raw, "harbour with staplers")


_default = frame_reader(load_office, "lee")
_harbour = frame_reader(harbour_office, "will")
_stapled = frame_reader(_harbour_with_staplers, "will")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks]


# class 1: a lower-case word name, the subject of a negated auxiliary, is the colleague
@pytest.mark.parametrize(
    ("text", "actor"),
    [
        (
            "grace hasnt approved my leave form yet. can you get her to sign it and bring it back",
            "grace",
        ),
        ("mark hasn't signed my contract. can you take it to him", "mark"),
        (
            "rose hasn't signed my timesheet yet, could you take it to her and bring it back?",
            "rose",
        ),
    ],
)
def test_a_lower_case_word_name_before_a_negated_verb_is_the_colleague(
    text: str, actor: str
) -> None:
    frame = _harbour(text)
    assert _tasks(frame) == [("sign", "document", "will", "will", actor)], frame


@pytest.mark.parametrize(
    "text",
    ["by the grace of god, please bring me a tea", "may I have a tea please"],
)
def test_a_word_name_used_as_the_word_stays_the_word(text: str) -> None:
    frame = _harbour(text)
    assert _tasks(frame) == [("produce", "tea", None, "will", None)], frame


# class 2: "the <file> from me" is the speaker's
@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("Wang needs the slides from me for the newsletter. Can you send them to her?", "wang"),
        ("Wang needs the spreadsheet from me. Can you send it to her?", "wang"),
        ("Wang needs the spreadsheet from me. Can you send it to Chen?", "chen"),
    ],
)
def test_the_file_from_me_is_the_speakers(text: str, recipient: str) -> None:
    frame = _default(text, "zhang")
    assert _tasks(frame) == [("send_file", "file", "zhang", recipient, None)], frame


def test_another_colleagues_file_said_as_theirs_stays_theirs() -> None:
    frame = _default("Wang finished her slides, print it", "zhang")
    assert _tasks(frame) == [("print", "file", "wang", "zhang", None)], frame


# class 3: an obligation to sign, then the paper taken to the signer and back
@pytest.mark.parametrize(
    "text",
    [
        "Rose has to sign my timesheet. could you take it to her and bring it back?",
        "Rose has to sign off my form. Could you take it to her and bring it back?",
        "Rose has to sign off on my paperwork. Can you take it over to her and bring it back "
        "to me?",
        "rose has to sign off on my timesheet. could you take it to her and bring it back?",
    ],
)
def test_taken_to_the_one_obliged_to_sign_and_back_is_their_signing(text: str) -> None:
    frame = _harbour(text)
    assert _tasks(frame) == [("sign", "document", "will", "will", "rose")], frame


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        # no way back: the paper handed to her, as before
        ("Rose has to sign my timesheet. could you take it to her?", "rose"),
        # someone else named: a hand-over to them, the obligation context
        ("Rose has to sign my timesheet. could you take it to Mark and bring it back?", "mark"),
    ],
)
def test_a_trip_without_the_way_back_or_to_another_stays_a_hand_over(
    text: str, recipient: str
) -> None:
    frame = _harbour(text)
    assert _tasks(frame) == [("transfer", "document", "will", recipient, None)], frame


# class 4: an occasion named by a task word's -ing form, an adjective before the thing
@pytest.mark.parametrize(
    "text",
    [
        "Would it be possible to borrow Ms Okafor's good stapler for the contract signing at 3?",
        "can I borrow Ms Okafor's nice stapler for the signing",
        "can I borrow May's stapler for the contract printing",
    ],
)
def test_an_occasion_named_by_a_task_word_is_why_not_work(text: str) -> None:
    frame = _stapled(text)
    assert _tasks(frame) == [("transfer", "stapler", "may", "will", None)], frame


def test_an_occasion_in_the_default_office() -> None:
    frame = _default(
        "Would it be possible to borrow Ms Wang's good stapler for the contract signing at 3?"
    )
    assert _tasks(frame) == [("transfer", "stapler", "wang", "lee", None)], frame


@pytest.mark.parametrize(
    ("text", "task"),
    [
        # the work asked on the speaker's thing, the occasion only why
        ("print my report for the contract signing", ("print", "file", "lee", "lee", None)),
        # "for signing" with no determiner: the work asked of the colleague
        ("take my contract to Wang for signing", ("sign", "document", "lee", "lee", "wang")),
    ],
)
def test_work_asked_beside_or_without_an_occasion_is_read_as_before(
    text: str, task: tuple[str, str, str, str, str | None]
) -> None:
    frame = _default(text)
    assert _tasks(frame) == [task], frame


def test_a_thing_the_office_lacks_before_an_occasion_is_not_its_paper() -> None:
    """Harbour has no stapler: the contract of the occasion is never the thing borrowed (it
    asked "Who should sign your document?"), and the dummy "it" of "would it be
    possible" points at nothing."""
    frame = _harbour(
        "Would it be possible to borrow Ms Okafor's good stapler for the contract signing at 3?"
    )
    assert frame.tasks == [] and frame.question is not None, frame
    assert "document" not in frame.question, frame
