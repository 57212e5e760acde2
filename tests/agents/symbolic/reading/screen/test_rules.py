"""The table: every verdict has its rule, tried in priority order; the first match decides."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.rules import RULES
from assistantx.agents.symbolic.reading.screen.terms import Terms
from reading.screen._judge import Read


def test_the_rules_in_priority_order() -> None:
    assert [verdict for verdict, _ in RULES] == [
        "withdrawn",
        "note",
        "exclusion",
        "exclusion",  # "not her camera" after one colleague was named
        "which",  # "she needs the umbrella" with nobody named: whom "she" means is asked
        "which",  # "my lamp" where two of the speaker's things are lamps
        "which",  # two things as alternatives ("the stapler? or the scissors, not sure which")
        "statement",  # a purpose or open offer cut off ("so he can book ...", "if anyone needs it")
        "statement",  # the reason for a request ("..., need it for the report")
        "statement",  # a reason naming a service as its topic ("..., need the laundry numbers")
        "statement",  # why the colleague a request names needs it ("..., he needs it for his file")
        "statement",  # what the colleague given to will do ("..., she needs to check my results")
        "statement",  # what someone wants to know ("a visitor wants to know the coffee prices")
        "statement",  # the things to use a tool asked for on ("..., a pile of letters to seal")
        "statement",  # a count of things, why it is asked ("..., like 20 letters going out")
        "statement",  # a past event of the speaker's own thing ("..., mine went in the compost")
        "statement",  # news of someone no colleague ("Blaze flew brilliantly today")
        "statement",  # a contrast of kinds beside a request ("the file not a printout")
        "statement",  # a hedged view of what a thing needs ("imo the room could use a table")
        "wish",
        "wish",  # a hope about a colleague ("really hope Otto gets his phone back")
        "thanks",
        "thanks",  # an acknowledgement said back ("crystal clear, thanks!", "will do")
        "statement",  # a fragment of news, its things after prepositions ("2 mins to the lure")
        "statement",  # how a question beside it is meant ("just curious", "no rush")
        "statement",  # a moment asked for ("give me a min to find another", "hang on a tick")
        "statement",  # an event and its time after a request ("..., ground run in 10")
        "statement",  # the speaker's own plan, told ("might heat my soup a bit later")
        "condition",
        "statement",  # what a told state rules out ("printer's down, so no printing")
        "negated",
        "destructive",  # an unsafe act: fire, a false alarm ("set light to Reed's banner")
        "destructive",  # a running machine opened ("..., I know it's still brewing")
        "statement",  # what the speaker will do with the thing asked for ("..., need to eat it")
        "unsupported",  # a facility asked for work it does not do ("shred it in the printer")
        "unsupported",  # a test the office lacks, asked by a generic verb ("run an NMR on it")
        "unsupported",  # a service's verb said of a drink the office makes ("shred my coffee")
        "destructive",
        "unsupported",  # acting as a colleague ("take Pat's card and log into her account")
        "unsupported",  # the workplace's card for a private use ("..., to fill my own car")
        "unsupported",  # a send to an account outside ("to my personal gmail")
        "unsupported",  # an absent owner's yes said for them ("Otto is away, ... he won't mind")
        "unsupported",  # behind the owner's back ("borrow Zhang's stapler without telling him")
        "unsupported",  # against a colleague ("disable Pat's badge so she can't get in")
        "unsupported",  # every one of a kind colleagues own ("wipe all the drives")
        "unsupported",  # into a colleague's closed things ("unlock Wang's drawer and take ...")
        "unsupported",  # a place outside ("... to the applicant's house on Elm Road")
        "unsupported",  # ordering from outside ("order us some sandwiches for the meeting")
        "statement",  # the speaker's own doing beside a request ("need to check the contacts"),
        # before its place ("..., need to check levels on L2") is read as a placement
        "statement",  # a colleague's own doing beside a request ("needs to measure a box")
        "statement",  # a colleague's own plan beside a request ("..., she'll frank it later")
        "statement",  # why a colleague's whereabouts are asked ("where's X? need a word ...")
        "unplaced",  # a thing put where nothing of the office is, by a verb that is no errand
        "unplaced",  # a request cut off mid-sentence ("can you take my tray to")
        "unsupported",  # a thing put in a vehicle or a home ("put my book in my car")
        "statement",  # the reason after an elliptical ask ("got a loupe? want to check ...")
        "statement",  # who deals with a fault ("..., Wang is on it"), before it is a whereabouts
        "fact",
        "statement",  # when someone will be back ("back in an hour"), no thing to fetch
        "statement",  # a facility said to be in some state ("scanner's jammed btw")
        "statement",  # a fault told with its auxiliary dropped ("printer jammed again")
        "statement",  # an owner's leave to keep their thing ("Wang can keep my stapler")
        "statement",  # a thing of an occasion beside a request ("need a copy of the new signing")
        "statement",  # a service's participle after a request ("... Running minipreps in 10")
        "statement",  # a need of the requester's own ("I need the tripod" after a fetch)
        "statement",  # a colleague's thing to send out ("Dev's contract needs couriering")
        "question",  # a facility's state asked with no verb ("laminator working today?")
        "question",  # where a thing is kept ("where do we keep the clay?"), in words
        "question",
        "question",  # the choices said with a question ("..., workshop store or dry store?")
        "statement",  # a problem reported after a question about a facility's state
        "statement",
        "statement",  # something on a thing, verbless ("oil on the stapler again")
        "statement",  # where an item is ("fyi the tape's in the cupboard")
        "statement",  # where it is not, beside a where-question ("where's X? not on his desk")
        "statement",  # an obligation on nobody named ("someone should ring the engineer")
        "statement",  # told for information beside a tag ("..., just so you know")
        "statement",  # a told sentence before a request that names its own thing
        "which",  # one of several things kept for their owner ("Jürgen's curry from the fridge")
        "which",  # one of a colleague's several things by a word for a kind ("one of X's tools")
        "unsupported",  # a made thing in a variant not made here (asked: "instead"), or above it
        "instead",  # a kind of a made thing the office names plainly ("a flat white"): asked
        "instead",  # a kind of machine the office lacks ("the raku kiln"): asked
        "unsupported",  # a service nothing here offers, before an outsider is asked about
        "unsupported",  # work no verb of the reader names ("polish my boots"; "sort out": asked)
        "instead",  # a colleague asked to run a facility they do not ("get Zhang to copy it")
        "instead",  # a means of sending out the office lacks ("go out with the courier")
        "instead",  # a recipient who is nobody of the office ("the courier guy")
    ]


def first_verdict(terms: Terms, message: Read, text: str) -> str | None:
    msg = message(text)
    for _, rule in RULES:
        found = rule(terms, msg, msg.pieces[0], "lee")
        if found is not None:
            return found.verdict
    return None


def test_the_first_rule_that_matches_decides(terms: Terms, message: Read) -> None:
    # "don't" negates, but the wish about other people is tried first
    assert first_verdict(terms, message, "don't let anyone use my pen") == "wish"
    assert first_verdict(terms, message, "don't bring me a pen") == "negated"
    assert first_verdict(terms, message, "bring me a pen") is None  # a request: no rule
