"""A hand-over code goes to a person other than the requester, owner or keeper only when the
requester named them AS the recipient (or the doer): a name in an explanatory clause ("...
because Rich asked for it"), a wisher ("Rich wants it on the board") or an owner ("Rich's
form") makes nobody a party. Properties over generated requests on a small clinic."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from assistantx.core.actions import SendQR
from assistantx.core.office import Office, parse_office
from assistantx.runtime import consent
from assistantx.runtime.recipients import named_recipients
from helpers.clinic import clinic, raw_clinic
from helpers.consent_memory import answered, exchange, memory
from helpers.drill_shed import drill_shed
from helpers.packing_loft import packing_loft
from helpers.watch_room import watch_room

RECIPIENT = (
    "take my {item} to {x}",
    "could you bring {x} my {item}",
    "please leave my {item} on {x}'s desk",
    "hand {x} my {item} please",
    "my {item} is for {x}, can you drop it off",
    "lend {x} my {item}",
    "leave my {item} with {x}",
    "pls leave my {item} w/ {x}",  # the chat shorthand the reader writes out
)
EXPLANATION = (
    "because {b} asked for it",
    "{b} wants it up on the board",
    "{b} said it was urgent",
    "as {b} mentioned this morning",
    "{b}'s one is broken",
    "I told {b} I would",
)
PRONOUN = (
    "{x} hurt {pos} hand, take {obj} my {item}",
    "{x} needs a {item}, please bring {obj} mine",
    "{x} has no {item}. Please take my {item} to {obj}",  # a lack: whom it goes to
    # the perfect of "be": a state she was in, no having of anything
    "{x} has been out on site all day, take {obj} my {item}",
)


def _written(office: Office, person: str, full: bool) -> str:
    name = office.person(person).name
    return name if full else name.split()[0]


@st.composite
def requests(draw: st.DrawFn) -> tuple[str, str, str, str]:
    """(requester, recipient, bystander, text): the recipient named as such, the bystander
    only in an explanation, in either order, joined by a comma, "and" or a full stop."""
    office = clinic()
    people = [p.id for p in office.people]
    requester, x, b = draw(st.permutations(people))[:3]
    item = draw(st.sampled_from(["clipboard", "thermometer", "form"]))
    ask = draw(st.sampled_from(RECIPIENT)).format(
        item=item, x=_written(office, x, draw(st.booleans()))
    )
    why = draw(st.sampled_from(EXPLANATION)).format(b=_written(office, b, draw(st.booleans())))
    joint = draw(st.sampled_from([", ", ". ", " - "]))
    text = f"{ask}{joint}{why}" if draw(st.booleans()) else f"{why.capitalize()}{joint}{ask}"
    return requester, x, b, text


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(requests())
def test_only_the_person_named_as_recipient_may_collect(
    request: tuple[str, str, str, str],
) -> None:
    office = clinic()
    requester, x, b, text = request
    stm = memory(requester, text)
    answered(stm, x, b)
    assert named_recipients(office, stm) == {x}, text
    mine = f"clipboard:{requester}"
    assert consent.check(office, stm, SendQR(contact=x, item=mine, purpose="collect")) is None
    refused = consent.check(office, stm, SendQR(contact=b, item=mine, purpose="collect"))
    assert refused is not None and refused.rule == "not_a_party", text


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(PRONOUN), st.data())
def test_a_pronoun_recipient_is_the_one_person_named_who_is_not_an_owner(
    template: str, data: st.DataObject
) -> None:
    office = clinic()
    requester, x, owner = data.draw(st.permutations([p.id for p in office.people]))[:3]
    text = template.format(
        x=_written(office, x, data.draw(st.booleans())),
        pos=data.draw(st.sampled_from(["her", "his", "their"])),
        obj=data.draw(st.sampled_from(["her", "him", "them"])),
        item="clipboard",
    )
    # an owner named beside them does not make the pronoun ambiguous
    text += f", or {_written(office, owner, True)}'s if mine is gone"
    assert named_recipients(office, memory(requester, text)) == {x}, text


def test_a_name_as_the_answer_or_in_an_accepted_offer_names_the_recipient() -> None:
    office = clinic()
    stm = memory("ines", "print my rota, Rich said so")
    assert named_recipients(office, stm) == set()
    stm.dialogue += exchange(
        "ines", "Who should get the printout?", "Hal Brooks, please", question_id="q1"
    )
    assert named_recipients(office, stm) == {"hal"}
    offer = memory("ines", "Dawn needs a thermometer.")
    offer.dialogue += exchange(
        "ines", "Shall I bring Dawn Ellis a thermometer?", "yes please", question_id="q1"
    )
    assert named_recipients(office, offer) == {"dawn"}
    # a name as a word, in lower case, names nobody
    assert named_recipients(office, memory("ines", "take my form to the may fair stall")) == set()


def _with_shared_name_words() -> Office:
    """The clinic plus a person whose surname is another's alias (Page / Oksana Page) and one
    who shares a surname with Hal Brooks."""
    raw = raw_clinic()
    raw["people"] += [  # Oksana first: the file's order must not decide who "Page" is
        {
            "id": "oksana",
            "name": "Oksana Page",
            "location": "desk_7",
            "handle": "@oksana",
            "owns": [{"type": "file"}],
        },
        {
            "id": "page_h",
            "name": "Page Holloway",
            "aliases": ["Page"],
            "location": "desk_6",
            "handle": "@page_h",
            "owns": [{"type": "file"}],
        },
        {
            "id": "ada",
            "name": "Ada Brooks",
            "location": "desk_5",
            "handle": "@ada",
            "owns": [{"type": "file"}],
        },
    ]
    return parse_office(raw, "clinic-shared-names")


def test_a_name_word_declared_for_one_person_names_that_person() -> None:
    office = _with_shared_name_words()
    text = "send my rota to Page and to Dawn Ellis"
    assert named_recipients(office, memory("ines", text)) == {"page_h", "dawn"}


def test_a_name_word_shared_by_several_people_names_each_of_them() -> None:
    # "Brooks" is nobody's declared name: the requester may mean either, and the reasoner
    # asks which; the guard must not pick one of them by the office file's order
    office = _with_shared_name_words()
    assert named_recipients(office, memory("ines", "take my form to Brooks")) == {"hal", "ada"}


CORRECTION = (
    "take my {item} to {x}, no wait, {y}",
    "take my {item} to {x}, no wait not {x}, {y}, they need it",
    "could you bring {x} my {item} - sorry, I meant {y}",
    "hand my {item} to {x}... oops, {y}",
)
NEWS = ("take my {item} to {x}. sorry, {y} has it", "take my {item} to {x}, sorry {y} is out")


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(CORRECTION), st.data())
def test_a_corrected_recipient_replaces_the_one_corrected(
    template: str, data: st.DataObject
) -> None:
    """Blind round 27's class: "to Siobhán, no wait not Siobhán, Łukasz" names Łukasz as the
    recipient (the reader hands it to him; on main the guard refused his code) and no
    longer Siobhán, whom the requester took back."""
    office = clinic()
    requester, x, y = data.draw(st.permutations([p.id for p in office.people]))[:3]
    text = template.format(
        item="clipboard",
        x=_written(office, x, data.draw(st.booleans())),
        y=_written(office, y, data.draw(st.booleans())),
    )
    assert named_recipients(office, memory(requester, text)) == {y}, text


@given(st.sampled_from(NEWS), st.data())
@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_a_name_after_sorry_that_is_news_is_no_recipient(
    template: str, data: st.DataObject
) -> None:
    office = clinic()
    requester, x, y = data.draw(st.permutations([p.id for p in office.people]))[:3]
    text = template.format(
        item="clipboard", x=_written(office, x, True), y=_written(office, y, True)
    )
    assert named_recipients(office, memory(requester, text)) == {x}, text


def test_a_rank_one_person_holds_names_them() -> None:
    """ "the Station Officer" (blind round 26's class): the guard reads the reader's ranks."""
    office = watch_room()
    stm = memory("kemal", "send my stock count spreadsheet to the Station Officer")
    assert named_recipients(office, stm) == {"frank"}
    stm = memory("kemal", "send my spreadsheet to the crew manager")
    assert named_recipients(office, stm) == set()


def test_a_lower_case_name_said_as_a_correction_is_the_receiver() -> None:
    """ "to sam. sorry not sam, robin" (blind round 28's class): the guard agrees with the
    reader that robin, not either Sam, receives; a name word said before more words is not
    a correction alone."""
    office = packing_loft()
    for text in (
        "pls print my file and take the copies to sam. sorry not sam, robin",
        "take my file to sam. sorry, robin",
    ):
        assert named_recipients(office, memory("lena", text)) == {"robin"}, text
    stm = memory("lena", "take my file to sam. sorry not sam, robin told me")
    assert named_recipients(office, stm) == {"sam_k", "sam_r"}


@pytest.mark.parametrize(
    "text",
    [
        "Nell's headset died mid-session. Miles has a spare one, could you bring it to her?",
        "Nell's headset died. Miles has a spare, bring it to her",
    ],
)
def test_the_one_said_to_have_it_is_no_receiver_of_her(text: str) -> None:
    """Blind round 36 after its fixes: the reader gave Miles's headset to Nell, and the
    guard refused Nell, counting "Miles has a spare one" as the one "her" may mean."""
    assert named_recipients(drill_shed(), memory("sunny", text)) == {"nell"}


@pytest.mark.parametrize(
    "text",
    [
        "Nell has been out in the rain all morning, bring her my headset",
        "Nell has been at the dentist, could you take her my headset when she's back",
    ],
)
def test_one_who_has_been_somewhere_is_no_holder(text: str) -> None:
    """Blind round 72's class: "has been" was read as "has" (a holder), so the guard refused
    the one "her" means the code for the thing the reader handed to her."""
    assert named_recipients(drill_shed(), memory("sunny", text)) == {"nell"}
