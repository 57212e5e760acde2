"""The rewrites that make what is left readable by the later stages: a thing named by its
purpose ("something to cut this with") becomes the office's item declared for it, "another
one" after a stated condition becomes that item, a pronoun the facts pin to one person gets
the name back, a dangling possessive ("lend him mine") gets its item."""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.her_or_hers import giving_her_in, kept_from_her
from assistantx.agents.symbolic.reading.lexicon import Lexed, Mention
from assistantx.agents.symbolic.reading.screen.contrast import CHOSEN
from assistantx.agents.symbolic.reading.screen.described_one import described_ones
from assistantx.agents.symbolic.reading.screen.elided_possessive import (
    elided_item,
    things_named,
)
from assistantx.agents.symbolic.reading.screen.facility_report import LACKED
from assistantx.agents.symbolic.reading.screen.kept import kept_thing
from assistantx.agents.symbolic.reading.screen.own_one import own_ones
from assistantx.agents.symbolic.reading.screen.pieces import Message
from assistantx.agents.symbolic.reading.screen.purpose_object import (
    PARTICLES,
    noun_only,
    object_nouns,
    purpose_words,
    said_as_declared,
    used_on,
)
from assistantx.agents.symbolic.reading.screen.service_input import worked_on
from assistantx.agents.symbolic.reading.screen.statement import ONE_HELD
from assistantx.agents.symbolic.reading.screen.terms import Terms, article
from assistantx.agents.symbolic.reading.screen.thanks import THANKED
from assistantx.agents.symbolic.reading.speech import NEED_PHRASES
from assistantx.agents.symbolic.reading.tokens import Token, gaps
from assistantx.agents.symbolic.reading.vocative import addressed_person
from assistantx.core import english, language
from assistantx.core.asked_to_have import asked_to_have, caused_for
from assistantx.core.handed_owner import carried_to
from assistantx.core.task_schema import Evidence, Hint
from assistantx.memory.names import normalize

_HAS_ASKED = re.compile(r"(\w)['’]s\s+asked\b", re.IGNORECASE)


def rewrite(
    terms: Terms, msg: Message, text: str, hints: list[Hint], context: list[str]
) -> tuple[str, list[Evidence]]:
    evidence: list[Evidence] = []
    # "Rhys has a spare one": the item a statement's "one" stood for, had by its subject
    held = {c.removeprefix(ONE_HELD) for c in context if c.startswith(ONE_HELD)}
    # "thanks for the milk earlier! could you bring a bit more": more of the thing thanked for
    thanked = [c.removeprefix(THANKED) for c in context if c.startswith(THANKED)]
    context = [c for c in context if not c.startswith(THANKED)]
    context = [c.removeprefix(ONE_HELD) for c in context]
    # what a facility was said to lack: a "some" may stand for it, never an "it"
    lacked = [f"{c.removeprefix(LACKED)}|" for c in context if c.startswith(LACKED)]
    context = [c for c in context if not c.startswith(LACKED)]
    text, found = purposes(terms, text, unmet=True)
    evidence += found
    text, found = kept_things(terms, msg, text)
    evidence += found
    text, found = container_of_named(terms, msg, text)
    evidence += found
    # "jonno's asked for ...": the "'s" of "has", so the need's subject is Jonno
    text = _HAS_ASKED.sub(r"\1 has asked", text)
    for phrase in NEED_PHRASES:  # "Chen is looking for a pen": Chen needs a pen
        spaced = r"[\s']*".join(re.escape(w) for w in phrase)
        text = re.sub(rf"\b{spaced}\b", "needs", text, flags=re.IGNORECASE)
    subjects = {c.removeprefix("person:") for c in context if c.startswith("person:")}
    said_of = {h.person for h in hints if h.kind in _SAID_OF and h.person}
    holder = _holder_of_last(terms, subjects | said_of, context, held)
    told = [c for c in context if not c.startswith(("person:", "product:", CHOSEN))]
    text = name_pronouns(terms, msg, text, hints, subjects - holder, holder, bool(told))
    text, found = dangling_possessives(terms, msg, text)
    evidence += found
    text, found = products_said_before(terms, text)
    evidence += found
    said = [
        f"{h.item_type}|"
        for h in hints
        if h.kind == "condition" and h.item_type and h.value != "not wanted"
    ]
    said += lacked
    chosen = [c.removeprefix(CHOSEN) for c in context if c.startswith(CHOSEN)]
    if chosen:
        text, found = chosen_kind(terms, text, chosen[-1])
        evidence += found
    stated = [c for c in context if not c.startswith(("person:", "product:", CHOSEN))]
    products = [c.removeprefix("product:") for c in context if c.startswith("product:")]
    said += stated
    # "my contract's got coffee on it, could you photocopy it": of the things stated, the one
    # the service asked takes
    worked = worked_on(terms, text, stated) if len(set(stated)) > 1 else None
    if worked is not None:
        said.append(worked)
    if said and not terms.names_an_item(text):
        item, _, whose = said[-1].partition("|")
        thing = terms.office.item_type(item).name
        # "the stapler is for Wang, bring it to him": "it" is the stated item, and
        # "Gao asked for my scissors, bring them to her": mine
        # Two things stated ("Lena has a loupe and Noor has a bone folder, bring it"): "it"
        # could be either, so it is left for the frames, which ask which one
        # One kind stated again by "one" ("Ivy's headset died. Rhys has a spare one"): "it"
        # is the one said last, the one that can still be brought
        again = (
            bool(stated) and stated[-1] in held and len({s.partition("|")[0] for s in stated}) == 1
        )
        one_stated = len(set(stated)) == 1 or again or worked is not None
        last = worked if worked is not None else stated[-1] if stated else None
        back = ("it", "them") if stated and said[-1] == last and one_stated else ()
        # "bring me a clean one": its describing words name no other thing, another one
        text = described_ones(text, terms.lex.items)
        # "someone else's" first: its "one" is no "one" of its own
        for phrase in (*terms.en.others_ones, *terms.en.another_one, "some", *back):
            pattern = re.compile(rf"\b{re.escape(phrase)}\b", re.IGNORECASE)
            match = pattern.search(text)
            if match:
                kept = phrase in back and whose
                said_as = f"{whose} {thing}" if kept else f"a {thing}"
                if kept and (made := made_from(terms, item, [*stated, *products])) is not None:
                    said_as += f" as {made}"  # "labels are in my file, run them off"
                meaning = said_as if kept else f"another {thing}"
                evidence.append(Evidence(words=match.group(0), meaning=meaning))
                text = text[: match.start()] + said_as + text[match.end() :]
                break
        else:
            text, found = container_of(terms, text, thing)
            evidence += found
    elif len(thanked) == 1 and not terms.names_an_item(text):
        text, found = more_of_thanked(terms, text, thanked[0])
        evidence += found
    return text, evidence


