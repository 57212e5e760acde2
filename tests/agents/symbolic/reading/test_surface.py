"""The surface stage: the message said again in the forms the later stages read, by one ordered
table of steps (``surface.STEPS``) that the parser runs first. Each step's own example goes
through the whole stage and is changed by that step, as its entry says; a placeholder and a
placement beside a colleague's thing end the reading there; a text no step touches passes as
it is."""

from __future__ import annotations

import copy
import functools
from collections.abc import Callable

import pytest
from _gear_office import gear_office
from _offices import office as office_named

from assistantx.agents.symbolic.reading.parser import InstructionParser
from assistantx.agents.symbolic.reading.surface import STEPS, Asked, Said, Step, Surface
from assistantx.core.office import Office
from helpers.chambers_post import chambers_post
from helpers.costume_shop import costume_shop
from helpers.courier_room import courier_room
from helpers.law_firm import law_firm
from helpers.music_school import music_school

# The order of the rewrites as the parser ran them when they were one hand-written sequence.
ORDER = [
    "pictographs",
    "signed_off",
    "undotted",
    "restored_pauses",
    "outsider_pronoun",
    "when_clause",
    "fallback",
    "possessive_pronouns",
    "question_preface",
    "hyphened_nouns",
    "group_member",
    "excluded_owners",
    "seated_subject",
    "thing_for_thing",
    "needed_done",
    "bare_rooms",
    "worked_rooms",
    "undone_services",
    "placeholder",
    "place_doers",
    "kept_copies",
    "run_off",
    "lent_verbs",
    "unmarked_possessive",
    "chat_shorthand",
    "spelled_are",
    "round_trip",
    "approved_uses",
    "hedged_leaves",
    "joined_gerunds",
    "form_said_after",
    "sent_files",
    "authored_things",
    "held_by_clauses",
    "taken_for_service",
    "format_reasons",
    "thing_wants",
    "sent_for_service",
    "booked_means",
    "taken_for_keeper",
    "signs_as_and",
    "withdrawn_thing",
    "role_appositives",
    "also_sent",
    "spelled_has_is",
    "consequence_boundaries",
    "told_then_asked",
    "caused_then_told",
    "numeral_ones",
    "announced_borrowings",
    "gapped_verbs",
    "named_later",
    "attributive_work",
    "purpose_modifier",
    "hyphened_description",
    "paper_parts",
    "file_subject",
    "emailed_paper",
    "picked_form",
    "carrying_particles",
    "hurried_errands",
    "namesake_surnames",
    "work_as_product",
    "products_listed",
    "something_from",
    "poured_vessels",
    "signed_on",
    "seating",
    "material_work",
    "lacked_purposes",
    "problem_remedy",
    "work_as_purpose",
    "contracted_needs",
    "due_service",
    "routed_work",
    "named_wants",
    "named_lacks",
    "announced_list",
    "wanting_idioms",
    "cleft_needs",
    "signature_put",
    "reported_requests",
    "possessive_places",
    "placed_things",
    "near_possessives",
    "beside_a_thing",
    "possessive_corrections",
    "accepted_owners",
]

_OFFICES: dict[str, Callable[[], Office]] = {
    "default": lambda: office_named("default"),
    "harbour": lambda: office_named("harbour"),
    "mail room": lambda: office_named("mail"),
    "courier room": courier_room,
    "chambers post": chambers_post,
    "costume shop": costume_shop,
    "law firm": law_firm,
    "music school": music_school,
    "gear studio": gear_office,
}

