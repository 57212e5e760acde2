"""The speaker's own thing said as the subject of what it does or suffers ("my drill's eating
batteries", "my stapler keeps jamming") before or after a request is the reason, context only;
the request's own thing is fetched (fix62b class 1: "my recorder's eating batteries.. can u
grab me some AAs" asked "Where is your field recorder?"). Two ways of saying it were misread:
a thing's "'s" before an -ing verb read as a possessive (``reading/contracted_has_is``: now
"is" where the -ing word opens no name of the office), and a "so" before a verb of giving with
no comma (``reading/consequence_boundary``: now a clause of its own). "my recorder's broken,
can you bring me another one", "bring me my recorder" and "my drill's in the van" are read as
before."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.consequence_boundary import consequence_boundaries
from assistantx.agents.symbolic.reading.contracted_has_is import spelled_has_is
from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.dataset_offices import default_office
from helpers.reading import frame_reader


def _workshop() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "Workshop",
            [
                ob.person("lee", "Lee Hart", "drill", "recorder", "stapler", aliases=["Lee"]),
                ob.person("wang", "Wang Li", "drill", "recorder", "stapler", aliases=["Wang"]),
                ob.person("max", "Max Doyle", "drill", aliases=["Max"]),
            ],
            rooms=[ob.room("store", "Store room", 20.0, 6.0)],
            item_types=[
                ob.item("drill", "drill", "personal"),
                ob.item("recorder", "field recorder", "personal", synonyms=["recorder"]),
                ob.item("stapler", "stapler", "personal"),
                ob.item("lead", "charging lead", "personal"),
                ob.item("battery", "battery", consumable=True, synonyms=["AAs", "AA battery"]),
                ob.item("staples", "staples", consumable=True),
            ],
            operations=[],
            facilities=[
                ob.facility(
                    "cupboard",
                    "supply cupboard",
                    at="store",
                    guards=["max"],
                    supplies=[{"type": "battery", "count": 40}, {"type": "staples", "count": 20}],
                )
            ],
            home="store",
        )
    )()


_lee = frame_reader(_workshop, "lee")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("my drill's eating batteries, can you grab me some", "battery"),
        ("my recorder's eating batteries.. can u grab me some AAs", "battery"),
        ("can you grab me some batteries, my drill's eating them", "battery"),
        ("my recorder's playing up, can you get me batteries", "battery"),
        ("my stapler keeps jamming so bring me some staples", "staples"),
        ("my stapler's jammed so bring me some staples", "staples"),
        ("my recorder died so bring me some batteries", "battery"),
        ("my recorder died, could you get me batteries", "battery"),  # read so already
    ],
)
def test_the_own_things_doing_is_the_reason_and_the_ask_is_fetched(text: str, item: str) -> None:
    frame = _lee(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [(item, None, "lee")], frame
    assert frame.question is None, frame


def test_another_of_the_broken_thing_is_read_as_before() -> None:
    frame = _lee("my recorder's broken, can you bring me another one")
    assert frame.question == "Whose field recorder do you mean?", frame


def test_the_own_thing_asked_for_is_read_as_before() -> None:
    frame = _lee("bring me my recorder")
    assert frame.question is not None and "field recorder" in frame.question, frame
    assert frame.question.startswith("Where is your"), frame


def test_where_the_own_thing_is_is_still_told() -> None:
    frame = _lee("my drill's in the van")
    assert frame.tasks == [] and frame.decline is not None, frame


@pytest.mark.parametrize(
    ("text", "spelled"),
    [
        ("my drill's eating batteries", "my drill is eating batteries"),
        (
            "sorry, my recorder's playing up, get me one",
            "sorry, my recorder is playing up, get me one",
        ),
    ],
)
def test_a_things_s_before_its_doing_is_is(text: str, spelled: str) -> None:
    assert spelled_has_is(text, lambda p: p in ("drill", "recorder"), lambda p: False) == spelled


@pytest.mark.parametrize(
    "text",
    [
        "my drill's eating batteries",  # "drill" names no thing of the office here
        "bring me Wang's drill's charging lead",  # after a verb: no subject
    ],
)
def test_a_possessive_before_an_ing_word_stays_without_a_thing(text: str) -> None:
    assert spelled_has_is(text, lambda p: False, lambda p: False) == text


@pytest.mark.parametrize(
    "text",
    [
        "my drill's charging lead is frayed",  # the -ing word opens a name
        "my drill's cutting disc is worn",  # a verb of the subject's own follows
    ],
)
def test_an_ing_word_of_the_subjects_noun_stays_a_possessive(text: str) -> None:
    names = ("charging lead",)
    spelled = spelled_has_is(text, lambda p: p == "drill", lambda p: p.startswith(names))
    assert spelled == text


def test_so_before_a_verb_of_giving_opens_the_ask() -> None:
    assert consequence_boundaries("my stapler keeps jamming so bring me some staples") == (
        "my stapler keeps jamming, so bring me some staples"
    )
    assert consequence_boundaries("I'm so tired") == "I'm so tired"
    assert consequence_boundaries("do so bring me some") == "do so bring me some"


def test_a_name_opened_by_an_ing_word_is_still_the_things_name() -> None:
    frame = _lee("my drill's charging lead is frayed, bring me Wang's")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("lead", "wang", "lee")]


_default = frame_reader(default_office, "lee")


def test_the_default_offices_stapler_jamming_fetches_staples_or_asks_as_before() -> None:
    frame = _default("my stapler keeps jamming so bring me a pen")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("pen", "lee")], frame
