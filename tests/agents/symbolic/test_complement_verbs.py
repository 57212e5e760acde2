"""An operation verb of several words split by its object (``reading.complement_verbs``): an
office whose operation is asked for by "write to tape" or "back up" reads "write my data file
to tape", "back my file up" and "could you write the file to tape for me" as that operation
on the requester's file, never as the file passed on to someone ("Who should I pass your
file on to?"). The same holds for another office's words ("burn my file to disc") and for
harbour's "seal in plastic" of its laminator ("seal my badge in plastic"), whose head "seal"
alone is still a colleague's seal. In a small office built here, and on harbour."""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.core.task_schema import TaskFrame
from helpers import office_builder as ob
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader


def _raw_media_room() -> dict[str, Any]:
    """A server room with a tape drive (write to tape, back up) and a disc burner."""
    people = (
        ob.person("ines", "Ines Moll", "mug"),
        ob.person("otto", "Otto Brandt", "mug"),
        ob.person("kai", "Kai Lund", "mug"),
    )
    return ob.office_file(
        "media room",
        people,
        rooms=[ob.room("server_room", "Server room", 4.0, 20.0)],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["data file"]),
            ob.item("mug", "mug"),
            ob.item("backup_tape", "backup tape", "product"),
            ob.item("disc", "disc copy", "product"),
        ],
        operations=[
            ob.operation(
                "archive", "write to tape", "back up", input="file", product="backup_tape"
            ),
            ob.operation("burn", "burn to disc", input="file", product="disc"),
        ],
        facilities=[
            ob.facility(
                "tape_drive", "tape drive", at="server_room", guards=["kai"], operations=["archive"]
            ),
            ob.facility(
                "burner", "disc burner", at="server_room", guards=["kai"], operations=["burn"]
            ),
        ],
        everyone_owns=["file"],
        home="server_room",
    )


_media_room = ob.parsed(_raw_media_room)
_media = frame_reader(_media_room, "ines")
_harbour = frame_reader(harbour_office, "pat")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("write my data file to tape", "archive"),
        ("back my file up", "archive"),
        ("could you write the file to tape for me", "archive"),
        ("pls write my file to tape", "archive"),
        ("burn my data file to disc please", "burn"),
        ("can you burn the file to disc for me", "burn"),
    ],
)
def test_the_split_phrase_is_the_operation_on_the_speakers_file(text: str, operation: str) -> None:
    frame = _media(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [("print", "file", "ines", "ines")]
    assert frame.tasks[0].operation == operation


def test_a_head_verb_said_with_another_object_is_no_operation() -> None:
    """Neighbours: "write a note to Otto" names no declared phrase (nothing to tape), and
    "send my file to Otto" passes the file on as before."""
    assert all(t.kind != "print" for t in _media("write a note to Otto").tasks)
    assert _tasks(_media("send my file to Otto")) == [("send_file", "file", "ines", "otto")]


@pytest.mark.parametrize("text", ["seal my badge in plastic", "seal in plastic my badge"])
def test_harbour_seal_in_plastic_is_its_laminator(text: str) -> None:
    frame = _harbour(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("heat", "badge", "pat")]


def test_harbour_a_seal_alone_is_still_a_colleagues() -> None:
    """Neighbour: "can Mark seal my document" (no complement) is Mark's seal, as before."""
    frame = _harbour("can Mark seal my document")
    assert [(t.kind, t.actor) for t in frame.tasks] == [("seal", "mark")]


async def test_the_tape_drive_does_the_work_in_the_simulated_office() -> None:
    run = await run_instruction(_media_room(), "ines", "write my data file to tape")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert "tape" in run.stm.trace.summary.lower(), run.stm.trace.summary
