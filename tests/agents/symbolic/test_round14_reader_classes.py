"""Blind round 14's reader classes, by mechanism, on sentences of our own against a small
youth hostel's back office no sentence was written for (``helpers.hostel``): a post room
that keeps a parcel for anyone and sends parcels out by courier, a kitchen that keeps a
kettle and makes tea, people's step stools, ladders, book carts, storybooks and project
folders (the round's own office and sentences were never read)."""

from __future__ import annotations

import functools
import unicodedata

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from assistantx.core.task_schema import TaskFrame
from helpers.hostel import hostel, raw_hostel
from helpers.reading import frame_reader

Row = tuple[str, str | None, str | None, str | None]


_frame = frame_reader(hostel, "hamid")


def _tasks(frame: TaskFrame) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


# -- 4. "<Name>'s trying ..., take her a stool": the name written with decomposed accents -----


def _decomposed(text: str) -> str:
    return unicodedata.normalize("NFD", text)


@pytest.mark.parametrize(
    ("text", "to"),
    [
        ("Siân's trying to reach the top shelf, can you take her a step stool?", "sian"),
        (
            _decomposed("Siân's trying to reach the top shelf, can you take her a step stool?"),
            "sian",
        ),
        (_decomposed("Siân’s up on a chair, could you bring her a step stool"), "sian"),
        (_decomposed("Trần Bảo Châu's trying to reach the shelf, take her a ladder pls"), "chau"),
        ("Mei's been trying to reach the top shelf, can you take her a step stool?", "mei"),
        ("Dara's carrying the boxes upstairs, can you take him the book cart", "dara"),
    ],
)
def test_the_one_person_named_before_is_whom_the_pronoun_means(text: str, to: str) -> None:
    """A letter and its combining accent (text pasted in the decomposed form) are one word, so
    "Sia\u0302n's" is Siân's, not "Sia" and "n's"; the one person named is "her"."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", to)]


@pytest.mark.parametrize(
    "text",
    [
        _decomposed("Siân and Mei are trying to reach the shelf, can you take her a step stool?"),
        "Mei and Oona are trying to reach the shelf, can you take her a step stool?",
    ],
)
def test_two_people_named_before_the_pronoun_still_ask(text: str) -> None:
    frame = _frame(text)
    assert not frame.tasks and frame.question is not None


async def test_a_decomposed_name_is_handed_the_stool_with_no_refusal() -> None:
    text = _decomposed("Siân's trying to reach the top shelf, can you take her a step stool?")
    run = await run_instruction(hostel(), "hamid", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert not [r for r in run.stm.trace.actions() if r.refused]
    stools = {item: who for item, who in run.sim.world.holder.items() if "step_stool" in item}
    assert "sian" in stools.values(), stools


# -- 7. the same item named again in a sentence of its own is one item ------------------------


@pytest.mark.parametrize(
    "text",
    [
        "bring me Mei's step stool. the step stool, not the ladder",
        "bring me Mei's step stool. the step stool please",
        "bring me Mei's step stool! the step stool, not the ladder",
        "could you bring me Mei's step stool? the step stool I mean",
    ],
)
def test_the_item_said_again_is_one_fetch(text: str) -> None:
    assert _tasks(_frame(text)) == [("transfer", "step_stool", "mei", "hamid")]


@pytest.mark.parametrize(
    ("text", "items"),
    [
        ("bring me Mei's step stool. the ladder too", ["step_stool", "ladder"]),
        ("bring me Mei's step stool. and Bea's ladder", ["step_stool", "ladder"]),
        ("bring me Mei's step stool. take Dara the step stool too", ["step_stool", "step_stool"]),
    ],
)
def test_another_item_or_another_recipient_is_still_its_own_task(
    text: str, items: list[str]
) -> None:
    """Near-miss: a second sentence with another item, or the same kind for someone else, is
    a second errand as before."""
    assert [t.item for t in _frame(text).tasks] == items


async def test_the_item_said_again_is_handed_over_once() -> None:
    run = await run_instruction(
        hostel(), "hamid", "bring me Mei's step stool. the step stool, not the ladder"
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.holder["step_stool:mei"] == "hamid"
    assert run.sim.world.holder.get("step_stool:sian") != "hamid"
    assert run.sim.world.holder.get("ladder:bea") != "hamid"


# -- 5. a plural kind of thing after the request says why, it asks for no item ----------------


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("can u fetch Dara's book trolley? storytime books need moving", "book_cart", "dara"),
        ("could you bring Dara's book cart? storybooks need shelving", "book_cart", "dara"),
        ("can you get Bea's ladder? the folders need to go up high", "ladder", "bea"),
        ("bring me Dara's book cart, the books are heavy", "book_cart", "dara"),
        ("grab Mei's step stool pls. folders keep falling off the top shelf", "step_stool", "mei"),
    ],
)
def test_a_generic_plural_after_the_request_is_its_reason(text: str, item: str, owner: str) -> None:
    assert _tasks(_frame(text)) == [("transfer", item, owner, "hamid")]


@pytest.mark.parametrize(
    ("text", "items"),
    [
        ("can you get Bea's ladder? also folders please", ["ladder", "folder"]),
        ("can you get Bea's ladder? folders, too", ["ladder", "folder"]),
        ("can u fetch Dara's book trolley? and bring me folders", ["book_cart", "folder"]),
        ("get Bea's ladder and folders", ["ladder", "folder"]),
    ],
)
def test_a_plural_asked_for_is_still_fetched(text: str, items: list[str]) -> None:
    """Near-miss: a list of things ("folders please", "and bring me folders") is a request."""
    assert [t.item for t in _frame(text).tasks] == items


@pytest.mark.parametrize(
    "text",
    [
        "can you get Bea's ladder? the storybook needs moving",  # one thing: whose?
        "can you get Bea's ladder? my folders need to go up",  # mine: where to?
    ],
)
def test_a_singular_or_owned_thing_after_the_request_is_still_asked_about(text: str) -> None:
    frame = _frame(text)
    assert not frame.tasks and frame.question is not None


async def test_only_the_cart_moves_for_the_reason() -> None:
    run = await run_instruction(
        hostel(), "hamid", "can u fetch Dara's book trolley? storytime books need moving"
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.holder["book_cart:dara"] == "hamid"
    assert not [i for i, who in run.sim.world.holder.items() if "storybook" in i and who == "hamid"]


# -- 6. a trailing aside after a complete request -------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "need the step stool from Mei's desk, reserve shelf again 🙄",
        "need Mei's step stool, reserve shelf again ugh",
        "need Mei's step stool. reserve shelf again 🙄",
        "need Mei's step stool - laundry shelf again lol",
        "need the step stool from Mei's desk, reserve shelf is full again 🙄",
        "need Mei's step stool, print room is busy again",
    ],
)
def test_an_aside_after_the_request_leaves_the_request_done(text: str) -> None:
    """ "shelf" is a word of the laundry shelf's name, but alone it names no place of the
    office: "reserve shelf" is a compound said in passing, not a request for a service."""
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame.decline or frame.question
    assert _tasks(frame) == [("transfer", "step_stool", "mei", "hamid")]


@pytest.mark.parametrize(
    ("text", "operations"),
    [
        ("print my file and laminate my notice", ["print", "laminate"]),
        ("laminate my notice, then shred it", ["laminate", "shred"]),
        ("print my file, then laminate my notice again", ["print", "laminate"]),
    ],
)
def test_two_real_services_stay_two(text: str, operations: list[str]) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [t.operation or t.kind for t in frame.tasks] == operations


@pytest.mark.parametrize(
    "text",
    [
        "need Mei's step stool, reserve the shelf again 🙄",
        "bring me a ladder, reserve a room for me",
    ],
)
def test_a_service_the_office_lacks_asked_with_an_object_is_still_declined(text: str) -> None:
    """Near-miss: "reserve the shelf", "reserve a room" ask for a service (its object after a
    determiner); the office has none, so it says so rather than doing part."""
    frame = _frame(text)
    assert frame.decline is not None and not frame.tasks


# -- 3. words that describe an owned item stand between the possessive and the item ----------


@pytest.mark.parametrize(
    ("text", "row"),
    [
        ("bring me Bea's big blue project folder", ("transfer", "folder", "bea", "hamid")),
        ("could you get me Mei's old blue step stool", ("transfer", "step_stool", "mei", "hamid")),
        ("get Ms Quinn's laundry rota file for me", ("send_file", "rota", "quinn", "hamid")),
        ("get Quinn's budget rota file for me", ("send_file", "rota", "quinn", "hamid")),
        ("send me Ms Ashby's weekly laundry file", ("send_file", "rota", "quinn", "hamid")),
    ],
)
def test_the_description_between_possessive_and_item_keeps_the_owner(text: str, row: Row) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert _tasks(frame) == [row]


def test_the_description_holds_in_the_second_task_of_a_sentence() -> None:
    frame = _frame("send my budget spreadsheet to Mei and get Ms Quinn's laundry rota file for me")
    assert frame.question is None, frame.question
    assert _tasks(frame) == [
        ("send_file", "rota", "hamid", "mei"),
        ("send_file", "rota", "quinn", "hamid"),
    ]


@pytest.mark.parametrize(
    "text",
    [
        "bring me Bea's ladder and the blue project folder",
        "bring me Bea's ladder and a big blue project folder",
        "bring me Bea's ladder, also a blue project folder",
    ],
)
def test_an_article_or_a_join_starts_a_phrase_the_possessive_does_not_own(text: str) -> None:
    """Near-miss: "the/a ... folder" after "and" is a phrase of its own, not Bea's."""
    owners = {t.item: t.owner for t in _frame(text).tasks}
    assert owners.get("ladder") == "bea" and owners.get("folder") != "bea"


