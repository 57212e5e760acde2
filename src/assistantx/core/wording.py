"""Names for what people read: items, people and places by name, never by internal id.

Internal ids (``stapler:wang``, ``desk_03``, ``ins-1f…``) are for memory, traces and the API;
every text a person receives (messages, QR instructions, dashboard status lines) goes through
these helpers. Unknown ids degrade to readable words (underscores to spaces), never to an
id with a colon.
"""

from __future__ import annotations

from assistantx.core import language, task_kinds
from assistantx.core.english import words
from assistantx.core.office import FILE_WORD, Office, Operation
from assistantx.core.task_schema import kind_shape

# What the person does at the locker, per code purpose ({item}: an ``item_phrase``): moving
# the item in and out, and each task kind's work step from the table of kinds. The purposes
# that run an office operation on the item are worded with the office's own operation by
# ``purpose_text``; the table's line is only the fallback for an office without one.
_MOVE_TEXT = {
    "deposit": "put {item} into the locker",
    "collect": "take {item} out of the locker",
}


def locker_text(purpose: str) -> str | None:
    """The table's line for ``purpose`` (the item in or out, or a kind's work step)."""
    if purpose in _MOVE_TEXT:
        return _MOVE_TEXT[purpose]
    return next((k.locker for k in task_kinds.kinds() if k.purpose == purpose and k.locker), None)


def purpose_text(
    office: Office,
    purpose: str,
    item_id: str,
    *,
    you: str | None = None,
    operation: str | None = None,
    destination: str | None = None,
    send_to: str | None = None,
) -> str:
    """What the person does at the locker for a code of ``purpose`` on ``item_id``, in the
    office's words: "take your document out, scan it and put the original and the scan back"
    where the office's operation of the copy shape is a scan; "take Lee's form out and fax it
    to the county tax office" where it sends the item outside (``destination``); a file the
    work makes goes to its owner by message, or to ``send_to`` by name ("send the PDF to
    Wang Fang"): the operator learns whom only from these words."""
    thing = item_phrase(office, item_id, you=you)
    shape = kind_shape(purpose)
    op = _operation_on(office, shape, item_id.partition(":")[0], you) if shape else None
    if operation is not None and shape is not None:  # the one the code is for (scan, not copy)
        op = office.operation(operation)
    if op is None or shape not in ("transform", "treat"):
        return (locker_text(purpose) or "{item}").format(item=thing)
    if shape == "transform" and op.product and office.item_type(op.product).electronic:
        made = office.item_type(op.product).name  # a PDF goes by message, not into the locker
        whom = "its owner"
        if send_to is not None and send_to != item_id.partition(":")[2]:
            whom = person_name(office, send_to, you=you)
            whom = "yourself" if whom == "you" else whom
        return f"take {thing} out, {verb_it(op)}, send the {made} to {whom} and put it back"
    if shape == "transform":
        return f"take {thing} out, {verb_it(op)} and put the original and the {op.name} back"
    if not op.returns_item:  # shredded, faxed out: nothing goes back into the locker
        to = destination if op.sends_out and destination else None
        return f"take {thing} out and {verb_it(op, to)}"
    return f"take {thing} out, {verb_it(op)} and put it back"


def verb_it(
    op: Operation, destination: str | None = None, *, bare: bool = False, obj: str = "it"
) -> str:
    """An operation said with "it" for its object, in English whatever its name looks like:
    "fax it", "laser print it", "send it off"; a name that carries its own place ("send to
    the lab") puts "it" after its verb ("send it to the lab"), and a ``destination`` said
    replaces that place ("courier it to the Axiom lab"); ``bare``: without that place, for a
    question of where ("Where should I send it to?"). A name of several words where the
    office declares verbs is said by its first verb ("courier"). ``obj``: another object
    than "it" ("test masks", "courier blood samples"), said where "it" would be."""
    phrase = op.verbs[0] if " " in op.name.strip() and op.verbs else op.name
    return with_object(phrase, obj, destination, bare=bare, made=product_words(op))


def product_words(op: Operation) -> frozenset[str]:
    """The words of what the operation makes ("banner" of a "print a banner" that makes
    banners): where its name's own object is one of them, the name says what is made, not
    what is worked on (``with_object``)."""
    return frozenset(op.product.lower().replace("_", " ").split()) if op.product else frozenset()


