"""The pause people leave out in chat between two clauses: "my phone's on 3% can i borrow
zhou's charger cable", "take my mug over to Sun she's got nothing to drink from", "can u
bring me a torch no wait a uv lamp", "Zhang's stapler is broken get me another one". Said with
its comma each message was read as its two clauses (a statement, then the request; the
request, then its reason; a request, then its correction); run together the whole was one
clause, and the request was lost ("Noted. I did nothing."), a thing of the reason was fetched
too, or the correction withdrew everything.

The comma is put back before a word that can only open a clause of its own here:

- a request's opening, a modal and whom or what it asks of ("can i", "could you", "can
  someone", "could it", "can my ...", "any chance");
- a subject and its verb said together ("she's", "he's", "mine's", "I've", "they're", "his
  has", "I need");
- a correction's marker ("no wait", "no actually", "sorry no", "or rather");
- after a clause that tells a state ("... is broken", "... ran out"), a command: a task's
  word in its plain form ("get me another one");
- after a request, its reason: a noun's clause ("the fridge is rammed", "the batteries in
  mine just died") or one with its subject dropped ("forgot mine", "cant find mine", "need a
  fresh pair", "going in to weigh").

Never after a word that makes what follows part of the clause before ("if", "whether",
"wonder", "so", "and", a question word, a preposition, an article: "I wonder if you could
...", "tell me when you can"). A pause already there, or a stop, is left as it is."""

from __future__ import annotations

import re
from collections.abc import Collection

from assistantx.core import english, language

# what a request opens on after the clause before it: a modal, then whom or what it asks of
_MODALS = r"(?:can|could|would|will|cn|cld|may)"
_ASKED = r"(?:you|u|ya|i|we|someone|somebody|sombody|anyone|anybody|sum1|sb|ye|it|they|my)"
_REQUEST = (
    rf"(?:{_MODALS}\s+{_ASKED}|any\s+chance"
    r"|(?:anyone|anybody|someone|somebody)\s+(?:got|have|has)|got\s+(?:anything|something|any))\b"
)
# a subject and its verb, said as one word or two
_STATE_VERBS = (
    r"(?:is|was|has|had|keeps|just|got|went|broke|died|snapped|needs|wants|isnt|wasnt|hasnt"
    r"|need|want|have|am|cant|can't|forgot|left|lost|ll|spilled|spilt|skipped|dropped|said"
    r"|says)"
)
_SUBJECT_VERB = (
    r"(?:(?:he|she|it|they|we|mine|hers|his|theirs|ours)['’](?:s|re|ve|ll|d)"
    r"|hes|shes|theyre"
    rf"|(?:he|she|they|mine|hers|his|theirs|ours)\s+{_STATE_VERBS})\b"
)
_CORRECTION = (
    r"(?:no\s+wait|no\s+actually|actually\s+no|sorry\s+no|or\s+rather|no\s+sorry"
    r"|actually\s+never\s+mind|never\s+mind|actually\s+forget\s+it|forget\s+it"
    r"|actually\s+scratch\s+that|scratch\s+that)\b"
)
# a noun's clause of state: "the fridge is rammed", "the batteries in mine just died"
_NOUN_STATE = (
    r"(?:the|his|her|their|our)\s+(?:(?!(?:i|you|u|we|they|he|she)\b)[\w'’]+\s+){1,4}?"
    r"(?:is|are|was|were|has|have|had|needs|need|keeps|keep|just|cant|can't|won't|wont|isnt"
    r"|isn't|arent|aren't|looks|look|seems|went|broke|died)\b"
)
# a reason with its subject dropped, said of the speaker: "forgot mine", "need a fresh pair"
_DROPPED = (
    r"(?:forgot|left\s+mine|lost\s+mine|cant\s+find|can't\s+find|couldnt\s+find"
    r"|dropped\s+mine|been\s+stuck|been\s+on|going\s+in|doing\s+(?:a|the|some)"
    r"|need\s+(?:a|an|to|some|something|the)|got\s+(?:a|all|some|loads))\b"
)
# the word before: where a clause cannot start here, it belongs to the clause before
_JOINED = english.words("clause_joins") | english.words("clause_binding_words")
_OPENING = re.compile(
    rf"(?<=[\w'’%)])(?P<gap>\s+)(?P<open>{_REQUEST}|{_SUBJECT_VERB}|{_CORRECTION})",
    re.IGNORECASE,
)
# after a courtesy said mid-message, a subject opens a clause of its own ("take it to Miles
# pls he's on parcels", "a pen please my biro just died")
_AFTER_COURTESY = re.compile(
    r"(?:(?<=\bplease)|(?<=\bpls)|(?<=\bplz))(?P<gap>\s+)"
    r"(?P<open>(?:i|i'm|i've|im|ive|he|she|they|we|he's|she's|hes|shes|they're|my|one\s+of)\b)",
    re.IGNORECASE,
)
_REASON = re.compile(rf"(?<=[\w'’%)])(?P<gap>\s+)(?P<open>{_NOUN_STATE}|{_DROPPED})", re.IGNORECASE)
_WORD_AT = re.compile(r"(?<=[\w'’%)])(?P<gap>\s+)(?P<open>[a-z]+)\b")
_LAST_WORD = re.compile(r"([\w'’]+)\W*$")
_WORDS = re.compile(r"[\w'’]+")
_CLAUSE_START = re.compile(r"[,.;:!?]|\s[-–—]\s")
# a clause that tells a state: its verb ("is broken", "ran out", "died")
_TOLD = english.words("told_state_words")
# a clause that opens on these asks a question, no state told before a command
_ASKING_FIRST = english.words("question_openers")
# what a command's verb is followed by: whom or what it acts on ("get *me* another one")
_COMMAND_OBJECTS = english.words("command_objects")
# the words a told state may end on besides its verb and what is said of the thing
_STATE_ENDS = frozenset({"out", "again", "today", "now", "already", "tonight", "off", "down"})
_NEEDING = english.words("need_verbs")
_REQUEST_ENDS = frozenset({"me", "us", "him", "her", "them", "it", "pls", "please", "plz", "asap"})
_COURTESY = frozenset({"please", "pls", "plz"})
_LEAST_CLAUSE = 2  # the words a clause before a request's opening has, a name alone aside
_MODAL_WORDS = frozenset({"can", "could", "would", "will", "cn", "cld", "may", "pls", "please"})