async def test_the_described_folder_is_asked_of_its_owner() -> None:
    run = await run_instruction(hostel(), "hamid", "bring me Bea's big blue project folder")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.holder["folder:bea"] == "hamid"


# -- 1. "the <item> in/at/from <place>" is the one kept there ---------------------------------


@functools.cache
def _two_of_each() -> InstructionParser:
    """The hostel where the laundry shelf also keeps a kettle for anyone, and Bea has a bike
    pump of her own on her desk: the office's default kettle is the kitchen's, its default
    pump Yusuf's in the post room."""
    raw = raw_hostel()
    for f in raw["facilities"]:
        if f["id"] == "laundry_shelf":
            f["supplies"] = [*f["supplies"], {"type": "kettle"}]
    for p in raw["people"]:
        if p["id"] == "bea":
            p["owns"] = [*p["owns"], {"type": "pump"}]
    return InstructionParser(parse_office(raw, "hostel-two-of-each"))


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("grab the kettle in the laundry", "laundry_shelf"),
        ("bring me the kettle from the laundry shelf", "laundry_shelf"),
        ("bring me the bike pump on desk 2", "bea"),  # the one on a desk: whoever sits there
        # the one the office would take anyway is left to the planner (owner None), as before
        ("grab the kettle in the kitchen", None),
        ("bring me the bike pump in the post room", None),  # Yusuf's, kept there
    ],
)
def test_the_place_phrase_names_the_item_kept_there(text: str, owner: str | None) -> None:
    frame = _two_of_each().parse(text, "hamid")
    assert frame.question is None, frame.question
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("transfer", owner, "hamid")]


