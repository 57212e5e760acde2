"""A word after "my" that opens one of the office's names of several words ("my *test
records*", the work pack's own name) is that name, never a clipped name of another thing
("test" of "testing handbook"): round 231's "courier my test records to ..." was read as the
speaker's maintenance handbook, which the courier does not take, and declined. A clipped
word said alone ("my test", "my batt") is read by ``screen.owned_clipped`` as before."""

from __future__ import annotations

from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.reading import frame_reader


def _depot() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "Signalling depot",
            [
                ob.person("mihai", "Mihai Popescu", "work_pack", "handbook", aliases=["Mihai"]),
                ob.person("jay", "Jay Crane", "work_pack", "test_set", aliases=["Jay"]),
            ],
            rooms=[ob.room("stores_counter", "Stores counter", 20.0, 6.0)],
            item_types=[
                # "test" is read as the test set (the nearest name), and clips "testing" of the
                # handbook, which the speaker owns
                ob.item("test_set", "signal test set", synonyms=["test set", "tc tester"]),
                ob.item(
                    "handbook",
                    "maintenance handbook",
                    synonyms=["testing handbook", "handbook"],
                ),
                ob.item(
                    "work_pack",
                    "work pack",
                    "personal",
                    synonyms=["test records", "paperwork"],
                    signable=True,
                ),
            ],
            operations=[
                ob.operation(
                    "courier",
                    "courier",
                    input="work_pack",
                    sends_out=True,
                    destination_asked=ob.ASKS_NAME_AND_ADDRESS,
                )
            ],
            facilities=[
                ob.facility(
                    "despatch",
                    "despatch bench",
                    at="stores_counter",
                    guards=["jay"],
                    operations=["courier"],
                )
            ],
            home="stores_counter",
        )
    )()


_frame = frame_reader(_depot, "mihai")


def test_the_name_of_several_words_is_read_as_said() -> None:
    frame = _frame("Please courier my test records to Route Asset Records in York.")
    assert [(t.operation, t.item, t.owner) for t in frame.tasks] == [
        ("courier", "work_pack", "mihai")
    ], frame


def test_with_no_place_said_where_is_asked() -> None:
    frame = _frame("can you courier my test records off today")
    assert not frame.tasks and frame.decline is None, frame
    assert frame.question is not None and frame.question.startswith("Where should I courier"), frame


def test_the_handbook_said_as_its_name_is_still_declined() -> None:
    frame = _frame("courier my testing handbook to York")
    assert not frame.tasks and frame.decline is not None and "handbook" in frame.decline, frame
