"""What round 275 (an optician's glazing lab, written blind) showed once read, each by its
mechanism:

- a purpose's describing word before a service's word ("for the big print run") is part of the
  event's noun, no print asked;
- a need said with a service's gerund ("needs some paper for printing") is never praise;
- a form picked in a sentence of its own ("Jie's report? the pdf one") picks the file;
- chat shorthand ("mine hav gone walkabout") is written out before the screen reads it."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.chat_shorthand import spelled_shorthand
from assistantx.agents.symbolic.reading.purpose_modifier import without_purpose_modifier
from assistantx.core.office import load_office
from helpers import office_builder as ob
from helpers.reading import frame_reader

_mao = frame_reader(load_office, "mao")
_zheng = frame_reader(load_office, "zheng")

_LAB = ob.parsed(
    lambda: ob.office_file(
        "Lab",
        [
            ob.person("amy", "Amy Cole", aliases=["Amy"]),
            ob.person("sam", "Sam King", "pliers", aliases=["Sam"]),
            ob.person("cn", "Cn Li", aliases=["Cn"]),
        ],
        rooms=[ob.room("lab", "Lab", 30.0, 6.0)],
        item_types=[ob.item("pliers", "adjusting pliers", synonyms=["pliers", "pad pliers"])],
        operations=[],
        facilities=[],
        home="lab",
    )
)
_amy = frame_reader(_LAB, "amy")


def _tasks(frame: object) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    "text",
    [
        "Gao Min needs some printer paper for the big print run, can you take her some",
        "Gao Min needs printer paper for a massive print run, could you bring her some",
        "Gao needs paper for the weekly print job, take her some please",
    ],
)
def test_a_described_print_run_is_what_the_paper_is_for(text: str) -> None:
    frame = _mao(text)
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == [("transfer", "paper", None, "gao")], frame


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        # must not change: the print itself asked, a describing word on the file
        ("print my big file", "print"),
        ("can you do a quick print of my file", "print"),
        ("for the big meeting print my file", "print"),
    ],
)
def test_a_print_asked_stays_a_print(text: str, kind: str) -> None:
    frame = _mao(text)
    assert frame.question is None and frame.decline is None, frame
    assert [t.kind for t in frame.tasks] == [kind], frame


def test_a_need_with_a_service_gerund_is_no_praise() -> None:
    frame = _mao("Gao Min needs some printer paper for printing")
    assert frame.decline != "You're welcome! I did nothing.", frame
    assert not any(t.kind == "print" for t in frame.tasks) or frame.question is not None, frame
    # must not change: praise for a doing is thanks
    assert _mao("you're a star for fetching the clipboard").decline == (
        "You're welcome! I did nothing."
    )


@pytest.mark.parametrize(
    "text",
    [
        "can you get me Jie's report? the pdf one",
        "can you get me Jie's report. the pdf one please",
        "can you get me Jie's report, the pdf one",  # must not change
    ],
)
def test_a_form_picked_in_its_own_sentence_picks_the_file(text: str) -> None:
    frame = _zheng(text)
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == [("send_file", "file", "chen", "zheng")], frame


def test_a_sentence_that_goes_on_past_the_form_picks_nothing() -> None:
    frame = _zheng("print my report. the pdf one is on the drive")
    assert [(t.kind, t.owner) for t in frame.tasks] == [("print", "zheng")], frame
    assert _zheng("can you get me Jie's report! the paper one").tasks[0].item == "document"


def test_shorthand_is_written_out_before_the_screen() -> None:
    frame = _amy("hey can u grab me some pad pliers, mine hav gone walkabout again")
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == [("transfer", "pliers", None, "amy")], frame


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("mine hav gone walkabout", "mine have gone walkabout"),
        ("Wud u bring me a pen frm Olive", "Would u bring me a pen from Olive"),
        ("ask Cn for the pliers", "ask Cn for the pliers"),  # a colleague's name
        ("the havoc frmwork", "the havoc frmwork"),  # inside other words
    ],
)
def test_the_shorthand_rewrite(text: str, read: str) -> None:
    assert spelled_shorthand(text, {"cn"}) == read


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("for the big signature check", "for the big check"),
        ("for a massive print run tomorrow", "for a massive run tomorrow"),
        ("for the big print", "for the big print"),  # the service named
        ("for the new print room", "for the new print room"),  # the office's room
        ("for the team print run", "for the team print run"),  # no describing word
    ],
)
def test_the_described_purpose_rewrite(text: str, read: str) -> None:
    words = {"signature", "sign", "print"}
    assert without_purpose_modifier(text, words, {"print room"}) == read


_SITE = ob.parsed(
    lambda: ob.office_file(
        "Site office",
        [ob.person("dan", "Dan Osei", aliases=["Dan"])],
        rooms=[ob.room("office", "Office", 30.0, 6.0)],
        item_types=[
            ob.item("pegs", "survey pegs", synonyms=["pegs"], purposes=["peg out boundaries"])
        ],
        operations=[],
        facilities=[],
        home="office",
    )
)
_dan = frame_reader(_SITE, "dan")


@pytest.mark.parametrize(
    "text",
    [
        # "tmrw" is written out, so the need is for tomorrow; the request beside it is now
        "need something to peg out the boundary with tmrw, can you bring me some",
        "need something to peg out the boundary with, can you bring me some",
    ],
)
def test_a_described_need_gives_its_thing_to_the_request_beside_it(text: str) -> None:
    frame = _dan(text)
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == [("transfer", "pegs", None, "dan")], frame


def test_a_later_need_alone_is_still_noted() -> None:
    frame = _dan("need something to peg out the boundary with tomorrow")
    assert frame.tasks == [] and frame.decline is not None, frame
    assert frame.decline.startswith("Noted."), frame


_GLAZING = ob.parsed(
    lambda: ob.office_file(
        "Glazing lab",
        [ob.person("priya", "Priya Sandhu", aliases=["Priya"])],
        rooms=[ob.room("tint_room", "Tint room", 30.0, 6.0)],
        item_types=[ob.item("job_tray", "job tray", synonyms=["tray"])],
        operations=[ob.operation("tint", "tint", "dye", input="job_tray")],
        facilities=[
            ob.facility("tint_bath", "tint bath", at="tint_room", guards=[], operations=["tint"])
        ],
        home="tint_room",
        everyone_owns=["job_tray"],
    )
)
_priya = frame_reader(_GLAZING, "priya")


@pytest.mark.parametrize(
    "text",
    [
        "The lenses in my job tray need tinting, grey 50 percent.",
        "my job tray needs tinting",  # must not change
    ],
)
def test_a_thing_the_work_takes_said_needing_it_is_asked(text: str) -> None:
    frame = _priya(text)
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == [("heat", "job_tray", "priya", "priya")], frame


def test_an_unknown_thing_needing_the_offices_work_is_offered_not_noted() -> None:
    frame = _priya("my lenses need tinting")
    assert frame.question == "Shall I tint your job tray for you?", frame
