"""A service's verb said as a modifier inside a noun phrase: "can you get Tomás's shipping
spreadsheet for me", "get Wang to send me his printing budget", "my copying log", "her binding
quote".

An -ing form of a verb between a possessive and a noun stands in the
adjective's place: it says which of the owner's things is meant (the spreadsheet about
shipping), never the work asked for ("I can't ship an electronic file" was the answer). The
modifier is left out, as a hyphened description is (``described_items``), and the noun phrase
is read as the owner's thing ("Tomás's spreadsheet": his file, sent on to the speaker).

Only the forms of the office's own services' verbs and its task words are read (an unknown
verb was never read as work), and never where the -ing form belongs to a name of the office
("the printing machine", "the drying room"), nor before a noun another noun follows ("my
cupping notes file": the head comes later, read as it was), nor where no noun follows ("my
printing is urgent", "do the printing for me", "get my copying done").
"""

from __future__ import annotations

import re
from collections.abc import Collection

from assistantx.core import english, language

# whose the thing is: a possessive pronoun or a name's "'s" (a bare "the printing schedule"
# is read as before: the reader already reads some such names of papers whole)
_OWNERS = "|".join(sorted(english.words("held_copy_owners") | {"its"}))
_PHRASE = re.compile(
    rf"(?P<owner>\b(?:{_OWNERS})|\w['’]s|s['’])\s+(?P<modifier>[a-z]+ing)\s+(?P<noun>[a-z]+)\b"
    r"(?P<next>\s+[a-z]+)?",
    re.IGNORECASE,
)
# words after a modifier that are no noun it modifies (``purpose_modifier`` reads with them)
NOT_NOUNS = (
    english.words("prepositions_and_joins")
    | english.words("determiners")
    | english.words("pronouns")
    | english.words("copulas")
    | english.words("modal_auxiliaries")
    # when it happens: "the kitchen's boiling today" ("'s" for "is")
    | english.words("state_tails")
    | english.words("time_nouns")
    | english.words("now_words")
    | english.words("later_times")
)
# the nouns of papers and files, read as nouns whatever the dictionary says ("log")
_PAPERS = frozenset(
    english.words("file_nouns") | english.words("paper_nouns") | english.words("paper_heads")
)


def without_attributive_work(
    text: str, work_verbs: Collection[str], office_phrases: Collection[str]
) -> str:
    """``text`` with each -ing form of ``work_verbs`` (the office's verbs and task words, their
    lemmas) said between an owner and a noun left out ("his printing budget" →
    "his budget"); ``office_phrases``: the office's names of things, facilities and places,
    which keep theirs ("the printing machine")."""

    def plain(match: re.Match[str]) -> str:
        modifier, noun = match.group("modifier").lower(), match.group("noun").lower()
        if not language.verb_lemmas(modifier) & set(work_verbs):
            return match.group(0)
        if noun in NOT_NOUNS or (noun not in _PAPERS and "NOUN" not in language.lemmas(noun)):
            return match.group(0)
        after = (match.group("next") or "").strip().lower()
        if after and after not in NOT_NOUNS and "NOUN" in language.lemmas(after):
            return match.group(0)  # "my cupping notes file": the head is later, read as it is
        said = f"{modifier} {noun}"
        if any(said in p or p == modifier for p in office_phrases):
            return match.group(0)
        return f"{match.group('owner')} {match.group('noun')}{match.group('next') or ''}"

    return _PHRASE.sub(plain, text)