# Each step's example, a message it changes in one of the offices below.
EXAMPLES: dict[str, str] = {
    "pictographs": "bring me a pen and no marker 😩",
    "signed_off": "heat my lunch cheers",
    "undotted": "bring the book to Dr. Grace Huang",
    "restored_pauses": "my phone's on 3% can i borrow zhou's data cable",
    "outsider_pronoun": "a visitor needs his form stamped, can you do it",
    "when_clause": "when Wang is at the printer give him my file",
    "fallback": "bring me a stapler, or if there isn't one, scissors",
    "possessive_pronouns": "Wang and Zhou both sent slides. print hers and bring it to me",
    "question_preface": "frank question: who's got a stapler I could use tomorrow?",
    "hyphened_nouns": "could you bring me a pen for the warm-up drill?",
    "group_member": "bring me a cup please, one of the interns took mine",
    "excluded_owners": "could u bring me a stapler? anyone's but Wang's",
    "seated_subject": "the new guy at desk 4 needs a stapler, could you take him one",
    "thing_for_thing": "the DI box needs a fresh 9V battery, could you fetch me one?",
    "needed_done": "need my certificate photocopied, the auditors want one",
    "bare_rooms": "take the parcel down to meeting",
    "worked_rooms": "my badge isnt laminated, can you get it done in the badge office",
    "undone_services": "my badge hasn't been laminated yet, can you get it done",
    "placeholder": "bring me the thing from the fridge",
    "place_doers": "tore my apron, can laundry stitch it up?",
    "kept_copies": "can I grab two copies of the DI box",
    "run_off": "can you run off my report",
    "lent_verbs": "get my contract notarized",
    "unmarked_possessive": "can you get Wangs stapler for me",
    "chat_shorthand": "grab me a stapler, mine hav gone walkabout",
    "spelled_are": "mine r blunt, bring me a pen",
    "round_trip": "take my lunch to the kitchenette and bring it back",
    "approved_uses": "Pat ok'd me using her stamp, bring it",
    "hedged_leaves": "i hope mark won't mind if i borrow his ruler",
    "joined_gerunds": "would you mind laminating my badge, and getting my document signed",
    "form_said_after": "get me the rota numbers from Wang? She keeps them in a spreadsheet",
    "sent_files": "print the spreadsheet I sent",
    "authored_things": "can you send me the report Wang wrote",
    "held_by_clauses": "I need the stapler Zhang's got",
    "taken_for_service": "take my document to Wang to get it signed? need it back",
    "format_reasons": "scan my document, customs want a pdf",
    "thing_wants": "bring me a stapler, the register wants everything labelled",
    "sent_for_service": "can my document go to Wang to be signed?",
    "booked_means": "book a courier for my parcel",
    "taken_for_keeper": "my bow needs rehairing, take it to the store for Frank",
    "signs_as_and": "print my file + a coffee",
    "withdrawn_thing": "bring me a stapler and a pen. actually forget the stapler",
    "role_appositives": "get the duty manager, Wang, to sign my document",
    "also_sent": "print my report and also send it to Wang",
    "spelled_has_is": "Wang's gone to lunch",
    "consequence_boundaries": "my stapler's broken so can I borrow Wang's",
    "told_then_asked": "my phone is on 2% pls get me a charging lead",
    "caused_then_told": "get my swab tested the reading looked off on my kit",
    "numeral_ones": "coffee for me and 1 for Wang",
    "announced_borrowings": "I'm borrowing Wang's stapler for the afternoon",
    "gapped_verbs": "get Wang to sign my contract, and a coffee for me",
    "named_later": "Wang's budget plan? just send me the file",
    "attributive_work": "get Wang to send me his printing budget",
    "purpose_modifier": "Wang needs my stapler for the signature pages, can you take it to him",
    "hyphened_description": "Wang's setting-out file",
    "paper_parts": "My contract pages need stamping",
    "file_subject": "Wang's pdf of the stapler",
    "emailed_paper": "could I have Greta's brief? just email it to me",
    "picked_form": "Wang's document, the pdf one",
    "carrying_particles": "bring some up to reception",
    "hurried_errands": "Wang needs a stapler, can you run mine over to her",
    "namesake_surnames": "with Yang - Lei, not Liu",
    "work_as_product": "print my file and take the print-out to Mao",
    "products_listed": "copy my document and a printout",
    "something_from": "something from the vending machine",
    "poured_vessels": "a mug from the coffee machine please",
    "signed_on": "Lee here - bring me a pen",
    "seating": "Sue on reception needs a pen",
    "material_work": "need to cut some string for the parcel, got anything?",
    "lacked_purposes": "Hal has nothing to write with",
    "problem_remedy": "my coat is covered in dog hair, got anything to sort it out?",
    "work_as_purpose": "I've got 40 forms to sign and no pen",
    "contracted_needs": "Kit's after a torch",
    "due_service": "my document is due a print",
    "routed_work": "my lunch could do with a spin in the microwave",
    "named_wants": "Zhang would like a stapler",
    "named_lacks": "Wang has run out of paper",
    "announced_list": "Two things: a pen and a stapler",
    "wanting_idioms": "I'd murder a coffee",
    "cleft_needs": "it's a stapler I need",
    "signature_put": "could Mo put her signature on it",
    "reported_requests": "Zhang asked if someone could bring him a coffee",
    "possessive_places": "take this book to Wang's if he's in",
    "placed_things": "bring me the ruler at Mark's desk",
    "near_possessives": "put the ruler next to Mark's",
    "beside_a_thing": "leave the calculator beside Will's lamp",
    "possessive_corrections": "a stapler, not Wang's, Zhang's",
    "accepted_owners": "i need a pen. Lee's is fine",
}
# Each step's effect on its own example: (the office it is said in, words there before the
# step and gone after it, words there only after it, or "").
EFFECTS: dict[str, tuple[str, str, str]] = {
    "pictographs": ("default", "😩", ""),
    "signed_off": ("default", "cheers", ""),
    "undotted": ("default", "Dr.", "Dr Grace"),
    "possessive_pronouns": ("default", "print hers", "print her one"),
    "question_preface": ("default", "frank question:", ""),
    "hyphened_nouns": ("default", "warm-up", "the warmup drill"),
    "group_member": ("default", "one of the interns", "an intern took"),
    "excluded_owners": ("default", "anyone's but", "? not Wang's"),
    "seated_subject": ("default", "the new guy at desk 4", "Zhang Wei needs"),
    "thing_for_thing": ("gear studio", "needs a fresh", "me a fresh 9V battery for the DI box"),
    "needed_done": ("default", "need my", "get my"),
    "bare_rooms": ("courier room", "to meeting", "the Meeting room"),
    "worked_rooms": ("harbour", "the badge office", "in the laminator"),
    "undone_services": ("harbour", "get it done", "can you laminate it"),
    "place_doers": ("costume shop", "laundry stitch", "you stitch it up at the laundry"),
    "kept_copies": ("gear studio", "copies of the", "two DI boxes"),
    "run_off": ("default", "run off", "can you print my report"),
    "lent_verbs": ("law firm", "notarized", "sealed"),
    "restored_pauses": ("default", "3% can", "3%, can"),
    "outsider_pronoun": ("default", "needs his form", "the visitor's form"),
    "when_clause": ("default", "printer give", "printer, give"),
    "unmarked_possessive": ("default", "Wangs", "Wang's"),
    "chat_shorthand": ("default", " hav ", "mine have gone"),
    "spelled_are": ("default", " r ", "mine are blunt"),
    "round_trip": ("default", "bring it back", "heat my lunch"),
    "approved_uses": ("default", "ok'd", "said I could use"),
    "hedged_leaves": ("harbour", "mind if i", "mind, can i borrow"),
    "joined_gerunds": ("default", "getting", "and get my"),
    "form_said_after": ("default", "rota numbers from", "me Wang's spreadsheet?"),
    "sent_files": ("default", "I sent", "my spreadsheet"),
    "authored_things": ("default", "Wang wrote", "Wang's report"),
    "held_by_clauses": ("default", "Zhang's got", "Zhang's stapler"),
    "taken_for_service": ("default", "to Wang to", "signed by Wang"),
    "format_reasons": ("default", "customs", ""),
    "thing_wants": ("default", "register", ""),
    "sent_for_service": ("default", "go to Wang", "could Wang sign"),
    "booked_means": ("courier room", "book a courier", "by courier"),
    "taken_for_keeper": ("music school", "to the store", "could Frank rehair it"),
    "signs_as_and": ("default", "+", "file and a coffee"),
    "withdrawn_thing": ("default", "a stapler and", "bring me a pen"),
    "role_appositives": ("default", "duty manager", "get Wang to sign"),
    "also_sent": ("default", "send it", "forward it"),
    "spelled_has_is": ("default", "Wang's", "Wang is"),
    "consequence_boundaries": ("default", "broken so", "broken, so"),
    "told_then_asked": ("default", "2% pls", "2%, pls"),
    "caused_then_told": ("default", "tested the", "tested, the"),
    "numeral_ones": ("default", " 1 ", "one for Wang"),
    "announced_borrowings": ("default", "I'm borrowing", "can I borrow"),
    "gapped_verbs": ("default", "and a coffee", "and get a coffee"),
    "named_later": ("default", "plan?", "plan file?"),
    "attributive_work": ("default", "printing budget", "his budget"),
    "purpose_modifier": ("default", "signature pages", "for the pages"),
    "hyphened_description": ("default", "setting-out", "Wang's file"),
    "paper_parts": ("default", "pages", "contract need"),
    "file_subject": ("default", "of the stapler", ""),
    "picked_form": ("default", "the pdf one", "electronic file"),
    "carrying_particles": ("default", "up to", "some to reception"),
    "hurried_errands": ("default", "run mine over to", "take mine to"),
    "namesake_surnames": ("default", "not Liu", "Yang Lei"),
    "work_as_product": ("default", "the print-out", "the printout"),
    "products_listed": ("default", "document and", "document. and"),
    "something_from": ("default", "something", "a snack"),
    "poured_vessels": ("default", "from the coffee machine", "a mug of coffee"),
    "signed_on": ("default", "Lee here", "Bring me"),
    "seating": ("harbour", "on reception", "Sue needs"),
    "material_work": ("default", "need to cut", "need something to cut"),
    "lacked_purposes": ("default", "has nothing", "needs something"),
    "problem_remedy": ("costume shop", "anything to sort it out", "got a lint roller"),
    "work_as_purpose": ("default", "I've got", "no pen to sign"),
    "contracted_needs": ("default", "Kit's", "Kit is after"),
    "due_service": ("default", "is due", "needs a print"),
    "routed_work": ("default", "could do with a spin in", "put my lunch through the microwave"),
    "named_wants": ("default", "would like", "Zhang needs"),
    "named_lacks": ("default", "has run out of", "Wang needs paper"),
    "announced_list": ("default", "Two things", "I need a pen"),
    "wanting_idioms": ("default", "murder", "I need a coffee"),
    "cleft_needs": ("default", "it's a stapler", "I need a stapler"),
    "signature_put": ("default", "signature", "Mo sign it"),
    "reported_requests": ("default", "asked if", "bring Zhang"),
    "possessive_places": ("default", "Wang's if", "Wang if"),
    "placed_things": ("harbour", "at Mark's desk", "Mark's ruler"),
    "near_possessives": ("harbour", "next to", "at Mark's desk"),
    "possessive_corrections": ("default", "not Wang's", "a stapler, Zhang's"),
    "accepted_owners": ("default", "is fine", "Lee's please"),
}
# The steps that end the reading (what they say), or keep what is asked later.
STOPS = {"placeholder": ("default", "question"), "beside_a_thing": ("harbour", "decline")}
KEPT = {"emailed_paper": "chambers post"}
# The steps that take words out and say why in the reading's evidence (``Said.notes``).
NOTED = {"fallback": ("default", "scissors")}


