"""A colleague's thing the work cannot take is never swapped for the requester's own:
"Mark's laptop needs a scan, can you take it over" names Mark's laptop, no paper of the
office, and the work's reading fell back on the requester's own document (a scan of the
wrong thing, a wrong physical action). Where the work's item was not said, the requester's
own stands in only when nothing else is named as the object: a colleague's possessive before
a noun that is no item of the office names the thing meant, and that thing cannot be worked
on, so the request is declined in words."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.possessed_thing import possessed
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.core.task_schema import Task
from assistantx.core.wording import a_thing

# The words that say the requester's own ("my file", "mine"): their own is then said, not
# stood in for
_OWN = frozenset({"my", "mine", "our", "ours", "myself"})
# "Mark's one", "Mark's lot": a pro-form names no other thing
# "on Mark's desk", "to Zhang's office", "from Wang's drawer": a colleague's thing after a
# preposition says where, never the work's object
_PLACING = (
    english.words("party_prepositions")
    | english.words("location_prepositions")
    | english.words("to_facility_prepositions")
    | english.words("onto_prepositions")
    | english.words("from_facility_prepositions")
)
_PRO_FORMS = english.words("another_one") | {"one", "ones", "lot", "stuff", "things", "thing"}


def others_thing_declined(
    office: Office,
    tokens: Sequence[Token],
    mentions: Sequence[Mention],
    tasks: Sequence[Task],
    requester: str,
) -> str | None:
    """The decline of work that would take the requester's own item in place of the
    colleague's thing the request names ("Zhang's laptop needs printing"); None when the
    request names the work's item, the requester's own, or no colleague's other thing."""
    stood_in = [t for t in tasks if _stands_in(t, mentions, requester)]
    if not stood_in or any(t.word in _OWN for t in tokens):
        return None
    for n, m in enumerate(mentions):
        if m.kind != "person" or not m.possessive or len(m.ids) != 1 or m.id == requester:
            continue
        if m.start > 0 and tokens[m.start - 1].word in _PLACING:
            continue  # "leave them on Mark's desk": where the work goes, not what it takes
        thing = possessed(tokens, mentions, n)
        if thing is None or thing.kind != "word" or thing.end - thing.start != 1:
            continue
        word = tokens[thing.start].word
        # "Mao's rota", "Zhang's powerpoint": a word the dictionary lacks names a thing too
        if word in _PRO_FORMS or not (language.is_noun(word) or not language.lemmas(word)):
            continue
        owner = office.person(m.id).name
        item = office.item_type(stood_in[0].item or "").name
        return (
            f"Sorry, I can't do that with {owner}'s {tokens[thing.start].text}: it is not "
            f"something of this office I can work on, and I won't use your own {item} in its "
            f"place. If you meant {a_thing(item)} of yours, please say so."
        )
    return None


def _stands_in(task: Task, mentions: Sequence[Mention], requester: str) -> bool:
    """Whether ``task`` is work on the requester's own item that the request never named
    (no mention of its item type): their own stood in for the object."""
    if task.kind == "transfer" or task.item is None or task.owner != requester:
        return False
    return not any(m.kind == "item" and task.item in m.ids for m in mentions)