def more_of_thanked(terms: Terms, text: str, item: str) -> tuple[str, list[Evidence]]:
    """ "could you bring a bit more" after thanks for the milk: a milk, read as asked for;
    a request with no such words keeps its reading."""
    thing = terms.office.item_type(item).name
    for phrase in terms.en.another_one:
        match = re.search(rf"\b{re.escape(phrase)}\b", text, re.IGNORECASE)
        if match:
            evidence = [Evidence(words=match.group(0), meaning=f"more {thing}")]
            return text[: match.start()] + f"a {thing}" + text[match.end() :], evidence
    return text, []


# "his yr9 scheme of work would you": a possessive, then up to six words to the clause's end
_OWN_THING = re.compile(
    r"\b(my|his|her|their|our|\w+['’]s)\s+((?:[\w-]+\s+){0,5}?[\w-]+)"
    r"(?=\s*(?:[,.!?;]|$|\s+(?:would you|could you|will you|please|thanks|for me|to me|asap|"
    r"today|now)\b))",
    re.IGNORECASE,
)


def chosen_kind(terms: Terms, text: str, item: str) -> tuple[str, list[Evidence]]:
    """ "get José to send me his yr9 scheme of work, the file not a printout": a thing of
    someone's the office has no word for, beside a contrast that chose one of the office's
    kinds, is that kind ("his electronic file"); a request that names an item keeps it."""
    if terms.names_an_item(text):
        return text, []
    for match in _OWN_THING.finditer(text):
        words = match.group(2)
        tokens = terms.lex.tokens(words)
        if any(m.kind != "word" for m in terms.lex.scan(tokens)):
            continue  # a person, a place, a service: not an unnamed thing
        name = terms.office.item_type(item).name
        said = f"{match.group(1)} {name}"
        evidence = [Evidence(words=match.group(0), meaning=said)]
        return text[: match.start()] + said + text[match.end() :], evidence
    return text, []