@pytest.mark.parametrize(
    "text",
    [
        "bring me the ladder in the kitchen",
        "grab the kettle in the laundry",
        "leave the ladder in the kitchen",
        "bring me the step stool in the post room",
    ],
)
def test_nothing_of_the_kind_kept_there_is_asked_about(text: str) -> None:
    """Never another one from elsewhere: none of the kind is kept where the requester said."""
    frame = _frame(text)
    assert not frame.tasks and frame.question is not None
    assert frame.question.startswith("I don't know of a")


def _crowded_laundry() -> InstructionParser:
    """The hostel where Bea and Yusuf both keep their ladders on the laundry shelf."""
    raw = raw_hostel()
    for p in raw["people"]:
        if p["id"] in ("bea", "yusuf"):
            p["owns"] = [
                {"type": "ladder", "at": "laundry", "facility": "laundry_shelf"}
                if o["type"] == "ladder"
                else o
                for o in p["owns"]
                if o["type"] != "pump"
            ]
    return InstructionParser(parse_office(raw, "hostel-crowded"))


def test_several_kept_there_are_asked_which() -> None:
    frame = _crowded_laundry().parse("bring me the ladder in the laundry", "hamid")
    assert not frame.tasks and frame.question is not None
    assert "Bea Lindqvist's or Yusuf Demir's" in frame.question


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("bring me Bea's ladder", "bea"),  # a possessive, no place phrase: as before
        ("bring me a ladder", None),  # anyone's: the planner chooses, as before
    ],
)
def test_without_a_place_phrase_the_owner_is_read_as_before(text: str, owner: str | None) -> None:
    assert [t.owner for t in _frame(text).tasks] == [owner]


