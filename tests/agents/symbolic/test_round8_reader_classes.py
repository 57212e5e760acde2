"""Blind round 8's reader classes, by mechanism, on sentences of our own against a theatre's
production office no sentence was written for (``helpers.playhouse``) and against the
default office (the round's own office and sentences were never read)."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, load_office, parse_office
from helpers.playhouse import playhouse, raw_playhouse


@functools.cache
def _office(name: str) -> Office:
    return playhouse() if name == "playhouse" else load_office()


@functools.cache
def _parser(name: str) -> InstructionParser:
    return InstructionParser(_office(name))


def _tasks(office: str, text: str, who: str) -> list[tuple[str, str | None, str | None, str]]:
    frame = _parser(office).parse(text, who)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


# -- 1. "for the <noun>" after a copy or print request is its purpose ----------------------


@pytest.mark.parametrize(
    ("office", "who", "text", "wanted"),
    [
        ("default", "mao", "can you copy my contract? I need a copy for the file", "copy"),
        ("default", "mao", "copy my contract please, need a copy for the file", "copy"),
        ("default", "zhou", "can you photocopy my report. I need one for the file", "copy"),
        ("default", "chen", "print my slides, I need a printout for the report", "print"),
        ("playhouse", "oona", "can you copy my contract? I need a copy for the rota", "copy"),
        ("playhouse", "dev", "copy my rider, need a copy for the schedule", "copy"),
        ("playhouse", "ann", "please print my rota, need one for the green room", "print"),
        ("playhouse", "jon", "photocopy my agreement. I need a copy for the records", "copy"),
        ("playhouse", "jon", "copy my contract, I need one for the props cupboard", "copy"),
        ("default", "zhou", "copy my contract, I need a copy for the contract file", "copy"),
        ("playhouse", "ann", "copy my agreement. I need one for the rota folder", "copy"),
    ],
)
def test_a_purpose_after_the_product_is_no_recipient(
    office: str, who: str, text: str, wanted: str
) -> None:
    """The item word, place or thing after "for the" says what the product is for: the
    requester gets it, nobody is asked whom to pass a file on to."""
    [(kind, _, owner, recipient)] = _tasks(office, text, who)
    assert (kind, owner, recipient) == (wanted, who, who)


@pytest.mark.parametrize(
    ("office", "who", "text", "to"),
    [
        ("default", "mao", "get me a copy of my contract for Wang", "wang"),
        ("playhouse", "oona", "copy my contract. I need a copy for Dev", "dev"),
    ],
)
def test_a_person_after_for_is_still_the_recipient(
    office: str, who: str, text: str, to: str
) -> None:
    [(kind, _, owner, recipient)] = _tasks(office, text, who)
    assert (kind, owner, recipient) == ("copy", who, to)


async def test_the_copy_for_the_file_reaches_the_requester() -> None:
    run = await run_instruction(
        _office("default"), "zhou", "can you copy my contract? I need a copy for the file"
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"holds": ["zhou", "copy:zhou"]})


async def test_a_printout_for_the_noticeboard_reaches_the_requester() -> None:
    """The playhouse's files are rotas, not "file"s: the requester's rota, sent along with
    the request, is forwarded to the copier's keeper and the printout comes back."""
    text = "print my rota, I need a printout for the noticeboard"
    run = await run_instruction(_office("playhouse"), "ann", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"holds": ["ann", "printout:ann"]})


async def test_a_file_of_another_name_is_passed_on() -> None:
    run = await run_instruction(_office("playhouse"), "ann", "send my rota to Dev")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    forwarded = [r.action for r in run.stm.trace.actions() if r.action.type == "forward_file"]
    assert [(a.target, a.file) for a in forwarded] == [("dev", "rota:ann")]  # type: ignore[attr-defined]


# -- 2. a correction after an ellipsis, with the corrected-away person in a reason ---------


