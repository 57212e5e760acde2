"""How a simulated person reads a message: which item types, which requests and whose item.

This is the simulator's stand-in for a human reader. It reads the office's own tables, as a
colleague who works there would: item types and facilities by their names (longest first, so
"label printer" is a thing, not a request to print), then the office's operations by their
verbs and names as whole words with their ordinary endings ("print", "prints", "printed",
"printing" — never "printer"), longest phrase first whichever operation's ("3D print" before
"print"), then the English words of the person-to-person kinds (sign, seal) and of sending a
file. A request that names no operation and no thing but a machine that runs one ("could you
run my file through the 3D printer?") asks for that machine's operation.
"""

from __future__ import annotations

import re

from assistantx.core import english, language, task_kinds
from assistantx.core.office import Office, Operation
from assistantx.core.task_schema import FILE_KIND
from assistantx.memory.names import normalize

SEND_FILE_WORDS = english.kind_words(FILE_KIND)


def person_request_words() -> dict[str, tuple[str, ...]]:
    """The table's person-to-person kinds → the English words that signal them: a kind's own
    ``words``, else the package's English data file's; the office's own operations are
    signalled by their verbs, their names and their product's names (``request_words``)."""
    return {
        kind: task_kinds.kind(kind).words or english.kind_words(kind)
        for kind in task_kinds.person_kinds()
    }


def request_words(office: Office) -> dict[str, tuple[str, ...]]:
    """Request kind (or operation id) → the words that signal it, from the operation table."""
    words = person_request_words()
    for op in office.operations:
        if not office.runnable(op.id):
            continue
        # its verbs, not its display name: "print spine labels" names a label run whose
        # verb is "label"; its "print" is the printer's (Operation.request_phrases)
        found = [normalize(v) for v in op.request_phrases]
        if " " in op.name.strip():
            # the robot asks for it by its name ("could you send to the specialist cleaner
            # my coat?"); the whole phrase names this one service, never another's verb
            found.append(normalize(op.name))
        if op.product is not None:
            product = office.item_type(op.product)
            found += [normalize(n) for n in (product.name, *product.synonyms)]
        words[op.id] = tuple(w for w in dict.fromkeys(found) if w)
    words[FILE_KIND] = SEND_FILE_WORDS
    return words


def word_forms(word: str) -> tuple[str, ...]:
    """A word with its ordinary English endings: print → prints, printed, printing; bake →
    bakes, baked, baking; stop → stopped. Only the last word of a phrase is inflected."""
    head, _, last = word.rpartition(" ")
    lead = f"{head} " if head else ""
    stems = {last}
    if last.endswith("e"):
        stems.add(last[:-1])
    forms = {last, f"{last}s", f"{last}es", f"{last}d"}
    for stem in stems:
        forms.update({f"{stem}ed", f"{stem}ing"})
    if len(last) > 2 and last[-1] not in "aeiouwxy" and last[-2] in "aeiou":
        forms.update({f"{last}{last[-1]}ed", f"{last}{last[-1]}ing"})
    if last.endswith("y"):
        forms.update({f"{last[:-1]}ies", f"{last[:-1]}ied"})
    return tuple(f"{lead}{f}" for f in sorted(forms, key=len, reverse=True))


def _words(text: str) -> str:
    return f" {normalize(text)} "


def _names(office: Office, *, only_products: bool = False) -> list[tuple[str, str]]:
    """(name, item type id) for the item types' names (only the products'), longest first.
    A product is what an operation makes, whatever its kind: a scan sent as a PDF is an
    electronic item, and its name is often the operation's own verb ("scan"); read as a
    thing, the verb went with it and the keeper refused the work they run."""
    made = {op.product for op in office.operations if op.product is not None}
    pairs = [
        (normalize(n), t.id)
        for t in office.item_types
        if t.kind == "product" or t.id in made or not only_products
        for n in (t.id.replace("_", " "), t.name, *t.synonyms)
    ]
    return sorted((p for p in pairs if p[0]), key=lambda pair: -len(pair[0]))


def said_only_as_another(office: Office, text: str, type_id: str, others: set[str]) -> bool:
    """Whether every name of item type ``type_id`` that ``text`` says is also a name of one of
    the types ``others``: "your file" where a box file is also called a file and the office's
    electronic file is one of ``others`` may mean either, so it says nothing against them."""
    haystack = _without_full_names(office, _words(text))
    names = _names(office)
    own = {n for n, t in names if t == type_id}
    theirs = {n for n, t in names if t in others}
    said = {
        n
        for n in own
        if any(
            f" {v} " in haystack for v in dict.fromkeys((n, n + "s", n + "es", language.plural(n)))
        )
    }
    return bool(said) and said <= theirs