def kept_things(terms: Terms, msg: Message, text: str) -> tuple[str, list[Evidence]]:
    """ "bring me Jürgen's leftover curry from the staff fridge": a thing of a person's the
    office has no word for, said to be at a facility (or a place) that keeps one item of
    theirs, is that item ("Jürgen's lunch box"); several kept there are asked about by the
    screen's ``kept`` rule. Whose it is stays theirs: the owner is asked before it moves."""
    found = kept_thing(terms, msg.lexed, text)
    if found is None or len(found.kept) != 1:
        return text, []
    name = terms.office.item_type(found.kept[0]).name
    meaning = f"{terms.office.person(found.owner).name}'s {name} (kept at {found.where})"
    evidence = [Evidence(words=text[found.start : found.end], meaning=meaning)]
    return text[: found.start] + name + text[found.end :], evidence


def made_from(terms: Terms, item: str, stated: list[str]) -> str | None:
    """ "the new labels are ready in my file, run them off": the one product a statement
    names beside the item "them" stands for, that an operation of the office makes from that
    item; the request makes it, so the product picks the operation."""
    named = {c.partition("|")[0] for c in stated}
    made = {
        op.product
        for op in terms.office.operations
        if op.input == item and op.product is not None and op.product in named
    }
    if len(made) != 1:
        return None
    return terms.office.item_type(next(iter(made))).name


def container_of(terms: Terms, text: str, thing: str) -> tuple[str, list[Evidence]]:
    """ "I ran out of forms. Could you bring me a box?": a noun this office does not know,
    asked for right after a statement that named an item, is a quantity of that item."""
    pattern = re.compile(r"\b(?:a|an|one|another)\s+([a-z]+)\b", re.IGNORECASE)
    for match in pattern.finditer(text):
        noun = match.group(1).lower()
        if terms.names_at(text[match.start(1) :]) or not language.is_noun(noun):
            continue
        if language.zipf(noun) < 3 or noun in ("one", "bit", "lot"):
            continue
        if compound_head(text[match.end() :]):
            continue  # "a power bank": a thing of its own, not a quantity of the item
        evidence = [Evidence(words=match.group(0), meaning=f"a {noun} of {thing}")]
        return text[: match.start()] + f"a {thing}" + text[match.end() :], evidence
    return text, []


# A container or measure a thing is counted in ("a box", "a roll", "a ream", "a handful"):
# its unit nouns and the portions of a thing, less the words that count no container
_CONTAINERS = (english.words("unit_nouns") | english.words("portion_words")) - frozenset(
    {"one", "ones", "couple", "few"}
)
# what ends an exclamation or a fragment said alone ("tape!!!", "staples...", "gloves -")
_FRAGMENT_END = re.compile(r"\s*(?:[.!?;…]+|\s[-–—]+)\s*")
_ASKED_ONE = re.compile(r"\b(?:a|an|one|another)\s+([a-z]+)\b", re.IGNORECASE)


def container_of_named(terms: Terms, msg: Message, text: str) -> tuple[str, list[Evidence]]:
    """ "tape!!! a roll from the cupboard please", "staples... grab me a box from the
    cabinet": a thing named first and alone, as an exclamation or a fragment (a piece that is
    only an item's name, ended as a sentence is), then a container or measure of no name of
    the office asked for after it ("a roll", not "a roll of tape", nor "a power bank") is
    that much of the thing named: the container is said as the thing and the fragment drops.
    Only a thing counted so is: a supply used up, stuff, or a plural said ("pens!"), never
    one singular thing ("stapler! a box"). A container asked for with nothing named before it
    is left as said."""
    first = next((p for p in msg.pieces if p.words), None)
    if first is None or not _named_alone(first.lexed):
        return text, []
    item = first.lexed.mentions[0].ids[0]
    kind = terms.office.item_type(item)
    if not (kind.consumable or kind.mass or language.is_plural_noun(first.text.lower())):
        return text, []  # "stapler! a box": no box holds one stapler
    lead = len(text) - len(text.lstrip())
    if not text[lead:].startswith(first.text):
        return text, []
    end = _FRAGMENT_END.match(text, lead + len(first.text))
    if end is None:
        return text, []
    rest = text[end.end() :]
    for match in _ASKED_ONE.finditer(rest):
        noun = match.group(1).lower()
        if terms.names_an_item(rest[: match.start()]):
            break  # another thing named between: the container may be of that one
        after = rest[match.end() :]
        if noun not in _CONTAINERS or terms.names_at(rest[match.start(1) :]):
            continue
        if re.match(r"\s+of\b", after, re.IGNORECASE) or compound_head(after):
            continue  # "a box of pens", "a bag clip": what it holds is said, or its own thing
        thing = kind.name
        said = f"{article(thing)} {thing}"
        words = f"{first.text} ... {match.group(0)}"
        evidence = [Evidence(words=words, meaning=f"a {noun} of {thing}")]
        return rest[: match.start()] + said + after, evidence
    return text, []