def with_object(
    phrase: str,
    obj: str,
    destination: str | None = None,
    *,
    bare: bool = False,
    made: frozenset[str] = frozenset(),
) -> str:
    """A verb phrase of an operation ("send off", "send to the lab", "print") with ``obj``
    put where English puts it: after the verb and before a particle ("send it off"), before
    the phrase's own complement ("send it to the lab"), else after the phrase ("laser print
    it"); ``destination`` replaces the own complement, ``bare`` leaves it out. A name whose
    own object is what it makes (``made``: "print a banner") keeps it, and the thing worked on
    comes after "from" ("print a banner from Amber's file")."""
    said = phrase.split()
    if not said:
        return f"do {obj}"
    openers = words("verb_complement_openers")
    cut = next((k for k in range(1, len(said)) if said[k].lower() in openers), len(said))
    head, own = _without_own_object(said[:cut], made), said[cut:]
    particles = words("verb_particles")
    if _names_what_it_makes(said[:cut], made):
        spoken = [*head, "from", obj]  # "print a banner from Amber's file"
    elif all(w.lower() in particles for w in head[1:]):
        spoken = [head[0], obj, *head[1:]]  # "send it off"
    else:
        spoken = [*head, obj]  # "laser print it"
    if destination:
        spoken += ["to", destination]
    elif not bare:
        spoken += own
    return " ".join(spoken)


def _own_object_at(said: list[str]) -> int:
    """Where the object an operation's name carries of its own begins (it opens with an
    article or a possessive, ``object_starts``); the name's length where it has none."""
    starts = words("object_starts")
    return next((k for k in range(1, len(said)) if said[k].lower() in starts), len(said))


def _names_what_it_makes(said: list[str], made: frozenset[str]) -> bool:
    """Whether the name's own object is what the operation makes: after an article ("print
    a banner"), or bare, where every word after the verb is a word of the product ("print
    barcode labels" that makes barcode labels; "laser print" stays a verb)."""
    if not made:
        return False
    if {w.lower() for w in said[_own_object_at(said) :]} & made:
        return True
    rest = {w.lower() for w in said[1:]}
    singular = {w[:-1] if w.endswith("s") and w not in made else w for w in rest}
    return bool(rest) and said[0].lower() not in made and singular <= made


def _without_own_object(said: list[str], made: frozenset[str] = frozenset()) -> list[str]:
    """An operation's name cut before the object it names of its own ("patch a tube", "wash
    the mugs", "polish a trumpet": the verb alone): the real thing said after the verb takes
    its place, never beside it ("patch a tube Miles's inner tube" is no English). A name with
    none ("make coffee", "laser print") is kept whole, and so is one whose object is what it
    makes (``made``: "print a banner" says which work it is; the thing comes after "from")."""
    if _names_what_it_makes(said, made):
        return said
    return said[: _own_object_at(said)]


def operation_verb(name: str, made: frozenset[str] = frozenset()) -> str:
    """The operation's name as the verb of a phrase whose object follows it ("patch" of
    "patch a tube"; "print" and "make coffee" as they are; "print a banner from" where the
    banner is what it makes, ``made``)."""
    said = name.split()
    if _names_what_it_makes(said, made):
        return f"{name} from"
    return " ".join(_without_own_object(said)) or name


def works_on(op: Operation, things: str) -> str:
    """What an operation does said with the things it works on, in English whatever its name
    looks like: "laminate papers", "spin down samples" (a particle stays with its verb),
    "send samples to the lab", "patch inner tubes" (the name's own object is the thing worked
    on, said as the office names it), and "run an IR on samples" (the name's own object is
    the work, kept, and the things come after "on")."""
    said = op.name.split()
    made = product_words(op)
    openers = words("verb_complement_openers")  # "send to the lab": no object of its own
    cut = next((k for k in range(1, len(said)) if said[k].lower() in openers), len(said))
    own = said[_own_object_at(said[:cut]) : cut]
    if own and not _names_what_it_makes(said, made) and not _same_thing(own, things.split()):
        return f"{op.name} on {things}"
    particles = words("verb_particles")
    if len(said) > 1 and all(w.lower() in particles for w in said[1:]):
        return f"{op.name} {things}"  # "spin down samples"
    return with_object(op.name, things, made=made)


