"""Blind round 10's reader classes, by mechanism, on sentences of our own against a small
letterpress studio no sentence was written for (``helpers.printshop``) and against the
default office (the round's own office was read only to name the classes)."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, load_office
from helpers.printshop import printshop


@functools.cache
def _office(name: str) -> Office:
    return printshop() if name == "printshop" else load_office()


@functools.cache
def _parser(name: str) -> InstructionParser:
    return InstructionParser(_office(name))


Row = tuple[str, str | None, str | None, str, str | None]


def _tasks(office: str, text: str, who: str) -> list[Row]:
    frame = _parser(office).parse(text, who)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    return [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks]


# -- 1. "P has an X, could you bring it to me": the item and whose, from the statement -----


@pytest.mark.parametrize(
    ("who", "text", "item", "owner"),
    [
        ("kofi", "Lena has a loupe I think, could you bring it to me", "loupe", "lena"),
        ("kofi", "Edda has a creaser, can you get me that", "bone_folder", "edda"),
        (
            "noor",
            "I think Kofi Mensah has a bone folder. Could you fetch it for me?",
            "bone_folder",
            "kofi",
        ),
        ("kofi", "Noor's got a magnifier, bring it over please", "loupe", "noor"),
    ],
)
def test_a_pronoun_means_the_item_a_statement_said_someone_has(
    who: str, text: str, item: str, owner: str
) -> None:
    """The request names no item, only "it"/"that": the one item the statement names, whose
    it said it is (the owner is then asked, as for any borrowed item)."""
    assert _tasks("printshop", text, who) == [("transfer", item, owner, who, None)]


@pytest.mark.parametrize(
    ("who", "text", "item"),
    [
        ("edda", "is there any card stock left? if so bring me a sheet", "card_stock"),
        ("edda", "Is there any card stock left? If so bring me one.", "card_stock"),
        ("lena", "any cotton string left? bring me a piece", "string"),
        ("lena", "got any card? I could use a couple", "card_stock"),
    ],
)
def test_a_unit_of_a_thing_named_before_is_that_thing(who: str, text: str, item: str) -> None:
    """ "a sheet", "a piece", "one": a unit of the supply the question before named, and the
    conditional request on it is a request (no owner: the store's, for anyone)."""
    [(kind, got, owner, recipient, _)] = _tasks("printshop", text, who)
    assert (kind, got, owner, recipient) == ("transfer", item, None, who)


@pytest.mark.parametrize(
    "text",
    [
        "can you bring me a spare battery because my loupe is dying",  # a thing of its own
        "I think Lena has one I guess, could you bring it to me",  # no thing named at all
    ],
)
def test_a_unit_points_back_only_to_one_item_named(text: str) -> None:
    """A unit before a noun is that noun ("a spare battery", declined as unknown), and "it"
    with no item named anywhere is asked about: never a thing guessed."""
    frame = _parser("printshop").parse(text, "kofi")
    assert frame.tasks == []
    assert frame.question or frame.decline


# -- 2. "run X through / put X on <facility>": the facility's own operation ---------------


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("run my svg through the etching machine and bring it back to me", "engrave"),
        ("can you put my artwork file on the engraver", "engrave"),
        ("please run my artwork through the printer", "print"),
        ("could you send my svg through the engraver for me", "engrave"),
        # a thing of mine the office has no word for, at a machine that renders files
        ("run my poster through the engraver and bring it back to me", "engrave"),
        ("can you put my logo on the printer", "print"),
    ],
)
def test_a_file_taken_through_a_facility_is_its_operation(text: str, operation: str) -> None:
    """Which of two renderings of a file: the one of the facility the file is taken to; the
    product comes back to the requester, nobody is asked whom to pass the file on to."""
    [(kind, item, owner, recipient, op)] = _tasks("printshop", text, "ugo")
    assert (kind, item, owner, recipient, op) == ("print", "artwork", "ugo", "ugo", operation)


# -- 3. the product's own name decides between two operations of one shape ----------------


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("Could I get a brass print of my artwork file?", "engrave"),
        ("I'd like an etched plate of my svg", "engrave"),
        ("could I get a print of my artwork file?", "print"),
        ("could you etch my artwork file", "engrave"),
        ("print my svg please", "print"),
    ],
)
def test_the_product_named_says_which_rendering(text: str, operation: str) -> None:
    """ "a brass print" is the engraver's product though "print" is also the printer's verb:
    the words of a product's name are no verb said."""
    [(_, _, _, _, op)] = _tasks("printshop", text, "lena")
    assert op == operation


def test_a_rendering_the_words_do_not_name_is_asked() -> None:
    """With neither operation's words nor its product's said, nothing is rendered: the
    requester is asked, neither rendering guessed."""
    frame = _parser("printshop").parse("could you make something of my artwork file", "lena")
    assert frame.tasks == []
    assert frame.question is not None


# -- 4. a modifier glued to a service verb makes another service --------------------------


@pytest.mark.parametrize(
    ("office", "who", "text", "said"),
    [
        ("printshop", "noor", "can you 3D print my artwork file?", "3D print"),
        ("printshop", "noor", "could you 3-D print my svg", "3-D print"),
        ("printshop", "noor", "please screen print my artwork", "screen print"),
        ("default", "mao", "can you 3D print my report?", "3D print"),
        ("default", "mao", "could you laser copy my contract", "laser copy"),
    ],
)
def test_a_modified_service_is_declined_not_run_plain(
    office: str, who: str, text: str, said: str
) -> None:
    """The plain service is never run in its place: declined, saying the modified service as
    typed and what the office can do."""
    frame = _parser(office).parse(text, who)
    assert frame.tasks == []
    assert frame.decline is not None and f"can't {said}" in frame.decline
    assert "What I can do here:" in frame.decline