def _named_alone(lexed: Lexed) -> bool:
    """Whether a piece's words are all one item's name, read as that item alone."""
    mentions = [m for m in lexed.mentions if m.kind != "word"]
    if len(mentions) != 1:
        return False
    m = mentions[0]
    return (
        m.kind == "item"
        and len(m.ids) == 1
        and not m.possessive
        and m.start == 0
        and m.end == len(lexed.tokens)
    )


def dangling_possessives(terms: Terms, msg: Message, text: str) -> tuple[str, list[Evidence]]:
    """ "lend him mine", "give him Rich's", "borrow Priya's for me": a possessive with no
    item after it (the clause ends, or whom it is for, "back" or "over" follows; "mine"
    anywhere) means the item named last before it (in what is left, else in the whole
    message); "for the exam" after "Rich's" is a purpose, which leaves it alone."""
    evidence: list[Evidence] = []

    def last_item(before: str, word: str) -> str | None:
        tokens = terms.lex.tokens(before)
        items = things_named(tokens, terms.lex.scan(tokens))  # never "to lunch": when
        if items:
            return terms.office.item_type(items[-1].ids[0]).name
        # not in this piece: the nearest thing named before it in the whole message ("my
        # stapler's broken, can I have Wang's? and a coffee": the stapler, not the coffee)
        found = elided_item(msg.lexed, word)
        if found is not None:
            return terms.office.item_type(found).name
        items = [m for m in msg.lexed.mentions if m.kind == "item"]
        return terms.office.item_type(items[-1].ids[0]).name if items else None

    # "Zoe, mind if I borrow yours?": "yours" is the addressed colleague's, as "your ruler"
    # is there (reading/vocative.py); said to nobody in particular it is left as it was
    lexed = msg.lexed
    addressed = addressed_person(lexed.tokens, lexed.mentions, gaps(lexed.text, lexed.tokens))
    pronouns = {"mine": "my", **({"yours": "your"} if addressed is not None else {})}

    def whole(match: re.Match[str]) -> str:
        word = match.group(1)
        owner = re.sub(r"['’]s$", "", word)
        pronoun = pronouns.get(word.lower())
        if word.lower() in ("mine", "yours") and pronoun is None:
            return word
        if pronoun is None and not terms.is_person_word(owner):
            return word
        if pronoun is not None and _subject(text[match.end() :]):
            return word  # "mine ran out in June": what it says of mine, not an object
        thing = last_item(text[: match.start()], word)
        if thing is None:
            return word
        said = f"{pronoun} {thing}" if pronoun is not None else f"{word} {thing}"
        evidence.append(Evidence(words=word, meaning=said))
        return said

    # "mine" is never followed by its noun, so wherever it stands ("take mine down to Hattie
    # in repro", with "her" already named back) it is the requester's own item of the kind
    # named last; "Rich's" is a possessive only where no noun can follow it
    # ... and so is one followed by "to" and a colleague's name ("take Dawn's to Mark", or
    # "to him" with the name put back by ``name_pronouns``)
    # ... and so is one followed by how long it is had ("borrow Zoe's for the afternoon"):
    # how long is no thing to get, so it is read away after a colleague's possessive
    # "some of mine", "a few sheets of mine": "mine" after a quantity (and the word that
    # counts it) is the requester's item of the kind named last, so the requester stays its
    # owner ("some of my paper"); "a friend of mine" counts nothing and is left as said
    def part(match: re.Match[str]) -> str:
        thing = last_item(text[: match.start()], "mine")
        if thing is None or _subject(text[match.end() :]):
            return match.group(0)
        many, noun = match.group("many"), match.group("noun")
        if noun and not terms.names_at(noun):
            many = f"{many} {noun}"  # "a few sheets": the word that counts it stays
        # a counting word that names the item itself ("sheets" of paper) is said once
        said = f"{many} my {thing}" if many.lower().endswith(" of") else f"{many} of my {thing}"
        evidence.append(Evidence(words=match.group(0), meaning=said))
        return said

    text = _PART_OF_MINE.sub(part, text)
    # "take him my spare one": the requester's own thing of the kind named last, as "mine"
    text, found = own_ones(text, terms.lex.items, lambda before: last_item(before, "my"))
    evidence += found
    spans = re.compile(rf"\b(\w+['’]s)\s+{_SPAN}\b(?!\s*['’]s)", re.IGNORECASE)
    text = spans.sub(
        lambda m: (
            m.group(1) if terms.is_person_word(re.sub(r"['’]s$", "", m.group(1))) else m.group(0)
        ),
        text,
    )
    pattern = re.compile(
        r"(?<!\bof\s)\b(mine\b|yours\b|\w+['’]s(?=\s*(?:[,.!?;]|$|\s+(?:please|too|instead|then|if|"
        r"and|or|for now|for a bit|for today|(?:(?:down|up|over|round|across)\s+)?(?:for|to) "
        r"(?:me|us|him|her|them)|(?:(?:down|up|over|round|around|across|along)\s+)?to [A-Z]\w+|"
        r"back|over)\b)))",
        re.IGNORECASE,
    )
    return pattern.sub(whole, text), evidence