def _same_thing(own: list[str], things: list[str]) -> bool:
    """Whether an operation name's own object ("a tube") names the things said ("inner
    tubes"): a noun of one is a noun of the other, one or several."""

    def nouns(said: list[str]) -> set[str]:
        return {n for w in said for n in (w.lower(), *language.lemmas(w.lower()).get("NOUN", ()))}

    return bool(nouns(own[1:]) & nouns(things))


def things_worked_on(name: str) -> str:
    """An item type's name as the things a machine works on, in general: several of them
    ("samples", "bills of lading"), as it is where it is plural already or stuff ("papers",
    "data")."""
    if language.is_plural_noun(name) or language.is_mass_noun(name):
        return name
    return language.head_plural(name) or language.plural(name)


def verb_alone(op: Operation) -> str:
    """An operation's verb as said with no object of its own ("things I can courier"): its
    name where that is one word, else its first declared verb, else its name's verb before
    its own complement ("send" of "send to the lab")."""
    if " " not in op.name.strip():
        return op.name
    if op.verbs:
        return op.verbs[0]
    said = op.name.split()
    openers = words("verb_complement_openers")
    cut = next((k for k in range(1, len(said)) if said[k].lower() in openers), len(said))
    return " ".join(said[:cut])


def by_means(op: Operation) -> str:
    """How a send-out is named after "by" ("by fax", "by courier"): its one-word name or
    verb that is also a noun; "" where it has none (a name of several words is no means: "by
    send off", nor a verb that names no means: "by send")."""
    word = next(
        (
            w
            for w in (op.name, *op.verbs)
            if w.strip() and " " not in w.strip() and language.is_noun(w.strip())
        ),
        None,
    )
    return f"by {word} " if word else ""


def ways_out(ops: list[Operation]) -> str:
    """How an office sends things out, in one English sentence: "I can send things out of
    the office by fax or courier", "I can send things to the exam board" (a name that says
    its own place, never "by send to the exam board"); "" where no operation sends out."""
    means = list(dict.fromkeys(m.strip() for op in ops if (m := by_means(op))))
    named = [
        with_object(op.name if " " in op.name.strip() else verb_alone(op), "things")
        for op in ops
        if not by_means(op)
    ]
    said = []
    if means:
        listed = " or ".join(m.removeprefix("by ") for m in means)
        said.append(f"send things out of the office by {listed}")
    said += [
        n
        if any(w in n.split() for w in ("to", "into", "out", "off", "away"))
        else f"{n} out of the office"
        for n in dict.fromkeys(named)
    ]
    return f"I can {' or '.join(said)}." if said else ""


def done_words(op: Operation) -> str:
    """What an operation did to an item, in its own words for the outcome: the office's
    ``done`` ("scanned to PDF"), else its verb's past participle ("shredded", "faxed")."""
    if op.done:
        return op.done
    # "restrung", never "restrung a guitar": the name's own object is the item said before
    verb, _, rest = " ".join(_without_own_object(op.name.split(), product_words(op))).partition(" ")
    return f"{language.past_participle(verb)} {rest}".strip()


def _operation_on(
    office: Office, shape: str, item_type: str, by: str | None = None
) -> Operation | None:
    """The office's operation of ``shape`` that works on ``item_type`` (else the first); of
    several (a fax and a binder both take a document), the one ``by`` runs."""
    ops = [op for op in office.operations if op.shape(office) == shape]
    on = [op for op in ops if op.input == item_type]
    runs = [op for op in on if any(by in f.guards for f in office.offering(op.id))]
    return next(iter(runs or on or ops), None)


def person_name(
    office: Office, person_id: str, *, you: str | None = None, unknown: str | None = None
) -> str:
    """A person's (or group's) display name ("you" for the reader ``you``); one the office
    does not know is ``unknown`` when given, else its id in words."""
    if you is not None and person_id == you:
        return "you"
    names = {p.id: p.name for p in office.people} | {g.id: g.name for g in office.groups}
    if person_id in names:
        return names[person_id]
    return _words(person_id) if unknown is None else unknown


