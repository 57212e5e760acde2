"""A noun phrase whose head is a word of an office item's longer name, read as nothing.

"get Maren's vet notes forwarded to me", where the office's file is the "session notes", or
"fwd my ride briefing to Ulla", where it is the "briefing pack": the phrase says a thing of
the office in words the office does not list, so no mention of the item comes out of the
lexicon and no task carries it. In a request of two parts the other part is still read, and
without this the unread part vanishes while "Done" is reported for the rest.

The phrase is found from what opens it: a possessive ("my", "Maren's") or an article,
followed only by plain words up to its head; the head must be a word of a name of two words
or more of the office's electronic file (so "my lunch", "the way" never count), and no item
of the office may follow it in the phrase ("my wine list file" is the file). The
phrase is then quoted back to the requester as a part not understood, never guessed.

The same holds for a colleague's thing in words the office has nowhere, asked to be sent on:
"get Carmen's physio notes forwarded to me" (``unread_sent_thing``): a thing of hers to be
forwarded is no errand the reader may drop.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.core import language
from assistantx.core.office import Office
from assistantx.memory.names import normalize

_ARTICLES = frozenset({"the", "a", "an", "this", "that"})
_LONGEST = 4  # plain words in the phrase after its opener
# the participles that ask for a thing to be sent on ("get her notes forwarded to me")
_SENT_ON = frozenset(
    {"forwarded", "sent", "emailed", "mailed", "shared", "passed", "transferred", "fwded"}
)


def name_words(office: Office) -> frozenset[str]:
    """The words of the names of two words or more of the office's electronic files
    ("notes", "briefing"): what moves for them is a file, never a thing."""
    return frozenset(
        w
        for t in office.item_types
        if t.kind == "electronic"
        for name in (t.name, *t.synonyms)
        for words in [normalize(name).split()]
        if len(words) > 1
        for w in words
    )


def unread_compound(
    office: Office,
    mentions: Sequence[Mention],
    texts: Sequence[str],
    worked_on: frozenset[str] = frozenset(),
) -> str | None:
    """The words of the first such phrase (opener kept), or None. ``texts``: each token's
    text as written (an article is no mention of its own); ``worked_on``: the item types
    the request's operations take as their input ("burn a CD of *my master*", where burning
    takes a file): the head alone after its opener, a word of such a type's name ("master
    file"), is that item, whatever other thing's name shares the word ("master tape")."""
    words = name_words(office)
    taken = {
        w
        for t in office.item_types
        if t.id in worked_on
        for name in (t.name, *t.synonyms)
        for w in normalize(name).split()
    }
    ends = {m.end: m for m in mentions}
    for n, first in enumerate(mentions):
        if first.kind != "word" or first.start < 1:
            continue
        opener = ends.get(first.start)
        if opener is not None and opener.kind in ("self", "person") and opener.possessive:
            begin = opener.start
        elif opener is None and texts[first.start - 1].lower() in _ARTICLES:
            begin = first.start - 1
        else:
            continue
        run = [first]
        for m in mentions[n + 1 : n + _LONGEST]:
            if m.kind != "word" or m.start != run[-1].end:
                break
            run.append(m)
        # the head is the last plain word that is such a noun ("my ride briefing to ...")
        heads = [k for k, w in enumerate(run) if w.ids[0] in words and language.is_noun(w.ids[0])]
        after = next((m for m in mentions if heads and m.start == run[heads[-1]].end), None)
        if after is not None and after.kind == "item":
            continue  # "my wine list file": the item after it is the phrase's head
        if heads == [0] and run[0].ids[0] in taken:
            continue  # "burn my master": the master file burning takes, no question
        if heads:
            return " ".join(texts[begin : run[heads[-1]].end])
    return None


def unread_sent_thing(mentions: Sequence[Mention], texts: Sequence[str]) -> str | None:
    """ "Carmen's physio notes" in "get Carmen's physio notes forwarded to me": a colleague's
    possessive, then only plain words, then a participle of sending on; the words (opener
    kept), or None."""
    for n, opener in enumerate(mentions):
        if opener.kind != "person" or not opener.possessive:
            continue
        run: list[Mention] = []
        for m in mentions[n + 1 : n + 1 + _LONGEST]:
            if m.start != (run[-1].end if run else opener.end):
                break
            if texts[m.start].lower() in _SENT_ON:
                if run and language.is_noun(run[-1].ids[0]):
                    return " ".join(texts[opener.start : run[-1].end])
                break
            if m.kind != "word":
                break
            run.append(m)
    return None