@functools.cache
def _parser(name: str) -> InstructionParser:
    return InstructionParser(_OFFICES[name]())


def _requester(name: str) -> str:
    people = [p.id for p in _parser(name).office.people]
    return "lee" if "lee" in people else people[0]


def _step(name: str) -> Step:
    return next(s for s in STEPS if s.name == name)


def _recorded(surface: Surface) -> tuple[Surface, list[tuple[str, str, str | Said]]]:
    """``surface`` with each step's text before and what it gave recorded, in the order run."""
    seen: list[tuple[str, str, str | Said]] = []

    def recording(step: Step) -> Step:
        def rewrite(s: Surface, text: str, asked: Asked) -> str | Said:
            out = step.rewrite(s, text, asked)
            seen.append((step.name, text, out))
            return out

        return Step(step.name, rewrite)

    other = copy.copy(surface)
    other.steps = tuple(recording(s) for s in surface.steps)
    return other, seen


def _through(office: str, name: str, *, confirmed: bool = False) -> tuple[Said, str, str | Said]:
    """The stage's value for step ``name``'s example, and that step's text before and after."""
    surface, seen = _recorded(_parser(office).surface)
    said = surface(EXAMPLES[name], _requester(office), confirmed=confirmed)
    before, after = next((b, a) for n, b, a in seen if n == name)
    return said, before, after


