"""Two or more people joined by "and" where one recipient stands: each of them receives.

English coordinates the indirect object and the receiving phrase like any noun phrase: "bring
*Wang and Sun* a coffee", "a coffee for *Mao and Zhang*", "bring *him and Sun* a water",
"bring *me and Wang* a tea", "*Hal and Dawn* need a stapler". Read one name at a time, only
the first (or the last) got the recipient's role and the other was dropped, or, with a pronoun
first ("him and Sun"), nobody did and the thing went to the requester: a wrong hand-over.

A group is party words (a name, "me", "him"/"her" pointing back to the one colleague named
before) joined by "and" (a list "A, B and C" by commas too), that stands

- right after a giving verb or the office's task word, with the thing's noun phrase opening
  right after it ("bring Wang and Sun *a* coffee"), as one indirect object;
- after "to"/"for", and ends the phrase (no finite verb after it: "take it to Wang and Sun
  needs ..." starts a new clause with Sun);
- before "need(s)"/"want(s)", as the one subject of the need.

A plural pronoun said of people ("them both", "both of them", "the two of them") in those
places is the two colleagues named before it.

What each of them then gets is the frame's to decide (``for_each``): a product is made once
for each; one physical thing cannot go to two people, so whom is asked.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.indirect_object import gives_from_verb, opens_noun_phrase
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token, prev_word
from assistantx.core import english, language, task_kinds
from assistantx.core.office import Office
from assistantx.core.task_schema import FILE_KIND, Task

_DATIVE_VERBS = english.words("dative_verbs")
_NEEDS = english.words("need_verbs")
_MODALS = english.words("request_modals")
_RECEIVING = frozenset({"to", "for"})
# the words that may stand between "and" and the receiving word said again ("and then for")
_SEQUENCE = (["then"], ["also"])
# "him", "her" as a party of a group ("bring him and Sun ..."); "them" is the plural form below
_ONE_PERSON_PRONOUNS = frozenset({"him", "her"})
# "them both", "them each", "both of them", "the two of them", "all of them"
_PLURAL_AFTER = frozenset({"both", "each"})
# the same words floated after a plural subject: "Wang and Sun both need a stapler"
_FLOATED = _PLURAL_AFTER
_PLURAL_BEFORE = (("both", "of"), ("two", "of"))
# The words that, after a receiving phrase's last name, start a new clause with that name as
# its subject ("to Wang and Sun *will* sign it") rather than end the phrase
_CLAUSE_GOES_ON = _MODALS | frozenset({"to", "is", "has", "was", "can", "should", "must"})


@dataclass(frozen=True)
class Joined:
    """A group of recipients: who they are (in the order said) and where each was said."""

    people: tuple[str, ...]  # empty: a plural pronoun of people nobody said (asked)
    at: tuple[int, ...]  # the token start of each party word
    pronouns: frozenset[int]  # the starts of the pronoun mentions the group took in


def one_party(m: Mention, tokens: Sequence[Token]) -> bool:
    """Whether a mention can be one member of a group: a single named person, "me", or an
    object pronoun, none of them possessive (``Wang's`` owns the thing after it; "her" is
    read either way, and "and" after or before it says it owns nothing)."""
    if m.kind == "pronoun":
        return tokens[m.start].word in _ONE_PERSON_PRONOUNS
    if m.possessive:
        return False
    if m.kind == "person":
        return len(m.ids) == 1
    return m.kind == "self" and tokens[m.start].word == "me"


def _join(tokens: Sequence[Token], a: Mention, b: Mention) -> str:
    """How two neighbouring mentions are joined: "and", "," (a pause, nothing between) or ""
    (not joined)."""
    between = [t.word for t in tokens[a.end : b.start]]
    if between == ["and"] and not tokens[b.start].after_pause:
        return "and"
    # "for me and for Wang", "to Mao and to Sun": the receiving word said again joins the
    # same phrase (before, only the last got the thing and "me" was dropped unsaid)
    # "for me and then for Wang", "to Mao and also to Sun": a sequence word between
    said_again = (
        len(between) in (2, 3)
        and between[0] == "and"
        and between[1:-1] in ([], *_SEQUENCE)
        and between[-1] in _RECEIVING
    )
    if said_again and prev_word(tokens, a.start) == between[-1]:
        return "and"
    if not between and tokens[b.start].after_pause and not tokens[b.start].opens:
        return ","
    return ""


def chains(
    ms: Sequence[Mention],
    tokens: Sequence[Token],
    party: Callable[[Mention, Sequence[Token]], bool] | None = None,
    join: Callable[[Sequence[Token], Mention, Mention], str] | None = None,
) -> list[list[int]]:
    """Runs of two or more party mentions (by index), each joined by "and" to the one before,
    or by commas in a list that ends with "and" ("Wang, Sun and Mao"); ``party`` says which
    mentions may be members (``one_party``), ``join`` how two are joined ("and", "," or "")."""
    party = party or one_party
    join = join or _join
    found: list[list[int]] = []
    n = 0
    while n < len(ms):
        if not party(ms[n], tokens):
            n += 1
            continue
        run, joins = [n], []
        while n + 1 < len(ms) and party(ms[n + 1], tokens):
            how = join(tokens, ms[n], ms[n + 1])
            if not how:
                break
            run.append(n + 1)
            joins.append(how)
            n += 1
        # a comma alone joins no list ("Wang, Sun needs a coffee" addresses Wang)
        while joins and joins[-1] != "and":
            joins.pop()
            run.pop()
        if len(run) >= 2:
            found.append(run)
        n += 1
    return found


def _receives(
    tokens: Sequence[Token], ms: Sequence[Mention], first: int, start: int, end: int
) -> bool:
    """Whether words ``start``..``end`` (a group's span, mention ``first`` opening it) stand
    where a recipient stands: an indirect object, a receiving phrase, the subject of a need."""
    prev = prev_word(tokens, start)
    after = tokens[end].word if end < len(tokens) and not tokens[end].after_pause else ""
    if after in _FLOATED and end + 1 < len(tokens):  # "Wang and Sun both need ..."
        after = tokens[end + 1].word
    if prev in _RECEIVING:
        return not (after and (after in _CLAUSE_GOES_ON or language.is_finite_verb(after)))
    if (prev in _DATIVE_VERBS or gives_from_verb(tokens, ms, first, prev)) and opens_noun_phrase(
        tokens, end
    ):
        return True
    return after in _NEEDS


def _receiving_said_again(tokens: Sequence[Token], m: Mention) -> bool:
    """Whether a word mention is "to"/"for" said again after "and" ("for me and for Wang")."""
    word = tokens[m.start].word
    if m.kind != "word" or word not in _RECEIVING:
        return False
    before = prev_word(tokens, m.start)
    if [before] in _SEQUENCE:  # "for me and then for Wang"
        before = prev_word(tokens, m.start - 1)
    return before == "and"


def _colleague_before(others: Sequence[str]) -> str:
    """The one colleague a "him"/"her" of a group points back to; several or none: whom is
    asked (``UnresolvedPronoun``, raised by the caller from the empty answer)."""
    found = list(dict.fromkeys(others))
    return found[0] if len(found) == 1 else ""


def joined_recipients(
    tokens: Sequence[Token], ms: Sequence[Mention], requester: str, named_before: Sequence[str]
) -> list[Joined]:
    """The groups of recipients a clause says (see the module docstring); ``named_before``:
    the colleagues named before the clause, in order, for a pronoun of the group. A pronoun
    that points to nobody, or to either of two, gives no group (the caller's own reading
    asks whom it means)."""
    # "for me and *for* Wang": the receiving word said again is no break in the group
    ms = [m for m in ms if not _receiving_said_again(tokens, m)]
    groups: list[Joined] = []
    for run in chains(ms, tokens):
        first, last = ms[run[0]], ms[run[-1]]
        if not _receives(tokens, ms, run[0], first.start, last.end):
            continue
        people: list[str] = []
        for n in run:
            m = ms[n]
            if m.kind == "person":
                people.append(m.ids[0])
            elif m.kind == "self":
                people.append(requester)
            else:
                named = [p for p in named_before if p != requester]
                named += [ms[k].ids[0] for k in range(run[0]) if ms[k].kind == "person"]
                group_names = {ms[k].ids[0] for k in run if ms[k].kind == "person"}
                who = _colleague_before([p for p in named if p not in group_names])
                if not who:
                    break
                people.append(who)
        else:
            if len(set(people)) >= 2:
                groups.append(
                    Joined(
                        tuple(people),
                        tuple(ms[n].start for n in run),
                        frozenset(ms[n].start for n in run if ms[n].kind == "pronoun"),
                    )
                )
    plural = _plural_pronoun(tokens, ms, requester, named_before)
    if plural is not None:
        groups.append(plural)
    return groups


def _plural_pronoun(
    tokens: Sequence[Token], ms: Sequence[Mention], requester: str, named_before: Sequence[str]
) -> Joined | None:
    """ "bring them both a water", "a tea for both of them", "the two of them need a pen":
    the two colleagues named before, where the group stands as a recipient."""
    for n, m in enumerate(ms):
        if m.kind != "pronoun" or m.possessive or tokens[m.start].word != "them":
            continue
        start, end = m.start, m.end
        if end < len(tokens) and tokens[end].word in _PLURAL_AFTER:
            end += 1
        elif start >= 2 and (tokens[start - 2].word, tokens[start - 1].word) in _PLURAL_BEFORE:
            start -= 2
            if start >= 1 and tokens[start].word == "two" and tokens[start - 1].word == "the":
                start -= 1
        else:
            continue
        if not _receives(tokens, ms, n, start, end):
            continue
        named = list(dict.fromkeys(p for p in named_before if p != requester))
        if len(named) != 2:
            # "them both" of one, or of three named: no group (``people`` empty), whom the
            # caller asks, never the one named alone
            return Joined((), (), frozenset({m.start}))
        return Joined(tuple(named), (m.start, m.start), frozenset({m.start}))
    return None


def for_each(
    made: Sequence[Task], each: Sequence[Sequence[str]], office: Office, requester: str
) -> list[Task] | str:
    """The tasks of a clause with a group of recipients (``each``, from ``Roles.each``), one
    for each of them: a thing made to order (a coffee, a printout: a kind whose work produces
    it) or a file passed on (a copy costs nothing) is made or sent once for each; one
    physical thing cannot go to two people, so the question of whom is returned instead."""
    out: list[Task] = []
    for task in made:
        group = next((g for g in each if task.recipient in g), None)
        if group is None:
            out.append(task)
        elif task.kind == FILE_KIND or task_kinds.kind(task.kind).purpose == "produce":
            out += [task.model_copy(update={"recipient": who}) for who in dict.fromkeys(group)]
        else:
            return _whom_of(task, group, office, requester)
    # a file already sent to each ("email my file to Hal and Dawn", ``frames._to_each``) is
    # sent once to each, not once more per name
    return [t for n, t in enumerate(out) if t not in out[:n]]


def _whom_of(task: Task, group: Sequence[str], office: Office, requester: str) -> str:
    """ "Should the stapler go to Wang Fang, or to Sun Li?": one thing, several said to get
    it."""
    names = ["you" if who == requester else office.person(who).name for who in dict.fromkeys(group)]
    thing = office.item_type(task.item).name if task.item is not None else "it"
    the = f"the {thing}" if task.item is not None else thing
    choices = ", or to ".join(names)
    return f"Should {the} go to {choices}? {ONLY_ONE}"


# How the question of whom in a group ends: the answer names one of them (``group_answered``)
ONLY_ONE = "I can hand it to only one of them."


def group_spans(tokens: Sequence[Token], ms: Sequence[Mention]) -> list[tuple[int, int]]:
    """The token spans [start, end) of the joined groups of party words in a text (its
    lexicon's mentions, the function words among them left out)."""
    said = [m for m in ms if m.kind != "word"]
    return [(said[run[0]].start, said[run[-1]].end) for run in chains(said, tokens)]