@pytest.mark.parametrize(
    ("office", "who", "text", "owner", "item"),
    [
        (
            "default",
            "sun",
            "bring me Wang's seal... sorry, I meant Mao's seal, Wang needs hers today",
            "mao",
            "seal",
        ),
        (
            "default",
            "lee",
            "get me Wang's stapler... no wait, Zhang's, Wang is using hers",
            "zhang",
            "stapler",
        ),
        (
            "playhouse",
            "oona",
            "bring me Ann's torch... sorry, I meant Dev's torch, Ann needs hers tonight",
            "dev",
            "torch",
        ),
        (
            "playhouse",
            "oona",
            "could you get me Jon's lanyard... oops, I mean Jonathan's, Jon needs his own today",
            "jonathan",
            "lanyard",
        ),
        (
            "playhouse",
            "dev",
            "get me Ann's tape measure... sorry I meant Roseanne's tape measure, Ann needs hers",
            "roseanne",
            "tape_measure",
        ),
        (
            "playhouse",
            "dev",
            "get me Ann's tape measure - no wait, Oona's tape measure. Ann is using hers",
            "oona",
            "tape_measure",
        ),
        (
            "playhouse",
            "oona",
            "bring me Ann's torch... sorry I meant Dev's, Ann's using hers",
            "dev",
            "torch",
        ),
        (
            "playhouse",
            "oona",
            "fetch Ann's torch for me... no wait, Jon's, Ann has to keep hers",
            "jon",
            "torch",
        ),
        (
            "playhouse",
            "oona",
            "bring me Ann's torch.. sorry, meant Dev's torch - Ann needs hers today",
            "dev",
            "torch",
        ),
    ],
)
def test_the_corrected_owner_is_asked_and_the_requester_gets_it(
    office: str, who: str, text: str, owner: str, item: str
) -> None:
    """Only the corrected item is fetched, for the requester; the person of the reason is
    neither a recipient nor an owner asked (also when their name alone could mean two
    people: "Ann" or Roseanne, called "Anne": the reason's person is only context)."""
    assert _tasks(office, text, who) == [("transfer", item, owner, who)]


@pytest.mark.parametrize(
    ("office", "who", "text", "owner", "item"),
    [
        ("default", "sun", "bring me Mao's seal, Wang needs hers today", "mao", "seal"),
        ("playhouse", "oona", "get me Dev's torch, as Jon needs his tonight", "dev", "torch"),
    ],
)
def test_a_colleague_who_needs_their_own_is_the_reason(
    office: str, who: str, text: str, owner: str, item: str
) -> None:
    assert _tasks(office, text, who) == [("transfer", item, owner, who)]


def test_a_colleagues_need_alone_is_not_read_as_a_reason() -> None:
    """With no request beside it, "Wang needs hers" is no reason for anything: not answered
    as context, and nothing is fetched."""
    frame = _parser("default").parse("Wang needs hers today", "sun")
    assert frame.tasks == []


async def test_the_corrected_seal_reaches_the_requester_with_its_owners_yes() -> None:
    text = "bring me Wang's seal... sorry, I meant Mao's seal, Wang needs hers today"
    run = await run_instruction(_office("default"), "sun", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"holds": ["sun", "seal:mao"]})
    asked = {m.chat.id for m in run.sim.messenger.sent if "seal" in m.text}
    assert "mao" in asked and "wang" not in asked


# -- 3. a statement of where an item is is answered in words, never acted on ---------------


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("playhouse", "oona", "fyi gaffer tape's in the cupboard"),
        ("playhouse", "oona", "fyi Dev's torch's back in the cupboard"),
        ("playhouse", "ann", "fyi you'll find the gaffer tape in the cupboard"),
        ("playhouse", "jon", "fyi, your copy is at the copier"),
        ("playhouse", "jon", "just so u know the lanyard is in Jon's drawer"),
        ("playhouse", "dev", "heads-up: gaffer tape is in the props cupboard again"),
        ("playhouse", "dev", "heads up, the white gloves are back in the store room"),
        ("playhouse", "ann", "the torch is in the drawer again"),
        ("default", "lee", "fyi Wang's stapler is back in the print room"),
        ("default", "lee", "heads up: scissors are in the kitchenette again"),
        ("default", "zhou", "just so you know, the paper's by the printer"),
        ("default", "zhou", "fyi the wipes are back in the fridge"),
    ],
)
def test_where_an_item_is_is_answered_in_words(office: str, who: str, text: str) -> None:
    frame = _parser(office).parse(text, who)
    assert frame.tasks == [] and frame.question is None
    assert frame.decline is not None and "I did nothing" in frame.decline


def test_the_answer_says_what_was_told_with_its_verb_agreeing() -> None:
    frame = _parser("default").parse("heads up: scissors are in the kitchenette again", "lee")
    assert frame.decline == "Thanks for telling me where the scissors are. I did nothing."
    frame = _parser("playhouse").parse("fyi gaffer tape's in the cupboard", "ann")
    assert frame.decline == "Thanks for telling me where the gaffer tape is. I did nothing."


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        ("gaffer tape's in the cupboard, bring me some", ("transfer", "gaffer_tape", None, "oona")),
        (
            "the torch is in the cupboard, can you get it for me",
            ("transfer", "torch", None, "oona"),
        ),
        (
            "Jonathan's lanyard is in the props cupboard, could you bring it to Roseanne",
            ("transfer", "lanyard", "jonathan", "roseanne"),
        ),
        ("fyi my contract is on the copier, please copy it", ("copy", "contract", "oona", "oona")),
    ],
)
def test_a_request_beside_where_it_is_still_points_back_to_it(
    text: str, wanted: tuple[str, str, str | None, str]
) -> None:
    assert _tasks("playhouse", text, "oona") == [wanted]