def mentioned_item_types(office: Office, text: str) -> list[str]:
    """Item types named in ``text`` (longest names first, so 'data cable' beats 'cable'),
    in the singular or the plural. A colleague's full name is a name, never a thing: "Viola
    Brandt's lunch" asks for the lunch where a viola is an instrument of the office."""
    haystack = _without_full_names(office, _words(text))
    found: list[str] = []
    for name, type_id in _names(office):
        # the plural English gives it too ("batteries", "knives"), beside the plain endings
        for variant in dict.fromkeys((name, name + "s", name + "es", language.plural(name))):
            if f" {variant} " in haystack:
                if type_id not in found:
                    found.append(type_id)
                haystack = haystack.replace(f" {variant} ", " ")
    return found


def _without_full_names(office: Office, haystack: str) -> str:
    for name in sorted((normalize(p.name) for p in office.people), key=len, reverse=True):
        if name and " " in name:
            haystack = haystack.replace(f" {name} ", " | ")
    return haystack


def mentioned_requests(office: Office, text: str) -> list[str]:
    """Request kinds the text mentions, in the order it mentions them. Things (item types
    other than products, facilities) are read first and taken out, so a word inside a thing's
    name ("printer" in "label printer", "stamp" in "stamped envelope") is not a request, nor
    is a word of a colleague's full name ("lend Frank Szabó your tape gun" where "frank" is
    the franking machine's verb)."""
    original = _without_full_names(office, _words(_without_destinations(office, text)))
    things = [n for n, _ in _names(office)]
    products = {n for n, _ in _names(office, only_products=True)}
    things += [normalize(n) for f in office.facilities for n in (f.name, *f.synonyms)]
    at: dict[str, int] = {}
    words = request_words(office)
    by_person = person_request_words()
    phrases = {
        form
        for kind in words
        if kind not in by_person and kind != FILE_KIND
        for w in words[kind]
        if " " in w
        for form in word_forms(w)
    }
    haystack = _without_things(original, things, products, phrases)
    # an operation asked for by its whole name ("could anyone print barcode labels") is
    # that one service: read before any of its words is taken for another's means or verb
    named_whole: list[str] = []
    for op in sorted(office.operations, key=lambda op: -len(op.name)):
        name = normalize(op.name)
        if " " in name and op.id in words and f" {name} " in haystack:
            at[op.id] = min(at.get(op.id, len(original)), original.find(f" {name} "))
            haystack = haystack.replace(f" {name} ", " | ")
            named_whole.append(name)
    haystack = _means_left_out(office, words, haystack)
    # the office's words are used up as they are read; a thing whose name holds a word of
    # work by hand ("date stamp", "signature pad") is taken out first, so lending it is no
    # request to seal or sign (a one-word name stays: "stamp my form" asks for the work)
    rest = _without_things(original, [n for n in things if " " in n], set(), phrases)
    for name in named_whole:
        rest = rest.replace(f" {name} ", " | ")
    # the longest phrase first, whichever operation's: "3d print" is the 3D printer's, not
    # the plotter's "print" inside it
    office_forms = sorted(
        (
            (form, kind)
            for kind in words
            if kind not in by_person and kind != FILE_KIND
            for form in (f for w in words[kind] for f in word_forms(w))
        ),
        key=lambda pair: -len(pair[0]),
    )
    said_as_verb = _product_names_said_as_verbs(office, haystack)
    for form, kind in office_forms:
        if f" {form} " in haystack and (form, kind) not in said_as_verb:
            at[kind] = min(at.get(kind, len(original)), original.find(f" {form} "))
            haystack = haystack.replace(f" {form} ", " | ")
            rest = rest.replace(f" {form} ", " | ")
    # an operation's one-word verb that is also its machine's name, said as the verb asked
    # for ("could you autoclave my glassware in the autoclave?"): the machine's name was
    # taken out as a thing, but the work is asked for all the same
    for kind, form in _verbs_named_as_machines(office, words, by_person):
        asked = re.search(rf" (?:you|please|pls|plz) {re.escape(form)} ", original)
        if asked is not None:
            at[kind] = min(at.get(kind, len(original)), asked.start() + 1)
    # the English words of signing, sealing and sending, in what the office's words left
    for kind in (*by_person, FILE_KIND):
        for form in (f for w in words[kind] for f in word_forms(w)):
            if f" {form} " in rest:
                at[kind] = min(at.get(kind, len(original)), original.find(f" {form} "))
    return sorted(at, key=lambda k: at[k])