def test_the_table_runs_in_the_order_the_parser_ran_the_rewrites() -> None:
    assert [s.name for s in STEPS] == ORDER
    assert list(EXAMPLES) == ORDER
    assert len(set(EXAMPLES.values())) == len(STEPS)


def test_the_parser_runs_the_table_first_every_step_in_order() -> None:
    parser = copy.copy(_parser("default"))
    parser.surface, seen = _recorded(parser.surface)
    assert parser.surface.steps != STEPS and _parser("default").surface.steps is STEPS
    frame = parser.parse("bring me a stapler please", "lee")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "stapler")]
    assert [name for name, _, _ in seen] == ORDER


def test_every_step_is_one_of_the_tested_ones() -> None:
    assert set(EFFECTS) | set(STOPS) | set(KEPT) | set(NOTED) == set(ORDER)


@pytest.mark.parametrize("name", sorted(NOTED))
def test_a_step_that_takes_words_out_says_so_in_the_evidence(name: str) -> None:
    office, gone = NOTED[name]
    said, before, after = _through(office, name)
    assert isinstance(after, Said) and after.stop is None and after.notes
    assert gone in before and gone not in after.text and said.notes == after.notes
    frame = _parser(office).parse(EXAMPLES[name], _requester(office))
    assert frame.evidence[: len(said.notes)] == list(said.notes)