async def test_a_whereabouts_statement_moves_nothing() -> None:
    run = await run_instruction(_office("playhouse"), "oona", "fyi gaffer tape's in the cupboard")
    assert run.stm.trace.outcome == "done"
    assert not {"move", "send_qr", "inquire"} & set(run.actions)


# -- 6. the article told to people follows the noun ---------------------------------------


async def test_a_plural_supply_is_told_without_a_singular_article() -> None:
    run = await run_instruction(_office("playhouse"), "ann", "get me some cotton gloves")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    summary = run.stm.trace.summary
    assert "you now have some cotton gloves from the props cupboard" in summary
    assert "a cotton gloves" not in summary


async def test_a_consumable_supply_is_told_as_stuff() -> None:
    run = await run_instruction(_office("playhouse"), "ann", "could you bring me some gaffer tape")
    assert "you now have some gaffer tape from the props cupboard" in run.stm.trace.summary


# -- 5. a send-out service's destination outside the office, also named before "by" --------


def _with_service_synonyms() -> InstructionParser:
    """The playhouse where the courier desk is also called "courier" and the fax machine
    "fax": the service's word after "by" is then a facility's name too."""
    raw = raw_playhouse()
    names = {"courier_desk": ["courier"], "fax_machine": ["fax"]}
    for facility in raw["facilities"]:
        facility["synonyms"] = names.get(facility["id"], [])
    return InstructionParser(parse_office(raw, "playhouse with short names"))


@pytest.mark.parametrize(
    ("text", "op", "destination"),
    [
        ("send my loan agreement to the arts council by courier", "courier", "the arts council"),
        (
            "please send my rider to the touring company by courier",
            "courier",
            "the touring company",
        ),
        ("get my contract to the Lyric Theatre via courier", "courier", "the Lyric Theatre"),
        ("send my agreement to the county arts office by fax", "fax", "the county arts office"),
        ("send my contract to Hartwell & Co by courier please", "courier", "Hartwell & Co"),
        ("fax my agreement to Hartwell Associates", "fax", "Hartwell Associates"),
        (
            "fax my contract to the council's planning office",
            "fax",
            "the council's planning office",
        ),
        # a firm said by its role alone asks where since fix129e (test_role_destination.py)
        (
            "send my contract by fax to the insurers at 5 Bank Street",
            "fax",
            "the insurers at 5 Bank Street",
        ),
    ],
)
@pytest.mark.parametrize("short_names", [False, True])
def test_a_destination_outside_is_where_the_service_sends_it(
    text: str, op: str, destination: str, short_names: bool
) -> None:
    parser = _with_service_synonyms() if short_names else _parser("playhouse")
    frame = parser.parse(text, "oona")
    assert frame.question is None, frame.question
    assert [(t.item, t.owner, t.operation, t.destination) for t in frame.tasks] == [
        ("contract", "oona", op, destination)
    ]


def test_to_a_place_then_a_verb_is_still_a_purpose() -> None:
    """ "a torch to read by": "to" with a verb after it is what the item is for; only an
    article or a name that is no verb after "to" opens a place."""
    assert _tasks("playhouse", "bring me a torch to read the script with", "oona") == [
        ("transfer", "torch", None, "oona")
    ]


@pytest.mark.parametrize(
    ("text", "here"),
    [
        ("fax my contract to the green room", "The green room"),
        ("courier my contract to the Company", "The Company group"),
        ("send my contract to the props cupboard by courier", "The props cupboard"),
    ],
)
def test_a_place_or_group_of_the_office_is_no_destination_outside(text: str, here: str) -> None:
    """A send-out service sends things out of the office: a place, facility or group of
    the office after "to" is asked about, never sent to nor read as somewhere outside."""
    frame = _parser("playhouse").parse(text, "oona")
    assert frame.tasks == [] and frame.question is not None
    assert frame.question.startswith(f"{here} is here in the office")


@pytest.mark.parametrize(
    ("answer", "destination"),
    [
        ("the county arts office", "the county arts office"),
        ("to the Lyric Theatre", "the Lyric Theatre"),
    ],
)
def test_the_answer_names_the_place_outside(answer: str, destination: str) -> None:
    parser = _parser("playhouse")
    frame = parser.parse_with_answers("fax my contract to the green room", "oona", [answer])
    assert frame.question is None
    assert [(t.item, t.operation, t.destination) for t in frame.tasks] == [
        ("contract", "fax", destination)
    ]