def _product_names_said_as_verbs(office: Office, haystack: str) -> set[tuple[str, str]]:
    """(form, operation) pairs of a product's one-word name that the text says only in the
    verb's place, right after "you", "anyone" or "please": "could you spare Sam some of your
    lube" asks to lend, where "spare" is also a name of the key cutter's product (a spare key).
    The operation's own verbs are never in it ("could you duplicate my key")."""
    found: set[tuple[str, str]] = set()
    for op in office.operations:
        if op.product is None:
            continue
        verbs = {f for v in op.request_phrases for f in word_forms(normalize(v))}
        product = office.item_type(op.product)
        for name in (normalize(n) for n in (product.name, *product.synonyms)):
            if not name or " " in name or name in verbs:
                continue
            said = [m.start() for m in re.finditer(rf"(?<= ){re.escape(name)}(?= )", haystack)]
            if said and all(
                re.search(
                    r" (?:you|anyone|anybody|someone|somebody|please|pls|plz) $", haystack[:at]
                )
                for at in said
            ):
                found.update((form, op.id) for form in word_forms(name))
    return found


def _without_destinations(office: Office, text: str) -> str:
    """``text`` without the place a send-out service is asked to send to ("could you courier
    Bo's proof *to the print works at Felling*?"): from the "to" after the service's verb and
    its object to the end of the sentence (never the "to" of the service's own phrase: "send
    to the cleaners"). A colleague reads which work is asked from the verb; a word of
    another service inside the place's name ("print") asks for nothing."""
    verbs = {
        form
        for op in office.operations
        if op.sends_out and office.runnable(op.id)
        for phrase in op.request_phrases
        for form in word_forms(normalize(phrase).split()[0])
        if normalize(phrase)
    }
    if not verbs:
        return text
    alternatives = "|".join(re.escape(v) for v in sorted(verbs, key=len, reverse=True))
    return re.sub(rf"(?i)(\b(?:{alternatives})\s+(?!to\b)[^.?!;]*?)\bto\b[^.?!;]*", r"\1", text)


def facility_requests(office: Office, text: str) -> list[str]:
    """The operation a request names only by its machine ("could you run my file through
    the 3D printer?"): of each facility named (longest names first), its one operation the
    assistant can run; none for a facility that runs several, or none."""
    haystack = _words(text)
    found: list[str] = []
    names = sorted(
        ((normalize(n), f) for f in office.facilities for n in (f.name, *f.synonyms)),
        key=lambda pair: -len(pair[0]),
    )
    for name, facility in names:
        if not name or f" {name} " not in haystack:
            continue
        haystack = haystack.replace(f" {name} ", " | ")
        runs = [op for op in facility.operations if office.runnable(op)]
        if len(runs) == 1 and runs[0] not in found:
            found.append(runs[0])
    return found


# Before a thing's name, words that make it the thing: "at *the* heat press".
_DETERMINERS = r"(?:the|a|an|my|your|our|their|his|her|this|that)"


def _verbs_named_as_machines(
    office: Office, words: dict[str, tuple[str, ...]], by_person: dict[str, tuple[str, ...]]
) -> list[tuple[str, str]]:
    """(request kind, word form) for each one-word verb of an operation that is also the
    name of a facility ("autoclave", "microwave")."""
    machines = {normalize(n) for f in office.facilities for n in (f.name, *f.synonyms)}
    return [
        (kind, form)
        for kind in words
        if kind not in by_person and kind != FILE_KIND
        for w in words[kind]
        if " " not in w
        for form in word_forms(w)
        if form in machines
    ]