@pytest.mark.parametrize("text", ["bring me a ladder from the kitchen", "get me some kettle"])
def test_an_indefinite_thing_from_a_place_is_any_one_as_before(text: str) -> None:
    """Near-miss: "a ladder from the kitchen" asks for any one; none kept there is no
    reason to ask (the planner finds one, as before)."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [t.owner for t in frame.tasks] == [None]


async def test_the_kettle_kept_in_the_laundry_comes_from_its_keeper() -> None:
    parser = _two_of_each()
    run = await run_instruction(parser.office, "hamid", "grab the kettle in the laundry")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.holder["kettle:laundry_shelf"] == "hamid"
    assert run.sim.world.holder["kettle:kitchen_counter"] != "hamid"


# -- 2. a statement says where the item goes, then a send-out on "it" -------------------------


@pytest.mark.parametrize(
    ("text", "where"),
    [
        (
            "the parcel in the post room needs to go out to the Dublin office, can you courier it",
            "the Dublin office",
        ),
        (
            "the parcel in the post room has to go off to Galway Hostel, can you post it",
            "Galway Hostel",
        ),
        ("the parcel has to go off to Galway Hostel. Courier it please", "Galway Hostel"),
        (
            "the parcel should go over to 12 Shore Road, Cork, can you courier it",
            "12 Shore Road, Cork",
        ),
    ],
)
def test_the_statement_says_where_the_parcel_kept_there_goes(text: str, where: str) -> None:
    """ "post" is a verb of the courier service, but "the post room" names a place; "has to"
    and "should" state where it goes as "needs to" does, and the parcel is the one the post
    desk keeps for anyone (the requester has none of their own)."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [(t.item, t.owner, t.operation, t.destination) for t in frame.tasks] == [
        ("parcel", "post_desk", "courier", where)
    ]


@pytest.mark.parametrize(
    "text",
    [
        "I have to go over to Galway, can you courier the parcel",  # the person goes
        "the parcel has to go off to Galway Hostel, bring it to me",  # no send-out verb
        "the parcel is back in the post room",  # where it is: words only
    ],
)
def test_a_person_going_or_no_send_out_is_no_destination(text: str) -> None:
    assert not [t for t in _frame(text).tasks if t.destination is not None]


async def test_the_parcel_kept_in_the_post_room_is_couriered_where_the_statement_said() -> None:
    text = "the parcel in the post room needs to go out to the Dublin office, can you courier it"
    run = await run_instruction(hostel(), "hamid", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    [sent] = run.sim.world.sent_out()
    assert sent.detail["item"] == "parcel:post_desk"
    assert "to the Dublin office" in sent.detail["told"]
