"""Question: "who has a tape measure?", "is the printer working?": answered from what the
office file says; one that may be a request in disguise ("does anyone have a stapler?") is
answered and met with "Shall I bring you one?"."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.agents.symbolic.reading.screen.elliptical import elliptical_ask, spare_asked
from assistantx.agents.symbolic.reading.screen.facility_state_asked import in_service
from assistantx.agents.symbolic.reading.screen.findings import UNANSWERED, Finding
from assistantx.agents.symbolic.reading.screen.kept_at_place import kept_at, place_asked
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.rewrites import purposes
from assistantx.agents.symbolic.reading.screen.spare_of import spare_of, spares_only
from assistantx.agents.symbolic.reading.screen.terms import Terms, article, who_has
from assistantx.agents.symbolic.reading.speech import content
from assistantx.agents.symbolic.reading.used_today import used_later_today
from assistantx.core import wording


def question(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    kind = piece.acts.question
    if kind != "info" or asks_for_purpose(terms, msg, piece):
        return None
    if elliptical_ask(terms, msg, piece):
        return None  # "got a light meter? want to check the flash": a request, kept
    items = purpose_item(terms, piece) or terms.named(piece.lexed, "item")
    facilities = terms.named(piece.lexed, "facility")
    people = terms.named(piece.lexed, "person")
    spare = spares_only(piece) and not items and not facilities and not people
    if spare and len(spare_of(terms, msg, piece)) == 1:
        # "my pen's run out... any spares around?": a spare of the pen said before it
        items = spare_of(terms, msg, piece)
    if len(items) == 1 and not facilities:
        found = item_question(terms, piece, items[0], requester)
        if piece.acts.doubts_ability and found.offer:
            # "can you even carry ...?": yes, said first; the errand only on a yes
            message = f"Yes, I can do that. {found.message}"
            return Finding(
                found.verdict,
                piece,
                found.meaning,
                message=message,
                offer=found.offer,
                shall=found.shall,
            )
        return found
    if facilities:
        message = in_service(terms, facilities[0])
    elif len(people) == 1:
        p = terms.office.person(people[0])
        where = terms.office.location(p.location).name
        message = f"{p.name} works at {where}; I can't see whether they are there right now."
    elif (spare_asked(piece) or spare) and not any(
        terms.named(p.lexed, "item") for p in msg.pieces
    ):
        # "anyone got a spare?" with no thing said anywhere: answered in words, asking back
        message = "Which item do you need a spare of? Tell me and I'll get you one."
        return Finding("question", piece, "an ask for a spare, of no thing said", message=message)
    else:
        thing = terms.unknown_thing(piece.words)
        if not thing:
            message = f"I can't answer that from what I know. {terms.capabilities()}"
            return Finding("question", piece, UNANSWERED, message=message)
        message = f"I don't know of any {thing} in this office."
    return Finding("question", piece, "a question, answered in words", message=message)


def asks_for_purpose(terms: Terms, msg: Message, piece: Piece) -> bool:
    """ "got anything I can trim this ribbon with? bring it over": a question for a thing
    named by its purpose, which one item type of the office is declared for, then a request
    that names no thing of its own: the question says what the request's "it" is, so it is
    left in the request (the rewrite reads the purpose as the item)."""
    _, found = purposes(terms, piece.text)
    if not found:
        return False
    later = [p for p in msg.pieces if p.start > piece.end and p.acts.request]
    return bool(later) and not any(m.kind == "item" for p in later for m in p.lexed.mentions)


def purpose_item(terms: Terms, piece: Piece) -> list[str]:
    """The item type a question names by its purpose ("anything I can trim this with?")."""
    rewritten, found = purposes(terms, piece.text)
    return terms.named(terms.lex.read(rewritten), "item") if found else []


def item_question(terms: Terms, piece: Piece, item: str, requester: str) -> Finding:
    t = terms.office.item_type(item)
    owners = [o for o in terms.office.owners_of(item, known_only=True) if o != requester]
    asked = [p for p in terms.named(piece.lexed, "person") if p != requester]
    names = [terms.office.person(o).name for o in owners[:4]]
    makers = [f for f in terms.office.facilities if item in f.products]
    supplier = terms.office.supplier(item)
    whose = ""
    a_thing = wording.a_thing(t.name, mass=t.mass)  # "some gloves"
    if says_mine(piece.lexed, item):  # "did anyone find my umbrella?"
        answer = f"I don't know where your {t.name} is; I can't see it from here."
        return Finding("question", piece, "a question, answered in words", message=answer)
    if len(asked) == 1:  # "does Hope have a calculator?"
        who = terms.office.person(asked[0]).name
        if asked[0] in owners:
            answer, whose = f"As far as I know, {who} has {a_thing}.", f"{who}'s"
        else:
            answer = f"As far as I know, {who} has no {t.name}."
    elif makers:
        where = terms.office.location(makers[0].location).name
        answer = (
            f"The {makers[0].name} at the {where} makes {wording.them_or_it(t.name, mass=t.mass)}."
        )
    elif supplier is not None:  # "any AAs going spare?": the cupboard's, anyone's to have
        answer = f"{wording.there_is(t.name, mass=t.mass)} in the {supplier.name}."
    elif names:
        answer = who_has(names, a_thing)
    else:
        answer = f"I don't know of anyone here with {a_thing}."
    place = place_asked(piece.lexed) if not asked else None
    if place is not None:
        # "any wipes in the kitchenette?": what is kept there; who has one elsewhere after
        there, kept = kept_at(terms.office, item, *place)
        answer = there if kept else f"{there} {answer}"
    if t.kind not in ("belonging", "product"):  # a document, a file: not for me to tell
        answer = f"I can't tell that about the {t.name} from what I know."
        return Finding("question", piece, "a question, answered in words", message=answer)
    verb = "get" if t.kind == "product" else "bring"
    if piece.acts.later and not used_later_today(content(piece.words)):
        # "... I could use tomorrow?": a need for later is answered, with the offer for
        # then in words; nothing is fetched now and no question is left open on it ("...
        # I need this afternoon?" is had by then, so answered and offered for now)
        one = wording.some_or_one(t.name, mass=t.mass)
        message = f"{answer} Tell me when you need it and I'll {verb} you {one} then."
        meaning = "a question about a later need, answered"
        return Finding("question", piece, meaning, message=message)
    shall = f"Shall I {verb} you {wording.some_or_one(t.name, mass=t.mass)}?"
    return Finding(
        "question",
        piece,
        "a question that may be a request: answered, then asked",
        message=answer,
        offer=f"{verb} me {whose or article(t.name)} {t.name}",
        shall=shall,
    )


def says_mine(lexed: Lexed, item: str) -> bool:
    """ "did anyone find *my* umbrella?" (not "lend *me* a ruler": the asker's want)."""
    tokens, mentions = lexed.tokens, lexed.mentions
    return any(
        m.kind == "item"
        and m.ids == (item,)
        and n
        and mentions[n - 1].kind == "self"
        and tokens[mentions[n - 1].start].word in ("my", "mine")
        for n, m in enumerate(mentions)
    )