def _without_things(text: str, things: list[str], products: set[str], verbs: set[str]) -> str:
    """``text`` with the things it names taken out, longest first; a product's name stays
    whole, even where a shorter thing's name is inside it ("sample" in "sample board"); a
    thing named like an operation's phrase ("heat press") is the thing only after a
    determiner ("at the heat press"), else the work asked for ("could you heat press it")."""
    kept: list[str] = []
    for name in sorted((n for n in {*things, *products} if n), key=len, reverse=True):
        for variant in (name, name + "s", name + "es"):
            if f" {variant} " not in text:
                continue
            if name in products:  # held aside until the things are out
                text = text.replace(f" {variant} ", f" \x00{len(kept)} ")
                kept.append(variant)
            elif variant in verbs:
                text = re.sub(rf" ({_DETERMINERS}) {re.escape(variant)} ", r" \1 | ", text)
            else:
                text = text.replace(f" {variant} ", " | ")
    for n, variant in reversed(list(enumerate(kept))):
        text = text.replace(f" \x00{n} ", f" {variant} ")
    return text


# The words between a making verb and what it makes: "print *me some new* labels".
_BETWEEN = r"(?:(?:a|an|the|some|me|us|my|our|your|new|more|extra|fresh|\d+) )*"


def _means_left_out(office: Office, words: dict[str, tuple[str, ...]], haystack: str) -> str:
    """``haystack`` without the verbs that are only the means of making another operation's
    named product ("print spine labels", "get a staff card printed"): the product says
    which operation is asked for, as a colleague reads it, not the printer's verb."""
    for op in office.operations:
        if op.product is None or op.id not in words:
            continue
        names = _names_of_product(office, op)
        for other in office.operations:
            if other.id == op.id or other.id not in words:
                continue
            if op.input is not None and op.shape(office) != other.shape(office):
                continue  # "print a copy of my file": the copier's product, not its run
            made = _product_names(office, other)
            for verb in (f for w in other.request_phrases for f in word_forms(normalize(w))):
                if f" {verb} " not in haystack:
                    continue  # both patterns need the verb as a word: no regex to build
                if verb in made:
                    continue  # "print labels": "labels" is the label run's product, no verb
                for name in names:
                    # the verb may be gone (replaced by an earlier name), and both patterns
                    # need the name too: test first, as there are more patterns than re's
                    # cache keeps
                    if f" {verb} " not in haystack or name not in haystack:
                        continue
                    noun = rf"{re.escape(name)}(?:s|es)?"
                    haystack = re.sub(rf" {re.escape(verb)} (?={_BETWEEN}{noun} )", " | ", haystack)
                    haystack = re.sub(rf" ({noun}) {re.escape(verb)} ", r" \1 | ", haystack)
    return haystack


def _names_of_product(office: Office, op: Operation) -> list[str]:
    """The names of what ``op`` makes ("label", "sticker"), normalized, in the file's order."""
    if op.product is None:
        return []
    product = office.item_type(op.product)
    return list(dict.fromkeys(n for n in map(normalize, (product.name, *product.synonyms)) if n))


def _product_names(office: Office, op: Operation) -> frozenset[str]:
    """The names of what ``op`` makes ("labels", "label"), as the haystack spells them."""
    names = _names_of_product(office, op)
    return frozenset(form for n in names for form in (n, n + "s", n + "es"))


def possessor(office: Office, text: str, *, reader: str) -> str | None:
    """The person (not the reader) whose item the text names: "Zhang Wei's lunch" → zhang."""
    lowered = text.casefold().replace("’", "'")
    # the longest name that stands before the "'s" is whose: "Anna Lee's lunch" is Anna Lee's,
    # not the lunch of a colleague whose given name is Lee
    best: tuple[int, str] | None = None
    for person in office.people:
        if person.id == reader:
            continue
        names = {person.id, person.name, *person.aliases, person.name.split()[0]}
        for name in names:
            if re.search(rf"(?<!\w){re.escape(name.casefold())}'s\b", lowered):
                if best is None or len(name) > best[0]:
                    best = (len(name), person.id)
    return best[1] if best else None


def is_question(text: str) -> bool:
    t = normalize(text)
    return "?" in text or t.startswith(("can ", "could ", "would ", "do ", "does ", "are ", "is "))


def asks_to_do(text: str) -> bool:
    """Whether a message asks its reader to do something ("could you ...", "please ..."),
    not only about something ("is the 3D printer free?")."""
    return (
        re.search(r"\b(?:could|can|would|will) (?:you|anyone)\b|\bplease\b", text, re.I) is not None
    )


def asks_to_receive(text: str) -> bool:
    """Whether a message asks its reader to be there to receive something: a person answers
    that about themselves (whether they will be at their desk), whatever thing is named; an
    office whose item is called "delivery" or "parcel" must not turn it into a loan."""
    words = _words(text)
    return any(f" {form} " in words for form in word_forms("receive"))