def _ends_a_state(word: str) -> bool:
    """Whether a told state can end on ``word``: its verb or what is said of the thing
    ("is broken", "is empty", "ran out", "... today")."""
    if word in _TOLD or word in _STATE_ENDS:
        return True
    lemmas = language.lemmas(word)
    return ("ADJ" in lemmas and "VERB" not in lemmas) or language.is_past_participle(word)


def _ends_a_thing(word: str) -> bool:
    """Whether a request's clause can end on ``word``: the thing asked for ("a pair of
    gloves"), whom for ("me"), or a courtesy ("pls")."""
    if "'" in word or "’" in word:
        return False  # "i've got ...": a subject and its verb, not a thing
    if not word.isalpha():
        return True  # "on 3%", "booth 2"
    # a word the dictionary does not know is the office's own thing ("a hairnet")
    return word in _REQUEST_ENDS or language.is_noun(word) or not language.lemmas(word)


def restored_pauses(text: str, commands: Collection[str] = ()) -> str:
    """``text`` with a comma put back before each clause that opens run into the one before
    (``commands``: the task words, in their plain forms, that open a command)."""

    def free(match: re.Match[str], *, after_courtesy: bool = False) -> bool:
        before = _LAST_WORD.search(match.string, 0, match.start())
        if before is None:
            return False
        word = before.group(1).lower()
        if word in _JOINED and not (after_courtesy and word in _COURTESY):
            return False
        head = match.string[: match.start()].rstrip()
        return bool(head) and head[-1] not in ",.;:!?-–—"

    def clause_before(match: re.Match[str]) -> list[str]:
        head = match.string[: match.start()]
        starts = list(_CLAUSE_START.finditer(head))
        return [w.lower() for w in _WORDS.findall(head[starts[-1].end() if starts else 0 :])]

    asking = frozenset(commands) | _MODAL_WORDS

    def asked(words: list[str]) -> bool:
        return not asking.isdisjoint(words)

    def paused(match: re.Match[str]) -> str:
        if not free(match) or len(clause_before(match)) < _LEAST_CLAUSE:
            return match.group(0)  # "Otto could you ...": a name said first, kept as said
        return f",{match.group('gap')}{match.group('open')}"

    def courteous(match: re.Match[str]) -> str:
        said = [w.lower() for w in _WORDS.findall(match.string[: match.start()])]
        if len(said) < _LEAST_CLAUSE or not asked(said):
            return match.group(0)  # "please I ...": the courtesy opens the message
        return f",{match.group('gap')}{match.group('open')}"

    def reason(match: re.Match[str]) -> str:
        said = [w.lower() for w in _WORDS.findall(match.string[: match.start()])]
        if not free(match, after_courtesy=True) or not asked(said):
            return match.group(0)  # a reason follows a request, never a statement
        before = said[-1]  # ``free`` found a word before it
        if before in commands:
            return match.group(0)  # "print the slides ...": the command's own object
        if not _ends_a_thing(before):
            return match.group(0)  # "I will probably need ...": the clause's own verb
        if match.group("open").lower().startswith("need") and language.is_plural_noun(before):
            return match.group(0)  # "the milk samples need to stay cold": their verb
        return f",{match.group('gap')}{match.group('open')}"

    def command(match: re.Match[str]) -> str:
        word = match.group("open").lower()
        if word not in commands or word in _NEEDING or word not in language.verb_lemmas(word):
            return match.group(0)
        if not free(match):
            return match.group(0)
        before = _LAST_WORD.search(match.string, 0, match.start())
        if before is None or not _ends_a_state(before.group(1).lower()):
            return match.group(0)  # "I can't find ...", "have Joy sign ...": its own verb
        after = _WORDS.match(match.string, match.end() + 1)
        if after is None or after.group(0).lower() not in _COMMAND_OBJECTS:
            return match.group(0)  # "the glass I had cut for the frame": no command's object
        words = clause_before(match)
        if words[:1] and words[0] in _ASKING_FIRST:
            return match.group(0)  # "is the edger playing up or did robin fix it?": asked
        if not set(words) & _TOLD or asked(words):
            return match.group(0)  # "bring me a pen take it to Wang": one request said on
        return f",{match.group('gap')}{match.group('open')}"

    text = _OPENING.sub(paused, text)
    text = _AFTER_COURTESY.sub(courteous, text)
    text = _REASON.sub(reason, text)
    return _WORD_AT.sub(command, text) if commands else text