# "we need a new label, can you print one": "one" after the verb of a service (and whom it
# is for) stands for the one product named before it, not for a second thing
_ONE_MADE = re.compile(
    r"\b(?P<verb>[a-z]+)(?P<whom>\s+(?:me|us))?\s+(?P<one>one|some)\b(?!\s+(?:of|more|else)\b)",
    re.IGNORECASE,
)


def products_said_before(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """ "we need a new label for bed 4, can u print one": the "one" a service's verb makes is
    the office's product named before it (one kind of product named, and no other item), so
    the verb asks for that product rather than for a second thing of its own (the requester's
    file printed). Any other "one" is left as it was."""
    office = terms.office
    verbs = {normalize(v).split()[0] for op in office.operations for v in op.verbs if v.strip()}
    evidence: list[Evidence] = []

    def one(match: re.Match[str]) -> str:
        if match.group("verb").lower() not in verbs:
            return match.group(0)
        named = {
            i
            for m in terms.lex.read(text[: match.start()]).mentions
            if m.kind == "item"
            for i in m.ids
        }
        if len(named) != 1:
            return match.group(0)
        made = office.item_type(next(iter(named)))
        if made.kind != "product" or not any(op.product == made.id for op in office.operations):
            return match.group(0)
        said = f"{match.group('verb')}{match.group('whom') or ''} a {made.name}"
        evidence.append(Evidence(words=match.group(0), meaning=said))
        return said

    return _ONE_MADE.sub(one, text), evidence


# "for the afternoon", "for an hour", "for a few minutes": how long, never a purpose
_SPAN = (
    r"for\s+(?:(?:"
    + "|".join(sorted(english.words("span_fillers")))
    + r")\s+){0,4}(?:"
    + "|".join(sorted(english.words("span_words"), key=len, reverse=True))
    + ")"
)


# what follows a subject: "mine's broken", "mine is", "mine ran out"; "mine" may stand for
# several ("mine have gone blunt", "mine are at home", "mine've walked off")
_SUBJECT_VERBS = frozenset(
    {"s", "is", "was", "has", "had", "does", "did", "will", "wont", "isnt", "wasnt", "hasnt"}
    | {"are", "were", "have", "do", "re", "ve", "arent", "werent", "havent", "dont", "doesnt"}
    | {"didnt", "can", "cant", "could", "couldnt", "would", "wouldnt", "keep", "need", "d", "ll"}
)


def _subject(after: str) -> bool:
    """Whether the words after "mine" make it the subject of a verb ("mine ran out", "mine
    just died": an adverb may stand between)."""
    return any(w in _SUBJECT_VERBS or language.is_finite_verb(w) for w in language.words(after)[:2])


def name_pronouns(
    terms: Terms,
    msg: Message,
    text: str,
    hints: list[Hint],
    subjects: set[str],
    holder: frozenset[str] = frozenset(),
    things_told: bool = False,
) -> str:
    """ "Zhang is at his desk. Get him to sign ...", "Pat hurt her hand, take her my ice
    pack": with the fact taken out, a pronoun that can only mean the one person it named
    gets the name back. Where another person is named before it ("Thảo's on the ladder and
    Ivy's free, take her a stool"), whom it goes to is left to the frames, which ask; whose
    it is ("bring Zhou her stapler. It's Zhang Wei's stapler") is still the one the facts
    name. "she"/"he" asked to have a thing ("Lin's running the stall - could she have my
    stickers?") is that one person too: the one it is given to. ``holder``: who has the
    thing the statements name last ("Rhys has a spare one"), never whom the pronoun means;
    ``things_told``: the statements told of things, not only of people ("Zhang's lunch is in
    the fridge"), so they do not say a "bring her lunch" is to her."""
    people = {h.person for h in hints if h.kind in _SAID_OF}
    people = (people | subjects) - holder
    if len(people) != 1:
        return text
    person = next(iter(people))
    name = terms.office.person(person).name
    others_before = _named_before_pronoun(msg) - people - holder

    def named(match: re.Match[str]) -> str:
        word, gap, following = match.group(1).lower(), match.group(2), match.group(3)
        # "her stapler", and "at her desk": a place of hers (``place_words``) is hers too,
        # so the one named receives there ("Gao is out of paper, drop some at her desk"),
        # never "at Gao Min desk", a place nobody has
        possessive = word == "his" or (
            word == "her"
            and (normalize(following) in terms.lex.items or following.lower() in _PLACE_WORDS)
        )
        if others_before and not possessive:
            return match.group(0)
        kind = terms.lex.items.get(normalize(following), "")
        # her thing kept away from her (her lunch in the fridge), or one made for her ("bring
        # her coffee": a product nobody owns, so "her" can only be whom it is for)
        made = bool(kind) and terms.office.item_type(kind).kind == "product"
        to_her = made or (kind and kept_from_her(terms.office, person, kind))
        if possessive and word == "her" and to_her and giving_her_in(text, match.start()):
            # "Zhang can't get away, bring her lunch": the sentences before are about her, so
            # the thing goes to her ("bring Zhang Wei her lunch"); with someone else named or
            # her things told of, nothing decides, and the frames ask (``her_or_hers``)
            if others_before or things_told:
                return match.group(0)
            return f"{name} {match.group(1)}{gap}{following}"
        return (f"{name}'s" if possessive else name) + gap + following

    def having(match: re.Match[str]) -> str:
        # "Lin's running the stall - could she have my stickers?": the one to be given it
        # (``asked_to_have``), said by the pronoun of the one person named before
        after = language.words(match.group(4))
        before = match.group(1).lower()
        if others_before or not (asked_to_have(before, after[:4]) or caused_for(before, after)):
            return match.group(0)
        return match.group(1) + match.group(2) + name

    text = re.sub(
        r"\b(\w+)(\s+)(she|he)\b(?=((?:\s+[\w'’]+){1,9}))", having, text, flags=re.IGNORECASE
    )
    return re.sub(r"\b(him|his|her)\b(\s*)(\w*)", named, text, flags=re.IGNORECASE)


_BACK_PRONOUNS = frozenset({"him", "his", "her"})
_PART_OF_MINE = re.compile(
    r"\b(?P<many>(?:"
    + "|".join(sorted(english.words("partitive_quantities"), key=len, reverse=True))
    + r")(?:\s+of)?)(?:\s+(?P<noun>[a-z]+))?\s+of\s+mine\b",
    re.IGNORECASE,
)
_PLACE_WORDS = english.words("place_words")
# the facts said of a person that a pronoun may point back to
_SAID_OF = frozenset({"availability", "location", "condition"})


def _holder_of_last(
    terms: Terms, subjects: set[str], context: list[str], held: set[str]
) -> frozenset[str]:
    """ "Ivy's headset died. Rhys has a spare one, bring it to her": of the several people
    the statements are about, the one the last statement says has "one" (Rhys), who is not
    whom "her" means (the thing is theirs already). One person only, no "one" said last, or
    nobody's: nobody."""
    stated = [c for c in context if not c.startswith(("person:", "product:", CHOSEN))]
    if len(subjects) < 2 or not stated or stated[-1] not in held:
        return frozenset()
    whose = stated[-1].partition("|")[2].removesuffix("'s")
    holders = frozenset(p for p in subjects if terms.office.person(p).name == whose)
    return holders if len(holders) == 1 else frozenset()


def _named_before_pronoun(msg: Message) -> set[str]:
    """Everyone a name before the message's first "him/his/her" may mean: not the one a thing
    is taken from ("take Dawn's calculator to him", "take some from Jack to him"), who has it
    and is its source, never whom it is taken to."""
    tokens = msg.lexed.tokens
    mentions = msg.lexed.mentions
    first = next((n for n, t in enumerate(tokens) if t.word in _BACK_PRONOUNS), len(tokens))
    return {
        person
        for n, m in enumerate(mentions)
        if m.kind == "person" and m.start < first and not _source(tokens, mentions, n)
        for person in m.ids
    }


def _source(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> bool:
    """Whether the person ``mentions[n]`` is said as whom a thing comes from: its owner right
    before it ("Dawn's calculator", "Dawn's to him") or after "from" ("from Jack")."""
    m = mentions[n]
    if m.start and tokens[m.start - 1].word == _FROM:
        return True
    if not m.possessive or m.end >= len(tokens):
        return False
    if carried_to([t.word for t in tokens], m.end) is not None:
        # "take Dawn's to him", "take May's over to her": the bare possessive of the thing
        # said before, carried to someone else (``core.handed_owner``; "back to her" is not)
        return True
    after = mentions[n + 1] if n + 1 < len(mentions) else None
    return after is not None and after.start == m.end and after.kind == "item"


_FROM = "from"


_POSSESSIVE = re.compile(r"['’]s$")
# Words that open the object of a purpose's verb ("to cut *this* ribbon with").
_OBJECT_OPENERS = english.words("object_starts") | frozenset({"that"})


# A possessive right before the purpose's head: "her thing for ...", "Isla's gadget for ...".
_OWNER_BEFORE = re.compile(r"(?:\b(?:my|our|your|his|her|their)|[^\W\d_]['’]s?)\s+$", re.IGNORECASE)


def purposes(terms: Terms, text: str, *, unmet: bool = False) -> tuple[str, list[Evidence]]:
    """``text`` with a thing said by its purpose ("something to cut this with") as the item
    declared for it; ``unmet``: where no item is, the purpose's object dropped (what it would
    be used on is no thing asked for: "something to mop up *the coffee*")."""
    heads = "|".join(re.escape(h) for h in sorted(terms.en.purpose_heads, key=len, reverse=True))
    links = "|".join(re.escape(h) for h in sorted(terms.en.purpose_links, key=len, reverse=True))
    pattern = re.compile(
        rf"\b(?:{heads})\s+(?:{links})\s+([a-z]+)((?:\s+[a-z0-9]+(?:['’]s)?)*)", re.IGNORECASE
    )
    evidence: list[Evidence] = []
    match = pattern.search(text)
    if match is None:
        return text, evidence
    verb = stem(match.group(1).lower())
    tail = match.group(2).split()

    def declared(phrase: str) -> list[str]:
        # "open a parcel" is the declared "open parcels", "get dog hairs off" "get hair off"
        return [
            t.name
            for t in terms.office.item_types
            if any(said_as_declared(phrase, purpose(p)) for p in t.purposes)
        ]

    # "something to check continuity with": the object of a declared purpose is part of it
    said = purpose_words(declared, verb, tail)
    keep = object_nouns(tail, said)  # "check the tread *wear*": the object goes on
    while keep < len(tail) and tail[keep].lower() in terms.en.purpose_tail:
        keep += 1
    # "anything I can trim *this ribbon with*": the purpose's own object, up to its "with",
    # is part of the phrase (the ribbon is what is trimmed, never what is brought)
    with_at = next(
        (j for j in range(keep, min(len(tail), keep + 4)) if tail[j].lower() == "with"), None
    )
    if keep and with_at is not None and tail[keep - 1].lower() in _OBJECT_OPENERS | PARTICLES:
        # "anything I can trim *this ribbon with*", "to cut my pots off *the wheel with*": the
        # rest, up to the tool's "with", says what it works on and where
        keep = with_at + 1
    elif keep and keep < len(tail) and tail[keep - 1].lower() in _OBJECT_OPENERS:
        keep += 1  # "something to charge my phone": the phone is charged, never brought
        while keep < len(tail) and _POSSESSIVE.search(tail[keep - 1]):
            keep += 1  # "off a guest's coat": whose, then the thing it acts on, never brought
        # "on the lift control panel": the nouns after the first go on naming where it is
        # used, never left glued to the thing found ("a multimeter control panel")
        while keep < len(tail) and _more_of_the_noun(tail[keep - 1], tail[keep]):
            keep += 1
    if not keep and tail and _bare_object(tail[0]):
        # "something to cut ribbon with": a bare noun after the verb is what it works on,
        # its "with" the tool's; left behind it was glued to the tool ("a scissors ribbon")
        keep = 1
        while keep < len(tail) and _more_of_the_noun(tail[keep - 1], tail[keep]):
            keep += 1
        if keep < len(tail) and tail[keep].lower() == "with":
            keep += 1
    if keep:
        keep = _past_contents(tail, keep)
    used_tail = " ".join(tail[:keep])
    end = match.start(2) + (
        len(match.group(2)) - len(match.group(2).lstrip()) + len(used_tail) if keep else 0
    )
    # "to write on" (paper) before "to write" (pen, "to write with"); "to check continuity"
    # (a multimeter) before "to check"
    types = declared(" ".join([verb, *(w.lower() for w in tail[:said])]))
    if not types and unmet:
        # "something to mop up the coffee I spilled" with nothing declared for it: what it
        # is used on is no thing asked for; the parser asks what is meant
        return _without_object(text, match.start(), evidence)
    if len(types) != 1:
        return text, evidence  # several: the parser asks which item
    name = types[0]
    evidence.append(Evidence(words=text[match.start() : end], meaning=f"a {name} (to {verb})"))
    # "her thing for opening cases", "Isla's thing for ...": the owner said is its
    # determiner, so no article ("her a case opener" read "her" as whom it is for)
    before = text[: match.start()]
    owned = _OWNER_BEFORE.search(before) is not None
    return before + (name if owned else f"a {name}") + text[end:], evidence


# -- helpers -------------------------------------------------------------------------


_WORD = re.compile(r"\S+")
_PUNCTUATION = ".,!?;:"


def _without_object(text: str, at: int, evidence: list[Evidence]) -> tuple[str, list[Evidence]]:
    """``text`` without the object of the verb of the purpose said at ``at`` ("the coffee" of
    "something to mop up the coffee"), said back in the evidence as what it is used on."""
    spans = list(_WORD.finditer(text, at))
    used = used_on([m.group().lower().strip(_PUNCTUATION) for m in spans])
    if used is None:
        return text, evidence
    start = spans[used.start].start()
    last = spans[used.stop - 1]
    end = last.start() + len(last.group().rstrip(_PUNCTUATION))
    said = text[start:end]
    return text[:start] + text[end:], [*evidence, Evidence(words=said, meaning="used on")]


_PHRASE_ENDS = english.words("common")


# What a purpose's object may end on, said last ("something to weigh this bag on"): the thing
# found is what it is done on or with, never a word of its own
_STRANDED = frozenset({"on", "in", "into", "onto", "under", "with", "over"})
_CONTENT_DETERMINERS = frozenset({"the", "my", "our", "these", "those", "this", "that"})


def _past_contents(tail: list[str], keep: int) -> int:
    """``keep`` moved past what the purpose's object holds ("this bag *of nails*": the nails
    are weighed in their bag, never a thing asked for) and past a preposition left at the
    end ("to weigh this bag of nails *on*")."""
    while keep + 1 < len(tail) and tail[keep].lower() == "of":
        k = keep + 1
        if tail[k].lower() in _CONTENT_DETERMINERS:
            k += 1
        w = tail[k].lower() if k < len(tail) else ""
        if not w.isalpha() or w in _PHRASE_ENDS or not language.is_noun(w):
            break  # "of" then a noun ("coins", also a verb's form): what the object holds
        keep = k + 1
        while keep < len(tail) and _more_of_the_noun(tail[keep - 1], tail[keep]):
            keep += 1
    if keep == len(tail) - 1 and tail[keep].lower() in _STRANDED:
        keep += 1
    return keep


def _bare_object(word: str) -> bool:
    """Whether ``word``, right after a purpose's verb, is a bare noun that verb acts on
    ("cut *ribbon*"): a noun only, never a function word, a particle or a verb's form."""
    w = word.lower()
    if _POSSESSIVE.search(word) or w in _PHRASE_ENDS or not w.isalpha():
        return False
    return noun_only(w)


def _more_of_the_noun(before: str, word: str) -> bool:
    """Whether ``word`` goes on the noun phrase ``before`` ends (a noun after a noun: "lift
    *control* *panel*"); a possessive ends the phrase's noun it owns, a function word or a
    verb's form ("needs") ends it."""
    w = word.lower()
    if _POSSESSIVE.search(before) or w in _PHRASE_ENDS or not w.isalpha():
        return False
    return language.is_noun(w) and not language.is_finite_verb(w)


def stem(word: str) -> str:
    """'cutting' → 'cut', 'writes' → 'write', 'stapling' → 'staple' (the verb's lemma, from
    the morphology library; a word it does not know as a verb stays as it is)."""
    w = word.lower()
    found = language.verb_lemmas(w)
    return min(found, key=len) if found else w


def purpose(phrase: str) -> str:
    first, _, rest = phrase.lower().partition(" ")
    return f"{stem(first)} {rest}".strip()


def compound_head(after: str) -> bool:
    """Whether the word right after a noun is a noun that heads a compound with it ("a power
    *bank*"), not a time word or a courtesy ("a box today", "a box please")."""
    nxt = language.words(after)[:1]
    if not nxt or not after[:1].isspace():
        return False
    found = language.lemmas(nxt[0])
    return "NOUN" in found and "ADV" not in found