@pytest.mark.parametrize(
    "text",
    [
        "can you quickly print my svg",
        "could you now print my artwork file",
        "can you go print my artwork",
        "can you just engrave my artwork file",
    ],
)
def test_an_adverb_before_a_service_verb_is_no_modifier(text: str) -> None:
    """ "quickly", "now", "go", "just": the plain service is asked for."""
    [(kind, _, owner, _, _)] = _tasks("printshop", text, "kofi")
    assert (kind, owner) == ("print", "kofi")


# -- 5. thanks said as praise --------------------------------------------------------------


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("default", "lee", "cheers for the book, you're a star"),
        ("printshop", "kofi", "cheers for the loupe, you're a legend"),
        ("printshop", "kofi", "you've been a lifesaver"),
        ("printshop", "kofi", "much obliged for the creaser"),
        ("printshop", "kofi", "you are an absolute gem"),
    ],
)
def test_praise_of_the_assistant_is_thanks_in_words(office: str, who: str, text: str) -> None:
    frame = _parser(office).parse(text, who)
    assert frame.tasks == [] and frame.question is None
    assert frame.decline is not None and "welcome" in frame.decline


def test_praise_with_a_request_beside_it_keeps_the_request() -> None:
    [(kind, item, _, recipient, _)] = _tasks(
        "printshop", "you're a star, could you bring me a loupe", "kofi"
    )
    assert (kind, item, recipient) == ("transfer", "loupe", "kofi")


# -- round 9's residual classes ------------------------------------------------------------


@pytest.mark.parametrize(
    ("who", "text", "item", "owner", "recipient"),
    [
        ("lena", "take these loupes of mine to Noor", "loupe", "lena", "noor"),
        (
            "kofi",
            "I need a bone folder. could you borrow Edda's for me?",
            "bone_folder",
            "edda",
            "kofi",
        ),
        (
            "kofi",
            "Not the loupe - I need a bone folder. can you borrow Edda's for me?",
            "bone_folder",
            "edda",
            "kofi",
        ),
    ],
)
def test_an_owner_said_after_the_item_is_kept(
    who: str, text: str, item: str, owner: str, recipient: str
) -> None:
    """ "X of mine", and "P's" with nothing after it before "for me": the owner is kept (never
    another colleague's item borrowed with their yes)."""
    assert _tasks("printshop", text, who) == [("transfer", item, owner, recipient, None)]


@pytest.mark.parametrize(
    "text",
    [
        "Can I borrow a loupe? Not Lena's, she needs hers for the exam.",
        "can I borrow a loupe? not Lena's, she needs hers for the print run",
    ],
)
def test_a_possessive_before_a_purpose_is_not_made_the_request(text: str) -> None:
    """ "she needs hers for the exam": the excluded owner's need, with a purpose after it,
    never turned into a request for her item."""
    [task] = _parser("printshop").parse(text, "kofi").tasks
    assert (task.item, task.recipient) == ("loupe", "kofi") and task.owner != "lena"


@pytest.mark.parametrize(
    "text",
    [
        "take my proof to Ravi at the post desk so it can be mailed to the printers in Leeds",
        "can you run my proof down to Ravi so he can post it to the client",
        "take my proof to Ravi at the mailroom",
    ],
)
def test_a_hand_over_for_someone_else_to_send_out_is_a_hand_over(text: str) -> None:
    """The send-out in "so it can be mailed" is the colleague's to run: the errand is the
    hand-over, and nobody is asked where to mail it."""
    assert _tasks("printshop", text, "kofi") == [("transfer", "proof", "kofi", "ravi", None)]


def test_a_belonging_put_on_a_rendering_machine_is_not_a_file() -> None:
    """ "my loupe" is an item of the office, no file: not printed."""
    frame = _parser("printshop").parse("put my loupe on the printer", "lena")
    assert all(t.kind != "print" for t in frame.tasks)


def test_mailing_asked_of_the_assistant_still_asks_where() -> None:
    frame = _parser("printshop").parse("please mail my proof", "kofi")
    assert frame.tasks == [] and frame.question is not None and "Where" in frame.question


@pytest.mark.parametrize(
    ("office", "who", "text", "signer"),
    [
        (
            "printshop",
            "kofi",
            "I need Lena Ortiz's signature on my proof, can you get it signed and back to me?",
            "lena",
        ),
        (
            "printshop",
            "kofi",
            "Need Noor's signature on my layout - could you get it signed?",
            "noor",
        ),
        (
            "default",
            "lin",
            "Need Wang Fang's signature on my invoice, can you get it signed and back to me?",
            "wang",
        ),
    ],
)
def test_a_signature_named_by_its_signer_is_theirs(
    office: str, who: str, text: str, signer: str
) -> None:
    """ "P's signature" names who signs; "get it signed and back to me" is the same signing,
    the paper coming back to the requester (who never signs it)."""
    frame = _parser(office).parse(text, who)
    assert frame.question is None and frame.decline is None, frame.question
    [task] = frame.tasks
    assert (task.kind, task.actor, task.owner, task.recipient) == ("sign", signer, who, who)


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("printshop", "kofi", "Lena has a loupe and Noor has a bone folder. Bring it to me"),
        ("printshop", "kofi", "Noor has a bone folder and Lena has a loupe, bring them over"),
    ],
)
def test_a_pronoun_after_two_stated_items_is_asked_about_not_guessed(
    office: str, who: str, text: str
) -> None:
    """Two sentences each say someone has a thing: "it" could be either, so the reader asks
    instead of taking the last one named."""
    frame = _parser(office).parse(text, who)
    assert frame.question is not None and not frame.tasks, frame.tasks
