"""A pronoun whose antecedent is the one colleague a question or statement before it names, in
lower case, where the given name is also an English word ("is tam in today? if she doesn't mind
i'd borrow her stapler": blind round 59's class, analogue). The name word after the "is"/"was"
that opens a question of whether someone is here ("is tam in", "was wren around") is the
person; so is a name word in "if wren doesn't mind" (whose leave it is). The one person named
is whom "he/she/his/her" means, whatever the pronoun's gender (gender is never read from
names): the owner is asked, the speaker receives. Two people named before the pronoun still
ask whom it means; a name word where the word fits ("is grace period over") stays the word."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.name_reading import NameSlot, read_name
from helpers.events_desk import events_desk
from helpers.reading import frame_reader

_frame = frame_reader(events_desk, "ines")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("is tam in today? if she doesn't mind i'd borrow her stapler", "stapler", "tam"),
        ("is tam around? if he doesnt mind i'd borrow his stapler for a bit", "stapler", "tam"),
        ("is tam in? i'd like to borrow their tape measure", "tape_measure", "tam"),
        (
            "was wren in earlier? i'd borrow her tape measure if she's ok with it",
            "tape_measure",
            "wren",
        ),
        ("is wren free? could i borrow her tape measure", "tape_measure", "wren"),
        ("is drew about? i need his stapler for the afternoon", "stapler", "drew"),
        # a statement before it
        ("tam is in today. i'd borrow his stapler if he doesn't mind", "stapler", "tam"),
        # the person whose leave the condition names
        ("is tam in? if wren doesn't mind i'd borrow her tape measure", "tape_measure", "wren"),
    ],
)
def test_the_one_person_named_before_is_whom_the_pronoun_means(
    text: str, item: str, owner: str
) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, "ines")
    ], frame


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("are tam and wren in? if she doesn't mind i'd borrow her tape measure", "her"),
        ("are Tam and Wren in? I'd borrow her tape measure", "her"),
        ("tam and wren are in today. i'd like to borrow his tape measure", "his"),
    ],
)
def test_two_people_named_before_the_pronoun_still_ask_whom_it_means(text: str, said: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
    assert frame.question == f"Who do you mean by {said!r}? Please tell me their name.", frame


@pytest.mark.parametrize(
    ("prev", "word", "nxt", "after", "reading"),
    [
        ("is", "tam", "in", "today", "person"),
        ("was", "wren", "around", "", "person"),
        ("is", "grace", "period", "over", "word"),  # a noun after it: the word
        ("is", "penny", "enough", "", "word"),  # no word of being here
        ("if", "wren", "doesnt", "mind", "person"),
        ("if", "bill", "is", "due", "word"),  # a condition on no one's leave
        ("are", "tam", "and", "wren", "person"),
        ("are", "pens", "and", "paper", "word"),  # no name joined to it
    ],
)
def test_the_name_word_in_a_question_of_whether_someone_is_here(
    prev: str, word: str, nxt: str, after: str, reading: str
) -> None:
    slot = NameSlot(
        word=word,
        written=word,
        prev=prev,
        prev_opens=True,
        next=nxt,
        after_next=after,
        after_next_is_name=after == "wren",
    )
    assert read_name(slot) == reading


async def test_end_to_end_the_owner_is_asked_and_the_speaker_receives() -> None:
    text = "is tam in today? if she doesn't mind i'd borrow her stapler"
    run = await run_instruction(events_desk(), "ines", text)
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    asked = [getattr(r.action, "contact", None) for r in trace.actions()]
    assert "tam" in asked, trace.summary
    handed = [(e.detail["item"], e.detail["to"]) for e in run.sim.world.handovers()]
    assert ("stapler:tam", "ines") in handed, trace.summary