async def test_the_courier_to_an_outside_office_runs_to_done() -> None:
    text = "send my loan agreement to the arts council by courier"
    run = await run_instruction(_office("playhouse"), "oona", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert "the arts council" in run.stm.trace.summary


# -- 4. a name said like another person's name is asked about ------------------------------


@pytest.mark.parametrize(
    ("office", "who", "text", "names"),
    [
        ("default", "mao", "give my contract to Li", ("Sun Li", "Lee Ming")),
        ("default", "mao", "get Li a pen", ("Sun Li", "Lee Ming")),
        ("default", "zhou", "bring Li's book", ("Sun Li", "Lee Ming")),
        ("playhouse", "oona", "give my contract to Ann", ("Ann Mbeki", "Roseanne Vale")),
        ("playhouse", "oona", "get Jon's lanyard", ("Jon Petrov", "Jonathan Wilde")),
        ("playhouse", "dev", "give my rota to Jon", ("Jon Petrov", "Jonathan Wilde")),
    ],
)
def test_a_given_name_said_like_anothers_alias_is_asked(
    office: str, who: str, text: str, names: tuple[str, str]
) -> None:
    """ "Li" is Sun Li's given name and sounds like "Lee", Lee Ming's alias: either may be
    meant, so the reader asks, naming both, and moves nothing."""
    frame = _parser(office).parse(text, who)
    assert frame.tasks == [] and frame.question is not None
    assert all(name in frame.question for name in names), frame.question


@pytest.mark.parametrize(
    ("office", "who", "text", "wanted"),
    [
        # an alias the office declares is how that person is called: it wins
        ("default", "mao", "get Lee's book", ("transfer", "book", "lee", "mao")),
        ("default", "mao", "take my stapler to Lee", ("transfer", "stapler", "mao", "lee")),
        ("playhouse", "oona", "get John's lanyard", ("transfer", "lanyard", "jonathan", "oona")),
        (
            "playhouse",
            "oona",
            "bring me Anne's tape measure",
            ("transfer", "tape_measure", "roseanne", "oona"),
        ),
        # only the one spelled so owns the item: no other could be meant
        ("default", "mao", "bring me Li's scissors", ("transfer", "scissors", "sun", "mao")),
        ("playhouse", "oona", "get Jon's torch", ("transfer", "torch", "jon", "oona")),
        # names that only look alike, said differently ("Lei", "Lin"), are never mixed up
        ("default", "mao", "give my contract to Lei", ("transfer", "document", "mao", "yang")),
        ("default", "mao", "give my contract to Sun Li", ("transfer", "document", "mao", "sun")),
    ],
)
def test_an_alias_or_the_owner_settles_who_is_meant(
    office: str, who: str, text: str, wanted: tuple[str, str, str, str]
) -> None:
    assert _tasks(office, text, who) == [wanted]


async def test_the_question_comes_before_anything_moves() -> None:
    """In the simulated office the requester is asked "Who do you mean by 'Li'?", naming
    both, in their own chat, before the robot moves; the simulated requester answers "Sun
    Li" (the option that has the word they wrote), and the answer that names one of the two
    settles it (``reading.name_chosen``): Sun Li gets the contract, Lee Ming never does."""
    run = await run_instruction(_office("default"), "mao", "give my contract to Li")
    actions = [r.action for r in run.stm.trace.actions()]
    asked = [a for a in actions if a.type == "inquire"]
    assert asked and asked[0].contact == "mao"  # type: ignore[attr-defined]
    assert "Sun Li" in asked[0].question and "Lee Ming" in asked[0].question  # type: ignore[attr-defined]
    moves = [n for n, a in enumerate(actions) if a.type == "move"]
    assert not moves or actions.index(asked[0]) < moves[0]
    assert run.sim.world.check({"holds": ["sun", "document:mao"]})
    assert not run.sim.world.check({"holds": ["lee", "document:mao"]})


@pytest.mark.parametrize(
    ("office", "text", "said", "who"),
    [
        ("playhouse", "fax this to the council's planning office", "fax", "oona"),
        ("default", "heat this up", "for me to heat", "lee"),
        ("default", "could you sign it?", "to be signed", "lee"),
    ],
)
def test_which_item_is_asked_in_the_offices_words(
    office: str, text: str, said: str, who: str
) -> None:
    """With no item to act on, the question names the service as the office calls it, never
    the task kind behind it (a fax is not "the heat request")."""
    frame = _parser(office).parse(text, who)
    assert frame.question is not None and said in frame.question
    assert "request" not in frame.question and "heat" not in frame.question.replace(said, "")