@pytest.mark.parametrize("name", sorted(EFFECTS))
def test_each_example_is_changed_by_its_own_step(name: str) -> None:
    office, gone, now = EFFECTS[name]
    said, before, after = _through(office, name)
    assert isinstance(after, str) and after != before, (before, after)
    assert gone in before and gone not in after, (before, after)
    if now:  # "" where the step only takes words out
        assert now not in before and now in after, (before, after)
    assert said.stop is None


@pytest.mark.parametrize("name", sorted(STOPS))
def test_an_early_exit_ends_the_stage_with_what_it_says(name: str) -> None:
    office, said_as = STOPS[name]
    said, before, after = _through(office, name)
    assert isinstance(after, Said) and said.stop is not None
    assert getattr(said.stop, said_as), said.stop
    assert said.stop.tasks == [] and said.text == before
    # the parser answers with it, reading nothing further
    frame = _parser(office).parse(EXAMPLES[name], _requester(office))
    assert frame == said.stop


def test_the_emailed_paper_is_kept_to_be_asked_or_brought_on_a_yes() -> None:
    said, before, after = _through(KEPT["emailed_paper"], "emailed_paper")
    assert said.stop is None and said.emailed is not None
    assert isinstance(after, Said) and after.text == before == said.text
    assert said.emailed.question in (
        _parser("chambers post").parse(EXAMPLES["emailed_paper"], "nadia").question or ""
    )
    said, before, after = _through(KEPT["emailed_paper"], "emailed_paper", confirmed=True)
    assert said.emailed is None and isinstance(after, str)
    assert "email" in before and "email" not in after and "bring" in after


@pytest.mark.parametrize("office", ["default", "harbour"])
def test_a_text_no_step_touches_passes_unchanged(office: str) -> None:
    text = "bring me a stapler please"
    surface, seen = _recorded(_parser(office).surface)
    said = surface(text, _requester(office))
    assert said == Said(text)
    assert len(seen) == len(STEPS) and all(before == after for _, before, after in seen)