def item_type_name(office: Office, type_id: str) -> str:
    try:
        return office.item_type(type_id).name
    except KeyError:
        return _words(type_id)


def file_noun(office: Office) -> str:
    """What a person's electronic file is called in a sentence ("your file", "your script"):
    "file" where the office calls its type so (its name or a synonym: "electronic file",
    also "file"), else the type's name, whatever its id ("script", "drawing")."""
    type_id = office.file_type()
    if type_id is None:
        return FILE_WORD
    t = office.item_type(type_id)
    names = {t.name.lower(), *(s.lower() for s in t.synonyms)}
    return FILE_WORD if FILE_WORD in names else t.name


def a_thing(name: str, *, mass: bool = False) -> str:
    """``name`` with the article its noun takes: "a stapler", "an umbrella", "some handling
    gloves" (a plural), "some glue" (stuff; ``mass``: an item the office names as stuff,
    "some gaffer tape"), and "a pair of scissors" for the English nouns that have no
    singular (``plural_only`` in the package's English words: one never lends "a
    scissors"). Plural and stuff are the morphology library's (``core.language``)."""
    if name.lower().startswith("pair of "):
        return f"a {name}"
    if name.split()[-1].lower() in words("plural_only"):
        return f"a pair of {name}"
    if mass or language.is_plural_noun(name) or language.is_mass_noun(name):
        return f"some {name}"
    return f"{'an' if name[:1].lower() in 'aeiou' else 'a'} {name}"


def is_are(name: str, *, mass: bool = False) -> str:
    """The verb "to be" that agrees with an item's name: "the gloves are", "the tape is";
    stuff (``mass``) is one thing to the verb whatever its name's last word looks like."""
    return "are" if language.is_plural_noun(name) and not mass else "is"


def _counted_plural(name: str, *, mass: bool) -> bool:
    """Whether ``name`` takes a plural verb: a plural that is not stuff ("gloves", not
    "some hand sanitiser"), nor a noun said as a pair ("a pair of scissors")."""
    return a_thing(name, mass=mass).startswith("some ") and is_are(name, mass=mass) == "are"


def there_is(name: str, *, mass: bool = False) -> str:
    """ "There are gloves", "There is some hand sanitiser", "There is a stapler": the
    existential sentence agrees with what its thing is, several things or one lot of stuff."""
    if _counted_plural(name, mass=mass):
        return f"There are {name}"
    return f"There is {a_thing(name, mass=mass)}"


def some_or_one(name: str, *, mass: bool = False) -> str:
    """What stands for an item in "I'll bring you ___": "some" gloves or stuff, "one"
    stapler (and one pair of scissors)."""
    return "some" if a_thing(name, mass=mass).startswith("some ") else "one"


def them_or_it(name: str, *, mass: bool = False) -> str:
    """The pronoun for an item named in general: "makes them" (gloves, staplers made one by
    one), "makes it" (stuff: coffee the office names as stuff, glue)."""
    stuff = mass or language.is_mass_noun(name)
    return "it" if stuff and not language.is_plural_noun(name) else "them"


def item_phrase(office: Office, item_id: str, *, you: str | None = None) -> str:
    """``stapler:wang`` → "Wang Fang's stapler" ("your stapler" when ``you`` is Wang)."""
    type_id, _, owner = item_id.partition(":")
    thing = item_type_name(office, type_id)
    if not owner:
        return f"the {thing}"
    if you is not None and owner == you:
        return f"your {thing}"
    if office.is_supply(item_id):  # owned by nobody: where it is kept names it
        stuff = office.item_type(type_id).mass
        return f"{a_thing(thing, mass=stuff)} from the {office.facility(owner).name}"
    return f"{person_name(office, owner)}'s {thing}"


def place_name(office: Office, place_id: str, *, unknown: str | None = None) -> str:
    """A location, facility or person (their desk) by name; a place the office does not know
    is ``unknown`` when given, else its id in words."""
    for location in office.locations:
        if location.id == place_id:
            return location.name
    for facility in office.facilities:
        if facility.id == place_id:
            return facility.name
    try:
        return f"{office.person(place_id).name}'s desk"
    except KeyError:
        return _words(place_id) if unknown is None else unknown


def _words(identifier: str) -> str:
    return identifier.replace(":", " ").replace("_", " ")
