"""Speech acts: what each sentence of a message *does*, before any task is read from it.

Only a request moves the robot. Every piece of a message (a sentence, or a comma part of
one) is one of:

===========  ==========================================================  =====================
act          examples                                                    answered with
===========  ==========================================================  =====================
request      "bring me a stapler", "can you get me a pen?", "I need ..." the errand
question     "who has a tape measure?", "is the printer working?",       words from memory;
             "where is Zhang?", "does anyone have a stapler?"            "Shall I ...?" when
                                                                         it may be a request
thanks       "thanks for the stapler!", "say thanks to Wang for ..."     words
wish         "please keep everyone away from Mao's seal today",          words: nothing is
             "nobody take my mug", "don't let anyone use my pen"         moved
withdrawal   "never mind", "forget about the scissors", "cancel that"    drops what came before
statement    "my laptop cable is too short", "I spilled my tea",         context only
             "Pat hurt her hand", "I've got some"
need         "Min needs scissors" (a third person's need)                a request only with
                                                                         one ("bring her
                                                                         some"), else asked
===========  ==========================================================  =====================

A polite request phrased as a question ("could someone lend me a pen?", "can I have ...")
stays a request. The words are the package's English data (``data/english.yaml``); finite
verbs ("spilled", "hurt") come from the morphology library (``core.language``).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import Literal

from assistantx.agents.symbolic.reading import future_need
from assistantx.agents.symbolic.reading.clipped_progressive import clipped_progressive
from assistantx.agents.symbolic.reading.compound_subject import compound_modifier
from assistantx.agents.symbolic.reading.declined_more import declines_more
from assistantx.agents.symbolic.reading.done_passive import reports_done_work
from assistantx.agents.symbolic.reading.facility_told import facility_told
from assistantx.agents.symbolic.reading.fault_subject import subject_of_fault
from assistantx.agents.symbolic.reading.grumble import grumble, grumbled, wished_better
from assistantx.agents.symbolic.reading.handed_to_named import handed_to_named
from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.linked_state import linked_state
from assistantx.agents.symbolic.reading.modal_told import denied_ability, told_with_modal
from assistantx.agents.symbolic.reading.no_work import no_work_told
from assistantx.agents.symbolic.reading.obligation import PERSON_WORK, obliged_verb
from assistantx.agents.symbolic.reading.offers import offered
from assistantx.agents.symbolic.reading.outsider_need import (
    DESCRIBING_ARTICLES,
    LACKED_OPENERS,
    outsider_subject,
    outsider_wants,
)
from assistantx.agents.symbolic.reading.outsider_report import outsider_reports
from assistantx.agents.symbolic.reading.passive_service import service_asked_in_passive
from assistantx.agents.symbolic.reading.phrase_index import (
    PhraseIndex,
    by_first_word,
    phrase_at,
    without_phrases,
)
from assistantx.agents.symbolic.reading.place_name_subject import opens_with_place_name
from assistantx.agents.symbolic.reading.poor_prospect import poor_prospect
from assistantx.agents.symbolic.reading.prohibition_contracted import with_is
from assistantx.agents.symbolic.reading.sequence_opener import after_sequence_word, wanted_done_by
from assistantx.agents.symbolic.reading.service_command import service_command
from assistantx.agents.symbolic.reading.service_noun_subject import service_noun_subject
from assistantx.agents.symbolic.reading.service_verb_heads import service_asked
from assistantx.agents.symbolic.reading.speaker_lack import given_thing, speaker_lacks
from assistantx.agents.symbolic.reading.taken_from_speaker import (
    mishap_to_thing,
    taken_from_speaker,
)
from assistantx.agents.symbolic.reading.thanks_ahead import thanks_ahead
from assistantx.agents.symbolic.reading.thing_needs import part_told, work_told
from assistantx.agents.symbolic.reading.thing_state import state_told
from assistantx.agents.symbolic.reading.used_today import used_later_today
from assistantx.core import english, language
from assistantx.core.receiving_place import MEET_AT, PLACE_PRONOUNS, PLACE_WORDS

QuestionKind = Literal["polite", "info"]

_WH = english.words("wh_words")
_AUX = english.words("question_auxiliaries")
_DO_COMMANDED = english.words("do_commanded")
_MODALS = english.words("request_modals")
# Words between "go" and "to" of a thing sent on ("should go *back* to Lee")
_GOING_PARTICLES = frozenset({"back", "over", "across", "along", "round", "straight"})
_ASKEES = english.words("request_askees")
# "have *somebody* sign my contract": whom the requester leaves unnamed, made to do it
_UNNAMED_DOERS = english.words("unnamed_doers")
_GROUP_DOERS = frozenset({"person", "people", "whoever"})
_OPENERS = english.words("speech_openers")
# "can't read these", "couldn't see a thing": the speaker's inability, the "I" left out
_CANNOT = frozenset({"cant", "cannot", "couldnt"})
# "to be honest, ...", "by the way ...": the speaker's stance before what is said
_STANCE = tuple(tuple(p.split()) for p in english.entries("stance_phrases"))
_THANKS = english.words("thanks_words")
_RELAY = english.words("relay_verbs")
_PRAISE = tuple(tuple(p.split()) for p in english.entries("praise_openers"))
_APPROVAL_VERBS = english.words("approval_verbs")
_APPROVAL_OBJECTS = english.words("approval_objects")
_APPROVAL_DEGREE = english.words("approval_degree")
_NOBODY = tuple(tuple(p.split()) for p in english.entries("prohibition_subjects"))
_EVERYONE = english.words("everyone_words")
_GUARD_VERBS = english.words("guard_verbs")
_AWAY = english.words("guard_away")
_NEED = english.words("need_verbs")
_PUTTING = english.words("putting_verbs")  # "leave", "put", "pop": a thing put down
_OWN = frozenset({"my", "our"})  # the requester's own thing
# A thing said before, by a pronoun after a work's verb ("sign *it*"), and the particles
# that may stand between ("sign *off* on it")
_SAID_BEFORE = frozenset({"it", "them"})
_WORK_PARTICLES = frozenset({"off", "on", "up", "over"})
_IN_PLACE = frozenset({"in", "at", "inside"})
_RECEIVE = english.words("receive_verbs")  # "Min gets the printout": a recipient, not a fact
_SUBJECTS = english.words("statement_subjects")
# Where a spilled thing went ("got *on* my notes", "went *everywhere*"): no errand's words
_SPREAD = frozenset({"on", "onto", "into", "in", "over", "all", "everywhere", "across"})
_PLEASE = frozenset({"please", "pls", "plz", "plse", "pleeease"})
_SUBJECT_VERB = english.words("subject_contractions")
_STATE_VERBS = english.words("state_verbs")
_WILLING = english.words("request_markers")
_WITHDRAW_HEADS = tuple(tuple(p.split()) for p in english.entries("withdraw_heads"))
# Whole withdrawals ("don't bother", "no need"): said after a refusal word, still one
_WITHDRAW_WHOLE = frozenset(tuple(p.split()) for p in english.entries("withdraw"))
_REFUSING = frozenset({"no", "nah", "nope"})
_BORROW = english.words("borrow_words")
_DONE_VERBS = english.words("done_verbs")
_DONE_MARKERS = tuple(tuple(p.split()) for p in english.entries("done_markers"))
# "Olu's got one i think": the speaker's doubt about what someone else has; its "I" is no
# speaker who has the thing
_SPEAKERS_DOUBT = tuple(
    tuple(p.split())
    for p in sorted(english.entries("parenthetical_hedges"), key=lambda p: -len(p.split()))
)
_DECLINING_THANKS = tuple(tuple(p.split()) for p in english.entries("declining_thanks"))
_PAST_TIMES = tuple(tuple(p.split()) for p in english.entries("past_times"))
# Another one of what was asked for: "X brought me *one*", "Ida lent me *hers*"
_ONE_MORE = frozenset({"one", "some", "hers", "his", "mine", "theirs"})
# The errand itself, said again: "someone already did *it*"
_THE_ERRAND = frozenset({"it", "that", "this"})
_HAVE_NOW = frozenset({"have", "ive", "weve", "got"})
# "it's already got coffee on it", "this one has already got a crease": what a thing has is its
# state, never the speaker's having what was asked for; the subject is read past the helping
# words between it and "have"/"got"
_THING_SUBJECTS = frozenset({"it", "its", "this", "that", "one"})
_BEFORE_HAVING = frozenset({"s", "has", "have", "ve", "d", "had"}) | english.words("done_markers")
_BEFORE_HAVING |= {"just", "still", "also", "now"}
# "he can have mine", "you may have it": a "have" given leave or promised, not had now
_MAY_HAVE = _MODALS | {"can", "could", "may", "might", "will", "would", "shall", "should", "to"}
_PREPOSITIONS = frozenset({"in", "to", "for", "with", "on", "of", "at"})
# What follows a command's verb: "bring *me*", "fetch *the* ...", "copy *my* ..."
_COMMAND_OBJECTS = frozenset(
    {"me", "us", "a", "an", "the", "my", "our", "some", "this", "these", "those", "her", "him"}
)
_POSSIBLY = english.words("possibility_words")
_DOUBTS = english.words("doubt_words")
_DEFERRALS = tuple(tuple(p.split()) for p in english.entries("deferrals"))
_SPEAKER_SUBJECTS = frozenset({"i", "we", "id", "ill", "im", "ive", "wed", "well"})
NEED_PHRASES = tuple(tuple(p.split()) for p in english.entries("need_phrases"))
_YOU = frozenset({"you", "u", "ya"})
# "would you be so kind as to ...", "would you be good enough to ...": the asked one's grace
_GRACIOUS = english.words("gracious_asks")
# How far a statement's verb is looked for after its subject: six words for a plain subject,
# ten where it carries a phrase of place ("the holly wreath on the reception desk is ...").
_PLAIN_SUBJECT = 7
_BARE_COPULAS = frozenset({"is", "are", "was", "were", "has", "have"})
# "the van is back from Pinewood", "stamp's back": a thing or person back again, told
_RETURN_COPULAS = frozenset({"is", "are", "was", "were"})
_RETURN_AFTER = frozenset({"from", "in", "at", "on", "again", "now", "already", "safe"})
_RETURN_SUBJECT = 4  # "the big white van is back"
_OTHERS_LACKS = tuple(tuple(p.split()) for p in english.entries("others_lack_phrases"))
_LACK_JOINERS = english.words("others_lack_joiners")
_THIRD_PERSONS = frozenset({"he", "she", "they"})
# people named by what they are, nobody of the office ("client", "patient")
_OUTSIDER_NOUNS = english.words("outsider_nouns") - english.words("statement_subjects")


def _outsider_possessive(word: str) -> bool:
    """ "clients" from "client's": a noun naming an outsider by what they are, with its
    possessive "s" (the words are folded: "customers" of "customer's")."""
    return word.endswith("s") and word[:-1] in _OUTSIDER_NOUNS


def _outsider_did(w: list[str]) -> bool:
    """ "client just signed contract 12", "buyer settled lot 40", "customer paid invoice 7":
    an outsider named by what they are, with its article dropped, then (after adverbs such as
    "just") a past verb: what someone outside did, told as the reason beside a request; never
    the verb's work asked of the office ("Who should sign your document?")."""
    if len(w) < 2 or w[0] not in _OUTSIDER_NOUNS:
        return False
    n = 1
    while n < len(w) - 1 and w[n] in _DONE_ADVERBS:
        n += 1
    return language.is_past_verb(w[n]) and not set(w[:n]) & _MODALS


# the adverbs between an outsider's bare name and their past verb ("client *just* signed")
_DONE_ADVERBS = frozenset({"just", "already", "finally", "now", "also", "only", "has", "have"})


def _verb_like(word: str) -> bool:
    """Whether a word may open or be a clause's verb ("print", "took"), or is a grammar word
    ("can", "could"): not the noun of a bare subject."""
    return (
        word in language.verb_lemmas(word)
        or language.is_finite_verb(word)
        or word in _MODALS
        or word in _AUX
        or "AUX" in language.lemmas(word)
    )


_SUBJECT_REACH = 11
_IN_PLACE_PHRASE = frozenset({"on", "in", "at", "by", "near", "under", "behind"})
# a preposition and a determiner open a noun phrase: the next word is its noun, never a
# finite verb ("from the shed", "in my drawer")
_NOUN_OPENERS = frozenset({"the", "a", "an", "my", "your", "our", "their", "his", "her", "its"})
_PREPOSITIONS = _IN_PLACE_PHRASE | {"from", "off", "into", "inside", "beside", "to"}


# The prepositions that take a person as their object: "for Rose", "to Mark", "from Will".
_PARTY_PREPOSITIONS = frozenset({"to", "for", "from", "with", "by", "off"})


def _after_preposition(w: list[str], n: int) -> bool:
    """Whether ``w[n]`` comes right after a preposition and a determiner ("from the shed")."""
    return n >= 2 and w[n - 1] in _NOUN_OPENERS and w[n - 2] in _PREPOSITIONS


# Words that only ever open a noun phrase: the word right after one is a modifier or the
# noun ("my *signed* contract", "the *printed* agenda"), never a finite verb. "her", "his"
# and "its" are left out: chat writes "its" for "it's", and "her" may be an object.
_ONLY_DETERMINERS = frozenset({"the", "a", "an", "my", "your", "our", "their"})


def _attributive(w: list[str], n: int) -> bool:
    """Whether ``w[n]`` is a past participle between a word that only opens a noun phrase
    and the noun after it ("my signed contract needs couriering"): then it describes the
    thing, and the statement's verb is later. Any other word there is read as before."""
    if n < 1 or n + 1 >= len(w) or w[n - 1] not in _ONLY_DETERMINERS:
        return False
    if w[n + 1] in _ONE:
        return False  # "the printed one": a thing picked by how it is, no statement's subject
    return language.is_past_participle(w[n]) and language.is_noun(w[n + 1])


_ONE = frozenset({"one", "ones"})


_SELF_PLANS = frozenset({"ill"})
_EMBEDDED_QUESTIONS = tuple(tuple(p.split()) for p in english.entries("embedded_questions"))
_REFLEXIVES = frozenset({"myself", "himself", "herself", "themselves", "ourselves"})
# "Wang doesn't need", and "Wang *hardly* needs": an adverb that denies the verb after it
# makes the statement a denial too ("rarely", "barely", "scarcely", "seldom")
_NEGATIONS = english.words("statement_negations") | english.words("negative_adverbs")
_SO = frozenset({"so", "then"})  # a reason, then the request it leads to
# Words that open how a task would be done, not on what: "print *in* colour", "copy *double*-sided"
_MANNER = english.words("manner_openers")
# The words before a facility that is the subject of a wished clause ("if only *the* printer")
_WISHED_SUBJECT_DETERMINERS = frozenset({"the", "this", "that", "our", "these", "those"})
_UNNAMED_DOERS = english.words("unnamed_doers")
_WISH_OPENERS = tuple(tuple(p.split()) for p in english.entries("wish_openers"))
# "I'd love a ... someday": the liking verbs of a wish, and the times that put it off for good
_LIKING = frozenset({"love", "like", "fancy"})
_SOMEDAY = tuple(tuple(p.split()) for p in english.entries("someday_times"))
_FOR_SPEAKER = frozenset({"i", "me", "my", "mine", "id", "im", "ive"})
_SELF_OFFERS = english.words("self_offers")  # "I'll get it myself": the requester's own plan
_NOTE_OPENERS = tuple(
    sorted((tuple(p.split()) for p in english.entries("note_openers")), key=lambda p: -len(p))
)
# the verbs that destroy a thing: "melt down the ring" is no note ("jot this down")
_DESTROYING = frozenset(
    p.split()[0] for key in ("destructive", "destructive_of_others") for p in english.entries(key)
)
_CONDITIONS = tuple(tuple(p.split()) for p in english.entries("condition_openers"))
# The question words that also open a clause of when ("when Wang is in, give him ...")
_WHEN_CLAUSES = frozenset({"when", "whenever"})
_LATER = tuple(tuple(p.split()) for p in english.entries("later_times"))
_DEADLINES = frozenset({"by", "before", "until", "till"})
_HEDGES = (("itd", "be"), ("it", "would", "be"), ("would", "be"), ("wouldnt", "it", "be"))
# What stands before a verb that is not a command: its subject, "to", a modal's contraction.
_SUBJECT_WORDS = english.words("subject_pronouns") | _SUBJECT_VERB | {"to", "ll", "d", "s"}


@dataclass(frozen=True)
class Act:
    """The act of one piece, with what it is about."""

    kind: Literal["question", "thanks", "wish", "withdrawal", "statement", "need"]
    question: QuestionKind | None = None
    relay: bool = False  # thanks to be passed on to someone else
    approval: bool = False  # "Love it.": a reaction to what was said, no thanks to anyone


# The titles said before a person's name ("Dr", "Mrs"), not the articles the titles list has.
_PERSON_TITLES = english.words("titles") - {"a", "an", "the", "our"}


# The articles and titles before a person's name after a causative "have" ("have the Boss
# sign it", "have Dr Osei sign it").
_NAME_OPENERS = english.words("titles")


# What opens the thing after a causative "have" ("have *my* proof signed", "have *it* done").
_THING_OPENERS = frozenset({"my", "our", "the", "this", "that", "these", "those", "it", "them"})


def _left_at_someones_place(w: list[str]) -> bool:
    """Whether the words name a person's own place as where a thing is left: "on her desk",
    "in my office", "at their workstation" (``core.receiving_place``)."""
    return any(
        a in MEET_AT and (b in PLACE_PRONOUNS or b in _OWN) and c in PLACE_WORDS
        for a, b, c in zip(w, w[1:], w[2:], strict=False)
    )


def _approval(w: list[str]) -> bool:
    """ "love it", "I absolutely love this", "loving it so much": the whole piece is degree
    words around one approving verb and its object ("it", "this"), nothing else."""
    verbs = [n for n, x in enumerate(w) if x in _APPROVAL_VERBS]
    if len(verbs) != 1 or verbs[0] + 1 >= len(w) or w[verbs[0] + 1] not in _APPROVAL_OBJECTS:
        return False
    rest = w[: verbs[0]] + w[verbs[0] + 2 :]
    return all(x in _APPROVAL_DEGREE for x in rest)


def _needs_to(w: list[str], n: int) -> bool:
    """ "the courier needs to sign": what they must do, not a thing they want."""
    return n + 1 < len(w) and w[n + 1] == "to"


def content(words: list[str]) -> list[str]:
    """The words after the openers: greetings, fillers, a stance adverb ("honestly") or
    phrase ("to be honest", "just so you know"), however many, in any order; "hi" alone says
    nothing to act on."""
    k = 0
    while k < len(words):
        phrase = phrase_at(words, k, _STANCE_AT)
        if phrase is not None:
            k += len(phrase)
        elif _stance_infinitive(words[k : k + 3]):
            k += 3  # "to be frank", "to be blunt": never a colleague called Frank
        elif words[k] in _OPENERS or language.is_stance_adverb(words[k]):
            k += 1
        else:
            break
    return words[k:]


def _stance_infinitive(w: list[str]) -> bool:
    """ "to be frank", "to be blunt", "to be clear": "to be" and an adjective whose -ly
    adverb is a stance adverb ("frankly"), the same stance said as an infinitive."""
    return len(w) == 3 and w[:2] == ["to", "be"] and language.is_stance_adverb(f"{w[2]}ly")


def _after_courtesy(w: list[str]) -> list[str]:
    """The words after a "please" that follows an opener ("mark this down please: ...")."""
    k = 0
    while k < len(w) and w[k] in ("please", "pls", "plz", "kindly"):
        k += 1
    return w[k:]


def _hedged(w: list[str]) -> tuple[str, ...] | None:
    """ "it'd be lovely if ...", "it would be so handy if ...": a hedged wish opener, with
    whatever word says how nice it would be (one or two words before "if")."""
    for head in _HEDGES:
        if _starts(w, head):
            for n in (1, 2):
                if w[len(head) + n : len(head) + n + 1] == ["if"]:
                    return tuple(w[: len(head) + n + 1])
                if w[len(head) + n : len(head) + n + 2] == ["to", "have"]:
                    return tuple(w[: len(head) + n + 2])  # "would be nice to have ..."
    return None


def _has_need_phrase(w: list[str]) -> bool:
    return _said_anywhere(w, _NEED_AT)


def _perfect_after(words: list[str]) -> bool:
    """A past participle just after "have" ("'ve lost", "have just misplaced"): the perfect,
    not having a thing; "got" is read as having ("I've got one")."""
    return any(language.is_past_verb(x) and x != "got" for x in words)


def _without_hedges(words: list[str]) -> list[str]:
    """``words`` less the speaker's hedges ("i think", "pretty sure"): "Olu's got one i think"
    tells what Olu has, not what the speaker has."""
    return without_phrases(words, _DOUBT_AT)


def _said_anywhere(words: list[str], index: PhraseIndex) -> bool:
    return any(phrase_at(words, n, index) is not None for n in range(len(words)))


_STANCE_AT = by_first_word(_STANCE)
_NEED_AT = by_first_word(NEED_PHRASES)
_DOUBT_AT = by_first_word(_SPEAKERS_DOUBT)
_DECLINING_THANKS_AT = by_first_word(_DECLINING_THANKS)
_DONE_MARKERS_AT = by_first_word(_DONE_MARKERS)
_PAST_TIMES_AT = by_first_word(_PAST_TIMES)
_DEFERRALS_AT = by_first_word(_DEFERRALS)


def _starts(words: list[str], phrase: tuple[str, ...], at: int = 0) -> bool:
    """Whether ``phrase`` is said at ``words[at]``. The reader asks this millions of times
    (every phrase list at every word): the first word is compared before any slice is made."""
    end = at + len(phrase)
    if end > len(words):
        return False
    if phrase and words[at] != phrase[0]:
        return False
    return tuple(words[at:end]) == phrase


# a thing's state said with its participle ("sample is labelled", "sample's labelled")
_BE_OR_HAVE = frozenset({"is", "was", "are", "were", "has", "have", "had"})
# the task kind whose words make a thing, never work done to one ("fix me a coffee")
_NO_WORK = frozenset({"make"})


def _passive(w: list[str], n: int) -> bool:
    """Whether "got" at ``n`` is the passive's ("got spilled", "got knocked over"): a past
    participle right after it that is no past form of a verb of having or giving to the
    speaker ("got given one" is had)."""
    nxt = w[n + 1] if n + 1 < len(w) else ""
    if w[n] != "got" or not language.is_past_participle(nxt):
        return False
    return not language.verb_lemmas(nxt) & {"give", "send"}


def _thing_subject(before: list[str]) -> bool:
    """Whether the subject said before a "have"/"got" of having is a thing ("it", "this one"),
    past the helping words and news marks between them ("it's already", "this one has")."""
    k = len(before)
    while k > 0 and before[k - 1] in _BEFORE_HAVING:
        k -= 1
    return k > 0 and before[k - 1] in _THING_SUBJECTS


class SpeechActs:
    """Classifies the pieces of a message against one office's vocabulary."""

    def __init__(self, lex: Lexicon) -> None:
        self.lex = lex
        self._known: frozenset[str] | None = None  # the office's words, read on first use
        # what may be a clause's subject before its verb ("courier leaves at 3"): the words of
        # the office's services and the one-word names of its facilities ("van leaves at 3",
        # where "the van" is the courier's)
        self._subject_words = lex.operation_words | frozenset(
            phrase for phrase in lex.facilities if " " not in phrase
        )
        # the words that ask for work on a thing: the office's operations by verb, near
        # form ("dying" of "dye"), noun ("a review") or a word of their names ("a read"),
        # and every task word but those of making ("fix" me a coffee says nothing of work
        # done to a thing); "moving", "delivering" hand it on, an errand
        self._work_words = (
            lex.operation_words
            | frozenset(
                w for kind, words in lex.cues.items() if kind not in _NO_WORK for w in words
            )
            | frozenset(lex.operation_nouns)
            | frozenset(w for name in lex.operation_names for w in name)
            | frozenset(said[0] for said in lex.near_forms.forms if len(said) == 1)
        )

    def withdrawal(self, words: list[str]) -> bool:
        """ "forget about the scissors", "never mind the stapler", "cancel my request"."""
        w = content(words)
        for head in _WITHDRAW_HEADS:
            if _starts(w, head):
                rest = w[len(head) :]
                if service_asked(self.lex, head, rest):
                    return False  # "scrap my old tyre" where the office scraps tyres
                if tuple(rest) in _WITHDRAW_WHOLE:
                    return True  # "actually no, don't bother": one withdrawal said twice
                if language.is_present_participle(rest[0]) if rest else False:
                    # "never mind copying this", "forget about printing it": the gerund of
                    # a service is what is withdrawn, its object, never a command
                    return True
                return not rest or not self._imperative(rest)
        # "no forget it", "nah never mind", "(oh) wait never mind", "no don't bother": a
        # refusal word or a "wait" before a withdrawal only stresses it ("wait for me"
        # withdraws nothing)
        if len(w) > 1 and w[0] in _REFUSING | {"wait"}:
            return tuple(w[1:]) in _WITHDRAW_WHOLE or self.withdrawal(w[1:])
        return False

    def had_already(self, words: list[str]) -> bool:
        """ "oh actually Ida just brought me one", "someone else already did it", "thanks
        anyway": what was asked for is had or done already, told after the request, so the
        request is withdrawn. A past task word (or "did", "found", "got") for the speaker or
        about "it", marked as news ("already", "actually") or said of "one"/"it"; a later
        fact with no such mark ("fetch the copies, Priya made them for me") is context."""
        w = [x for x in words if x not in ("oh", "ah", "ok", "okay", "well", "so")]
        if _said_anywhere(w, _DECLINING_THANKS_AT):
            return True
        w = _without_hedges(w)
        marked = bool(w) and _said_anywhere(w, _DONE_MARKERS_AT)
        # "got one already": a having marked as news opens no question ("got any tape?")
        news = marked and w[0] in _HAVE_NOW
        if not w or self._imperative(w) or w[0] in _MODALS or (w[0] in _AUX - {"did"} and not news):
            return False  # "could you ...", "did Ida bring one?" (a question) is no news
        if not marked and _said_anywhere(w, _PAST_TIMES_AT):
            return False  # "he lent me his last week": back-story told with the request
        mine = bool(set(w) & (_FOR_SPEAKER | {"us", "we", "weve"}))
        # "got one already, thanks": a having with its subject dropped is the speaker's
        mine = mine or w[0] in _HAVE_NOW
        for n, x in enumerate(w):
            if not language.is_past_verb(x) and x not in _HAVE_NOW:
                continue
            if x in _HAVE_NOW - {"got"} and _perfect_after(w[n + 1 : n + 3]):
                continue  # "I've lost mine": "have" of the perfect, its verb read next
            if x in _HAVE_NOW and n > 0 and w[n - 1] in _MAY_HAVE:
                continue  # "so he can have mine": an offer of the speaker's, nothing had
            if x in _HAVE_NOW and _thing_subject(w[:n]):
                continue  # "it's already got a stain on it": the thing's state
            if n > 0 and not set(w[:n]) & _FOR_SPEAKER and _passive(w, n):
                continue  # "tea got spilled on mine": what happened to a thing, not had
            lemmas = language.verb_lemmas(x) or {"have"}
            if not lemmas & (self.lex.cue_words | _DONE_VERBS):
                continue
            if taken_from_speaker(w, n, lemmas):
                continue  # "the intern borrowed mine": why the speaker asks, nothing had
            if mishap_to_thing(w, n, lemmas):
                continue  # "I dropped mine down the radiator": why the speaker asks
            after = set(w[n + 1 : n + 4])
            if x in _HAVE_NOW and _doing_after(w[n + 1 : n + 6]):
                continue  # "we've got a little one going for bloods": someone doing, not had
            if mine and (marked or after & _ONE_MORE):
                return True  # "Ida just brought me one", "I already have one"
            if marked and after & _THE_ERRAND:
                return True  # "someone else already did it"
        return False

    @staticmethod
    def defers(words: list[str]) -> bool:
        """ "I'll let you know", "will tell you when": the asking is put off; not the
        stance that opens a message ("just to let you know I'm off tomorrow")."""
        w = content(words)
        return _said_anywhere(w, _DEFERRALS_AT)

    def future_need(self, words: list[str], deferred: bool) -> bool:
        """ "I might need Hal's ruler later", "may need a calculator if ...": the speaker's
        need, only possible or for later, is not a request for now; with the asking put off
        in the same message ("..., I'll let you know") a later want is one too ("could I
        borrow it later? I'll let you know"). A command is always read as one."""
        w = content(words)
        if not w or self._imperative(w):
            return False
        at = next((n for n, x in enumerate(w[:7]) if x in _NEED or x in _BORROW), None)
        if at is None:
            return False
        before = w[:at]
        # the speaker's own verb, never a third person's "needs" ("Will needs ...": Will's),
        # nor "I'll need you to bring ...": the assistant asked, in so many words
        verb = w[at] in _NEED and not w[at].endswith("s") and not future_need.said_now(w)
        verb = verb and not (w[at + 1 : at + 2] and w[at + 1] in _YOU)
        if verb and future_need.speakers_future(before):
            return True  # "gonna need a ruler", "we're going to need the tape"
        if before and not (set(before) & (_SPEAKER_SUBJECTS | _POSSIBLY | _MODALS)):
            return False  # "Ida might need ...": someone else's, read as a need of theirs
        if before[:1] and before[0] in _MODALS and before[1:2] and before[1] in _FOR_SPEAKER:
            before = before[2:]  # "may I borrow ...": a polite question, not a "may" of doubt
            if before[:1] and before[0] in _POSSIBLY:
                before = before[1:]  # "could I possibly borrow ...": politer still
        if set(before) & _POSSIBLY and not (set(before) & _YOU):
            return True
        if verb and set(before) <= _SPEAKER_SUBJECTS | _POSSIBLY:
            # "I need scissors tomorrow", "need a ruler for the workshop later": put off by
            # a time after now in the need's own clause
            # "need the stamp for tomorrow": wanted ready for then, as "by tomorrow" is
            if self.later(future_need.need_clause(w, at), _DEADLINES | {"for"}):
                return True
        return deferred and self.later(w, events=True)

    def note(self, words: list[str]) -> list[str] | None:
        """ "note this down: the tape ran out", "for the record, ...": the words of a note
        to keep (after its opener), or None when the piece opens no note. The opener is read
        as a phrase, so a verb that is also someone's name ("mark this down") opens it too."""
        w = content(words)
        while w[:1] and w[0] in ("just", "also", "and", "so"):
            w = w[1:]  # "just for your records, ..."
        opener = next((p for p in _NOTE_OPENERS if _starts(w, p)), None)
        if opener is not None:
            return _after_courtesy(w[len(opener) :])
        # "<verb> this down": writing down, whatever the verb, unless it is a task word
        # ("bring this down to ..." is an errand) or one that destroys ("melt down the ring")
        for down in (["this", "down"], ["that", "down"], ["it", "down"], ["down"]):
            after = w[1 : 1 + len(down)]
            destroys = bool(w) and bool(language.verb_lemmas(w[0]) & _DESTROYING)
            if (
                after == down
                and language.verb_lemmas(w[0])
                and not destroys
                and w[0] not in self.lex.cue_words
            ):
                rest = w[1 + len(down) :]
                return None if rest[:1] == ["to"] else _after_courtesy(rest)
        return None

    def condition(self, words: list[str], asks: bool) -> bool:
        """ "if Hal ever needs a ruler", "in case anyone asks", "whenever Ida is back": a
        clause that says when, not what to do; not "if you could ..." (a polite request) nor
        "when is Ida back?" (a question)."""
        w = content(words)
        opener = next((p for p in _CONDITIONS if _starts(w, p)), None)
        if any(_starts(w, o) for o in _WISH_OPENERS):
            return False  # "if only Rich would lend me ...": a wish, read as one
        if opener is None or asks:
            return False
        rest = w[len(opener) :]
        if not rest or self._asks_you(rest) or self._imperative(rest) or self._minded(w):
            return False  # "if you could bring ...", "if you don't mind printing ..." is read on
        if self._main_clause(rest):
            return False  # "when you're free bring me a ruler": the request after it
        return not (w[0] in _WH and rest[0] in _AUX)  # "when is ...": a question

    def _main_clause(self, w: list[str]) -> bool:
        """A task word in command form after a condition with no comma ("if possible bring
        me ..."): not the condition's own verb ("if Wren needs to copy ...", "if Ida
        copies ...": after "to", a subject or a modal)."""
        for k in range(1, len(w)):
            before = w[k - 1]
            if before in _SUBJECT_WORDS or before in _MODALS or self._named(before):
                continue
            if self._imperative(w[k:]):
                return True
        return False

    @staticmethod
    def later(
        words: list[str], deadlines: frozenset[str] = _DEADLINES, *, events: bool = False
    ) -> bool:
        """ "... I could use later", "... tomorrow", "... on Friday": a time after now; not
        one after a word of ``deadlines`` ("by tomorrow": wanted ready by then, so now), nor
        one of the event the thing is for ("... I can borrow for the review at 2?": by then,
        so now); with ``events`` an event's time counts too (the asking put off in so many
        words: "... for the meeting at 3? I'll let you know" waits for the word)."""
        w = content(words) if events else future_need.without_events(content(words))
        if any(a == "on" and language.is_weekday(b) for a, b in itertools.pairwise(w)):
            return True
        if future_need.clock_time(w):
            return True  # "at 3", "at noon"
        return any(
            _starts(w, p, n) and (n == 0 or w[n - 1] not in deadlines)  # "by tomorrow": now
            for n in range(len(w))
            for p in _LATER
        )

    def wish(self, words: list[str]) -> bool:
        """A wish or prohibition about other people's conduct: nothing to fetch."""
        # "nobody's to use ...": "nobody is to use ...", not a possessive
        w = with_is(content([x for x in words if x not in ("please", "pls", "plz", "kindly")]))
        for n in range(len(w)):
            if any(_starts(w, p, n) for p in _NOBODY):
                return True  # "nobody take my mug", "make sure no one uses ..."
        if w[:1] and w[0] in _GUARD_VERBS and not _left_at_someones_place(w[1:]):
            # "leave it on her desk", "leave it in my office": where it is delivered to,
            # never "leave her alone"
            rest = set(w[1:])
            if w[0] in _PUTTING and not rest & _AWAY and handed_to_named(w[1:], self._named):
                return False  # "leave them with Fang", "on Fang's desk": handed to Fang
            if rest & _EVERYONE or rest & _AWAY:  # "keep everyone away from", "leave it alone"
                return True
            if self._kept_in_place(w[1:]):  # "leave May's ice pack in the fridge"
                return True
        if w[:2] in (["dont", "let"], ["do", "not"]) and set(w[2:4]) & _EVERYONE:
            return True  # "don't let anyone touch ..."
        return w[:2] == ["do", "not"] and w[2:3] == ["let"] and bool(set(w[3:5]) & _EVERYONE)

    def world_wish(self, words: list[str]) -> bool:
        """ "I wish the staff room had a kettle", "if only this place had ...": a wish about
        the place, asking nobody for anything (no person named, nothing for the speaker,
        nobody addressed); "if Hal could sign my form" is a request, read as one."""
        w = content(words)
        if self._someday_machine(w):
            return True  # "I'd love a proper espresso machine in here someday"
        opener = next((o for o in _WISH_OPENERS if _starts(w, o)), None) or _hedged(w)
        if opener is None:
            return False
        rest = w[len(opener) :]
        if not rest or set(rest) & (_YOU | _FOR_SPEAKER):
            return False
        if rest[0] in _UNNAMED_DOERS and rest[1:2] in (["would"], ["wd"]):
            return True  # "wish someone would refill the urn more often": others' habits
        tokens = self.lex.tokens(" ".join(rest))
        mentions = self.lex.scan(tokens)
        if any(m.kind in ("person", "self") for m in mentions):
            return False
        if not any(m.kind == "cue" for m in mentions):
            return True
        # "would be great if the coffee machine made hot chocolate one day", "if only the
        # printer printed in colour": the facility is the wished clause's subject, its task
        # word what the facility would do, nothing asked of anyone
        first = min(mentions, key=lambda m: m.start)
        before = {t.word for t in tokens[: first.start]}
        return first.kind == "facility" and before <= _WISHED_SUBJECT_DETERMINERS

    def _someday_machine(self, w: list[str]) -> bool:
        """ "I'd love a proper espresso machine in here someday", "would like a microwave up
        here one day": a machine the speaker would like the place to have, some time: a
        wish about the place, never the machine's product asked for now."""
        if not (set(w[:3]) & _LIKING) or not any(
            tuple(w[n : n + len(p)]) == p for n in range(len(w)) for p in _SOMEDAY
        ):
            return False
        mentions = self.lex.scan(self.lex.tokens(" ".join(w)))
        # "a coffee from the coffee machine at some point": the coffee is asked, later
        return any(m.kind == "facility" for m in mentions) and not any(
            m.kind in ("person", "item") for m in mentions
        )

    def thanks(self, words: list[str]) -> Act | None:
        w = content([x for x in words if x not in ("please", "pls", "plz", "kindly")])
        if _approval(w):
            return Act("thanks", approval=True)  # "Love it.", "I really love this": nothing asked
        if self._asks_you(w):
            w = w[next(n for n, x in enumerate(w) if x in _YOU) + 1 :]  # "could you thank ..."
            asked = True
        else:
            asked = False
        if w[:1] and w[0] in _RELAY - _THANKS and set(w[1:4]) & _THANKS:
            return Act("thanks", relay=True)  # "say thanks to Wang", "tell Wang thank you"
        if w[:1] == ["thank"] and w[1:2] and w[1] not in _YOU:
            return Act("thanks", relay=True)  # "thank Rich for the clipboard"
        if asked or self._command_inside(w):
            return None  # "could you bring ...", "so grateful to you fetch me ..."
        if thanks_ahead(w):
            return None  # "I'd be grateful for a box of staples": asked, with thanks ahead
        if set(w[:3]) & _THANKS:
            return Act("thanks")  # "thanks ...", "big thank you for ...", "much appreciated"
        if self._done_for_me(w):
            return Act("thanks")  # "you're a star for fetching the clipboard"
        if any(_starts(w, p) for p in _PRAISE) and not set(w) & (_WILLING | _MODALS):
            return Act("thanks")  # "you're a star", "you've been a great help"
        return None

    def _done_for_me(self, w: list[str]) -> bool:
        """ "... for fetching the clipboard": a task word as a gerund after "for", with no
        request wording: an act someone did, praised, not one asked for. A need said ("Gao
        needs some paper for printing") is what the thing is wanted for, never praise."""
        if self._imperative(w) or set(w) & _WILLING or (w[:1] and w[0] in _MODALS):
            return False
        if set(w) & (_NEED | {"needed"}):
            return False
        return any(
            a == "for"
            and b.endswith("ing")
            and bool({b, *language.verb_lemmas(b)} & self.lex.cue_words)
            for a, b in itertools.pairwise(w)
        )

    def _command_inside(self, w: list[str]) -> bool:
        """A command after an aside with no comma between ("I have faith in you bring me a
        ruler", "... in you please bring me ..."): a task word in its bare form, after
        "please" or after a word that is no subject, modal, "to" or determiner of it, with
        the speaker or a thing right after it ("bring me", "fetch the", "copy my"); "I have
        one copy left" has a noun there, not a command."""
        for k in range(2, len(w) - 1):
            x, before = w[k], w[k - 1]
            if x not in self.lex.cue_words or x not in language.verb_lemmas(x):
                continue
            aside_ends = before in _YOU and w[k - 2] in _PREPOSITIONS  # "faith in you bring"
            if (
                before not in ("please", "pls", "plz", "kindly")
                and not aside_ends
                and (
                    before in _SUBJECT_WORDS
                    or before in _MODALS
                    or before in _NEGATIONS  # "X doesn't need a ...": told, never a command
                    or before in _COMMAND_OBJECTS
                    or self._named(before)
                    or before.isdigit()
                    or before in ("one", "two", "and", "or", "the", "no")
                    # "the new lights make the bay look bright": a plural subject's own verb
                    or (before not in _YOU and language.is_plural_noun(before))
                )
            ):
                continue
            if w[k + 1] in _COMMAND_OBJECTS or self._named(w[k + 1].removesuffix("s")):
                return True
        return False

    def _minded(self, w: list[str]) -> bool:
        """ "I hope you don't mind bringing me ...", "if you wouldn't mind fetching ...": a
        task word as a gerund after "mind", with "you" just before: a request, hedged."""
        for n in range(1, len(w) - 1):
            if w[n] != "mind" or not set(w[max(0, n - 4) : n]) & _YOU:
                continue
            gerund = w[n + 1]
            if gerund.endswith("ing") and language.verb_lemmas(gerund) & self.lex.cue_words:
                return True
        return False

    def _graciously_asked(self, rest: list[str]) -> bool:
        """ "be so kind as to get ...", "be good enough to bring ...": after "would you", the
        asked one's grace, then "to" and a task's word ("... to tell me where Bo sits" is
        still a question)."""
        if rest[:1] != ["be"]:
            return False
        grace = next((n for n, w in enumerate(rest[1:4], 1) if w in _GRACIOUS), None)
        if grace is None:
            return False
        after = rest[grace + 1 : grace + 4]
        if "to" not in after or after.index("to") + 1 >= len(after):
            return False
        verb = after[after.index("to") + 1]
        return bool(language.verb_lemmas(verb) & self.lex.cue_words)

    @staticmethod
    def _asks_you(w: list[str]) -> bool:
        """ "could you ...", "if you could ...": someone is asked to do something."""
        return any(
            (a in _MODALS and b in _YOU) or (a in _YOU and b in _MODALS)
            for a, b in itertools.pairwise(w)
        )

    def question(self, words: list[str], asks: bool) -> QuestionKind | None:
        """Whether a piece is a question, and a polite request or a question for information."""
        w = content(words)
        if not w:
            return None
        for lead in _EMBEDDED_QUESTIONS:  # "I wonder if anyone has ...", "any idea who ..."
            if _starts(w, lead) and len(w) > len(lead):
                rest = w[len(lead) :]
                if rest[0] in ("if", "whether"):
                    inner = rest[1:]
                    if inner[1:2] and inner[0] in _ASKEES and inner[1] in _MODALS:
                        return "polite"  # "I was wondering if you could print ..."
                    rest = ["is", *inner]  # "if anyone has ...": a yes/no question
                return self.question(rest, asks=True) or "info"
        first, second = w[0], (w[1] if len(w) > 1 else "")
        if offered(w, asks):
            return "info"  # "would you like a ruler?": offered to the assistant, nothing asked
        if first in _WH:
            if second == "about":  # "how about a coffee?"
                return "polite"
            if first in _WHEN_CLAUSES and second not in _AUX and self._main_clause(w[1:]):
                # "when Wang is at the printer give him my file": a clause of when, then
                # the command, no comma between; "when is Wang back?" asks (its verb first)
                return None
            return "info"
        asked = second in _ASKEES or self._person_at(w, 1)
        if self.doubts_ability(w):
            return "info"  # "can you even carry a tea without spilling it?"
        if first in _MODALS and second in _YOU and w[2:5] == ["be", "able", "to"]:
            return "polite"  # "would you be able to bring me a pen?": asked, politely
        if first in _MODALS and second in _YOU and self._graciously_asked(w[2:]):
            return "polite"  # "would you be so kind as to get Ms Ede to sign my plan?"
        if service_asked_in_passive(w, self.lex.operation_words):
            return "polite"  # "could the proofs be comb-bound?": the office's work, asked
        if first in _MODALS and asked and "be" in w[2:4]:
            return "info"  # "will Ray be in tomorrow?"
        if first in _MODALS and second in _YOU and self._ability_only(w[2:]):
            return "info"  # "can you print in colour?": what it can do, nothing to act on
        if first in _MODALS and (asked or second in ("you", "u", "ya", "i", "we")):
            return "polite"  # "could you ...", "can someone lend me ...", "may I have ..."
        if first in _MODALS and second in ("not", "nt"):
            return "polite"
        if first == "do" and second in _DO_COMMANDED:
            return None  # "do the thing with my bottle": a command, not "do you ...?"
        if first in _AUX and first in _SUBJECT_VERB and not asks:
            return None  # "we're trying to ...": a contraction, not "were ...?"
        if first == "have" and not asks and self._causative(w):
            return None  # "have Ines stamp my lease": a request that she does it
        if first in _AUX and self._minded(w):
            return "polite"  # "do you mind copying my report?": asked, as "would you mind ..."
        if first in _AUX:
            if self._for_me(w):  # "does anyone have a stapler I could borrow?"
                # "... I could use later?": answered; "... I can use this afternoon?": now
                return "info" if self.later(w) and not used_later_today(w) else "polite"
            return "info"
        if asks and not self._imperative(w) and not (set(w) & _WILLING):
            return "info" if first in _AUX | _WH else None
        return None

    def statement(self, words: list[str]) -> bool:
        """A statement of fact, not a request: a subject, then a state or past verb, before
        any request wording ("my laptop cable is too short", "I spilled my tea")."""
        # "..., then have Wang sign it": the "then" joins, it is no subject told of
        w = self._one_word_name(self._untitled(after_sequence_word(content(words))))
        if len(w) < len(content(words)) and wanted_done_by(w):
            return False  # "and then the original signed by Dr Rao": a wanted state, asked
        if grumbled(words, self._named):
            return True  # "ugh", "argh Frank": an interjection of annoyance, to a colleague or not
        if wished_better(w, self._names_person):
            return True  # "wish i had a stapler that actually worked": a grumble, told
        if declines_more(w, self.lex.items):
            return True  # "no more water for me thanks": the speaker wants none
        if reports_done_work(w, self._asking_verb):
            return True  # "they've just been sharpened": work done, told; never asked again
        if no_work_told(w) and not set(w) & _YOU:
            return True  # "I have nothing to print": no work, told; never the work asked
        if poor_prospect(w, self._named):
            return True  # "no chance of getting my file printed by 4": venting, told
        if self._service_subject(w):
            return True  # "courier leaves at 3", "print is too small": told of the thing
        if told_with_modal(w, self._named):
            return True  # "van run might be off": a forecast about the thing, told
        if denied_ability(w):
            return True  # "can barely see a thing": the speaker's state, told
        if w and subject_of_fault(w, 0):
            return True  # "drive in slot 4 has died": a fault told, context for the ask
        if _own_one_does(w):
            return True  # "mine just crackle": what the speaker's own one does, told
        if _adjective_subject_told(w):
            return True  # "free chlorine looked low on my kit": told, "free" is no command
        if returned_told(w) and self.question(words, asks=False) is None:
            return True  # "van is back from Pinewood": a return told, whatever "van" names
        if not w or self._imperative(w) or self.question(words, asks=False) is not None:
            return False
        if service_command(w, self.lex.operation_words):
            return False  # "fax the booking confirmation to ...": a service asked for
        if set(words[1:]) & _PLEASE:
            # "a copy of my file printed for Zhang please": asked, not told ("pls is the
            # stapler here": a "please" that opens a question is read with the question)
            return False
        if grumble(w, self.lex.items.__contains__):
            return True  # "ugh still miles to go with these invoices": venting, told
        if work_told(w, self.lex.items, self._work_words):
            return True  # "the cup needs washing": how the thing is, not the thing asked for
        if part_told(w, self.lex.items, self._work_words):
            return True  # "the calculator needs new batteries": none kept, nothing to fetch
        if _has_need_phrase(w):
            return False  # "Chen is looking for a pen": a need
        if self._obliged_on_it(w):
            return False  # "Wang has to sign it": a need of the thing said before
        if self._lacks(w):
            return False  # "I've run out of wipes": said to the assistant, a want
        if facility_told(w, self.lex.facilities):
            return True  # "coffee machine's been making a weird noise": told of the machine
        if self._minded(w):
            return False  # "I hope you don't mind bringing me a pen": asked, gently
        if self._command_inside(w):
            return False  # "I have faith in you bring me a ruler": an aside, then the request
        pairs = itertools.pairwise(w)
        if any((a in _MODALS and b in _YOU) or (a in _YOU and b in _MODALS) for a, b in pairs):
            return False  # "I was wondering if you could print ..."
        if not self._named(w[0]) and outsider_reports(w):
            return True  # "Dad at reception says his son's lost his tie": their report, told
        if self._joined_lack(w):
            return True  # "the meeting is at 2 and Zoë has no headset": told, then asked
        if w[0] in _SELF_OFFERS and w[1:2] == ["to"]:
            return True  # "happy to lend it": the speaker offers, nobody asks
        if w[0] in _CANNOT and w[1:2] and w[1] in language.verb_lemmas(w[1]):
            return True  # "can't read these printouts": the speaker's own "I can't", a reason
        if w[-1] in _REFLEXIVES and w[0] not in _MODALS:
            return True  # "she'll get it herself": someone else's own plan
        wants = any(a == "to" and b in self.lex.cue_words for a, b in itertools.pairwise(w))
        if wants and w[-1] != "myself" and (w[0] in _SUBJECT_VERB or w[0] in ("i", "we", "id")):
            return False  # "I'm hoping to borrow a ruler": the speaker's own want
        if w[:2] in (["we", "will"], ["we", "ll"]):  # "we'll record the intro on the roof"
            w = ["i", "will", *w[2:]]
        if w[0] in _SELF_PLANS or w[:2] == ["i", "will"]:
            return not (
                len(w) > 1 and w[-1] not in ("myself", "ourselves") and set(w[1:3]) & _NEED
            )  # "I'll get it myself"
        if w[0] in _SUBJECT_VERB:
            return not (len(w) > 1 and (w[1] in _NEED or w[1] in _WILLING))  # "I'm out of ..."
        if self._doing_clause(w):
            return True  # "covering the river walk for Fen": what the speaker is doing
        if _asks_after_reason(w):
            return False  # "Fen asked me to lead the walk so could I get a vest"
        if (
            w[0] not in self.lex.cue_words
            and w[0] not in self.lex.items  # "scissors please": the thing asked for
            and w[0] not in language.verb_lemmas(w[0])  # "put it on ...": an imperative
            and not self._named(w[0])  # "rose needs ...": a name, not the verb "rise"
            and not self._possessive_name(w[0])  # "Frank's ...": a name's, not "franks"
            and w[0] not in _MODALS | _AUX | _WILLING
            and "AUX" not in language.lemmas(w[0])
            and language.is_finite_verb(w[0])
        ):
            return True  # "found one", "broke it"
        if w[0] in ("got", "found") and w[1:2] and w[1] in ("one", "some", "it", "them"):
            return True  # "got one already"
        if w[0] == "found" and w[1:2] and w[1] in ("the", "a", "an", "my", "mine", "his", "her"):
            return True  # "found the stapler in my drawer": a past find, never an errand
        if clipped_progressive(
            w,
            cue_words=self.lex.cue_words,
            asking_words=_MODALS | _WILLING | _NEED | _PLEASE,
            verb_like=_verb_like,
            names_item=self._names_item,
        ):
            return True  # "two parcels going out with Otto later": under way, context
        possessive = self._possessive_name(w[0])  # "Hal's clipboard snapped"
        # "client's laptop lost a key": an outsider's thing, its article dropped
        possessive = possessive or _outsider_possessive(w[0])
        # "Mr Okafor's order is ...": the title taken off (``_untitled``), a stranger's thing
        possessive = possessive or (len(w) < len(words) and self._stranger_possessive(w[0]))
        if (
            w[0] not in _SUBJECTS
            and not self._named(w[0])
            and not possessive
            and not self._numbered_subject(w)
            and not self._bare_subject(w)
            and not self._thing_happened(w)
            and not _outsider_did(w)
        ):
            return False
        # a subject may carry where its thing is ("the holly wreath on the reception desk
        # is shedding"): the verb is looked for past such a phrase, not only in six words
        placed = bool(set(w[1:_PLAIN_SUBJECT]) & _IN_PLACE_PHRASE)
        for n in range(1, min(len(w), _SUBJECT_REACH if placed else _PLAIN_SUBJECT)):
            if n >= _PLAIN_SUBJECT and w[n] in self.lex.cue_words:
                return False  # far from the subject, an errand's verb: read as before
            x = w[n]
            if x in _NEGATIONS:
                return True  # "Wang doesn't need the stapler any more": nobody asks
            if x in _NEED or x in _WILLING or x in ("mean", "meant"):
                return False  # "I need", "Min needs", "I'd like", "I meant a stapler"
            if x in self.lex.items:
                continue  # "Hu's scissors": an item of the office, never the verb
            if any(" ".join(w[n : n + k]) in self.lex.items for k in (2, 3)):
                continue  # "some wet wipes would be great": a name's first word, no verb
            if _plural_subjects_verb(w, n):
                return True  # "the new drills make a lot of noise": told of the drills
            if linked_state(w, n, _SUBJECTS):
                return True  # "the copies look great": how the copies are, told
            if self._work_obliged(w, n):
                return False  # "my banner has to be fireproofed": the work is needed
            if self._sent_to_someone(w, n):
                return False  # "my stapler should go to Lee": where it is wanted, asked
            if _after_preposition(w, n) or self._in_office_phrase(w, n):
                continue  # "some twine from the (potting) shed": a noun, not "shed"
            if w[n - 1] in _PARTY_PREPOSITIONS and self._named(x):
                # "..., both for Rose": a colleague's name after a preposition is its
                # object (as the lexicon reads "to Mark"), never the verb ("rose" of "rise")
                continue
            if _attributive(w, n):
                continue  # "my signed contract needs ...": a modifier, not "signed"
            if compound_modifier(w, n, _NEED):
                continue  # "the crew list needs ...": a noun of the subject, not "crowed"
            if x in _STATE_VERBS or (x not in _RECEIVE and language.is_finite_verb(x)):
                return True  # "Hal printed his rota yesterday": a task word, told as done
            if x in ("ve", "have", "has", "had", "got") and n + 1 < len(w) and w[n + 1] != "to":
                return True  # "I've got some", "I have one"
        return False

    def _asking_verb(self, word: str) -> bool:
        """A word that may be the verb of a request ("bring", "print"): before "has been", it
        makes the clause a relative one inside that request."""
        return word in self.lex.cue_words or word in self.lex.operation_words

    def _thing_happened(self, w: list[str]) -> bool:
        """ "coffee spilled all over my keyboard", "water got on my notes", "tea keeps
        getting spilled on it", "coffee got spilled on it": a thing of the office said bare,
        then a past or present verb that is no errand's (or the passive's "got"): what
        happened, told (the reason beside a request), not the thing asked for."""
        if state_told(w, self.lex.items):
            return True  # "stapler is working fine now": how the thing is, told
        if len(w) < 2 or w[0] not in self.lex.items:
            return False
        if w[1] in _BE_OR_HAVE and w[2:3] and language.is_past_participle(w[2]):
            # "sample is labelled and in the rack" ("sample's labelled", its "'s" read as
            # "has"): the thing's state, told; not
            # "scissors are needed" (a need, read as before)
            return not language.verb_lemmas(w[2]) & {"need", "want", "require"}
        verb, cues = w[1], self.lex.cue_words
        spread = w[2:3] and w[2] in _SPREAD  # "water got on my notes", "tea went everywhere"
        errand = verb in cues or any(lemma in cues for lemma in language.verb_lemmas(verb))
        if errand and not spread and not _passive(w, 1):
            # "coffee made for Wang": the errand's own verb, read as before; "coffee got
            # spilled on it" is the passive's "got", what happened to the thing
            return False
        # "tea keeps getting spilled on it": what keeps happening to it, told as well
        # ("stapler is urgent" is still the thing asked for: no "is", "has", "does")
        keeps = language.is_third_person_verb(verb) and not (
            language.verb_lemmas(verb) & {"be", "have", "do"}
        )
        said = language.is_past_verb(verb) or keeps
        return said and language.is_finite_verb(verb)

    def _in_office_phrase(self, w: list[str], n: int) -> bool:
        """Whether ``w[n]`` is the last word of a name of several words of the office's
        items, facilities or places ("potting shed", "print room"): a noun there, never
        the statement's verb."""
        lex = self.lex
        for size in (2, 3, 4):
            if n + 1 < size:
                break
            phrase = " ".join(w[n + 1 - size : n + 1])
            if phrase in lex.items or phrase in lex.facilities or phrase in lex.places:
                return True
        return False

    def _numbered_subject(self, w: list[str]) -> bool:
        """ "Court 3 is locked", "bay 2's flooded": a noun and its number name a room or a
        thing (whether the office lists it or not), a subject like "the lab", though the noun
        alone may be a verb ("court", "room"); never a request's verb and its count ("print
        3 copies", "need 2 pens"); "bidder 12 just settled lot 40" is one such subject too,
        its adverb read past."""
        k = 2  # "bidder 12 just settled lot 40": an adverb before the verb
        while k < len(w) - 1 and w[k] in _DONE_ADVERBS:
            k += 1
        return (
            len(w) > k
            and w[0].isalpha()
            and any(c.isdigit() for c in w[1])
            and (w[k] in _BARE_COPULAS or language.is_past_participle(w[k]))  # "3's locked"
            and w[0] not in self.lex.cue_words
            and w[0] not in _MODALS | _AUX | _NEED | _WILLING | _PLEASE
        )

    def _bare_subject(self, w: list[str]) -> bool:
        """ "kettle is broken", "uv bulb has gone": chat drops the subject's article; one to
        three words that are no verb, then "is"/"has", are still a subject. Only for things
        the office does not know: its own items and places are read by the rules for them
        ("scissors are in the kitchenette": where they are)."""
        if w[0] in _WILLING and w[1:2] == ["have"] and self._causative(w[1:]):
            return False  # "pls have holly sign it": a request marker is nobody's subject
        for n in range(1, min(len(w), 4)):
            if w[n] in _BARE_COPULAS:
                known = self._office_words()
                *before, head = w[:n]  # "hall clock has stopped": a head noun may be a verb too
                head_noun = not _verb_like(head) or (
                    language.is_noun(head) and head not in _MODALS | _AUX
                )
                return (
                    head_noun and all(not _verb_like(x) for x in before) and not set(w[:n]) & known
                )
        return False

    def _joined_lack(self, w: list[str]) -> bool:
        """ "sound check is at 2 and Zoë has no headset", "the printer is down again and Ana's
        got no charger", "rehearsal's at 4 so Sam is without a mug": a clause that asks
        nothing (a subject and its verb, no "you", no "please"), joined by "and"/"but"/"so" to
        a colleague's lack of a thing, is told: the request, if any, is said after it. A
        first clause that opens with a command ("bring me a pen and ...") is no statement."""
        for k, joiner in enumerate(w):
            if joiner not in _LACK_JOINERS or k < 2 or not self._others_lack(w[k + 1 :]):
                continue
            before = w[:k]
            if set(w) & (_YOU | _PLEASE) or self._imperative(before):
                return False
            if before[1] in _COMMAND_OBJECTS or before[0] in _MODALS | _AUX | _WILLING:
                return False  # "bring me ...", "could ...": a command or a question
            # a subject then its verb within a few words ("the audit starts at 10"), or a
            # time said with no verb ("soundcheck at 2")
            return any(
                x in _BARE_COPULAS or (language.is_finite_verb(x) and x not in _MODALS)
                for x in before[1:5]
            ) or any(a == "at" and b[:1].isdigit() for a, b in itertools.pairwise(before[1:]))
        return False

    def _others_lack(self, w: list[str]) -> bool:
        """ "Zoë has no headset", "Zoë Marsh hasn't got one", "Ana's got no charger", "she is
        without a mug": a colleague (or "he"/"she"/"they") said to lack a thing."""
        n = 0
        while n < len(w) and n < 3 and self._named(w[n]):
            n += 1
        if n == 0 and w[:1] and w[0] in _THIRD_PERSONS:
            n = 1
        elif n == 0 and w[:1] and self._possessive_name(w[0]):
            n = 1  # "Ana's got no": "'s" read as "has"
        if n == 0:
            return False
        rest = w[n:]
        return any(tuple(rest[: len(p)]) == p for p in _OTHERS_LACKS) and len(rest) > 1

    def _described_party(self, subject: list[str]) -> bool:
        """ "the carver", "a new lad": an article, at most one describing word and a noun that
        names nothing of this office (no thing, place or colleague): someone described, not
        the speaker, whose need is told ("the carver needs a set square" had fetched one for
        the speaker). "my laptop" (the speaker's own) and "the stapler" (a thing) are none."""
        if not 2 <= len(subject) <= 3 or subject[0] not in DESCRIBING_ARTICLES:
            return False
        head = subject[-1]
        if not language.is_noun(head) or head in self._office_words():
            return False
        return not any(self._named(x) for x in subject[1:])

    def _office_words(self) -> frozenset[str]:
        if self._known is None:
            lex = self.lex
            phrases = (*lex.items, *lex.facilities, *lex.places, *lex.people, *lex.name_words)
            # a whole name of one word ("scissors"), or a name's last word ("the kettle" of
            # "staff kettle"); a word that only leads a longer name ("reg" of "reg plates")
            # names nothing alone: "reg is on the job card" is told
            self._known = frozenset(p.split()[-1] for p in phrases if p)
        return self._known

    def _sent_to_someone(self, w: list[str], n: int) -> bool:
        """ "should go (back) to Lee", "has to go over to Sam", "is for Ana" from ``n``: an
        obligation to go, or "is for", then a colleague's name: the thing is wanted with that
        person, a delivery asked for (the reader resolves the thing and the person), not a
        fact told. "went to Ana yesterday" is past, told; "should be in my drawer" names
        nobody."""
        verb = obliged_verb(w, n)
        if verb is not None and w[verb] == "go":
            at = verb + 1
            while at < len(w) and w[at] in _GOING_PARTICLES:
                at += 1
            return w[at : at + 1] == ["to"] and at + 1 < len(w) and self._named(w[at + 1])
        if w[n] in ("is", "are") and w[n + 1 : n + 2] == ["for"] and n + 2 < len(w):
            return self._named(w[n + 2])
        return False

    def _work_obliged(self, w: list[str], n: int) -> bool:
        """ "has to be / must be" and a form of one of the office's own verbs from ``n``:
        work said to be needed on the subject ("my banner has to be fireproofed before the
        show"), as "needs to be" says it, not a fact told."""
        verb = obliged_verb(w, n)
        if verb is None or w[verb] != "be" or verb + 1 >= len(w):
            return False
        said = w[verb + 1 :]
        near = self.lex.near_forms.forms  # "has to be flame-proofed": a near form of one
        return said[0] in self.lex.operation_words or any(
            tuple(said[:size]) in near for size in (1, 2)
        )

    def need(self, words: list[str], requester_words: frozenset[str]) -> bool:
        """ "Min needs scissors": someone else's need, said as a fact."""
        w = content(words)
        if _has_need_phrase(w) and (self._named(w[0]) or self._has_done(w)):
            return True  # "Min asked for scissors", "jonno's asked for a thermometer"
        if outsider_wants(w):
            return True  # "a friend of mine needs a ruler": their want, told
        if self._obliged_on_it(w):
            return True  # "Wang has to sign it": as "Wang needs to sign it", told
        for n in range(1, min(len(w), 5)):
            if w[n] in _NEED and w[n].endswith("s"):
                subject = w[:n]
                if outsider_subject(subject) and not _needs_to(w, n):
                    return True  # "a visitor wants a coffee": a want, not the speaker's ask
                if (
                    self._described_party(subject)
                    and w[n + 1 : n + 2]
                    and (w[n + 1] in LACKED_OPENERS)
                ):
                    return True  # "the carver needs a set square": theirs, told
                return not set(subject) & requester_words and self._person_at(w, 0)
            if w[n] in _NEED and outsider_subject(w[:n]) and not _needs_to(w, n):
                return True  # "the visitors want coffee": their want, said as a fact
        return False

    def request(self, words: list[str]) -> bool:
        """Request wording: an imperative, a polite question, or the requester's own need."""
        w = content(words)
        if not w:
            return False
        if outsider_wants(w):
            return False  # "a client of ours could do with a pen": their want, no "could" asked
        said = set(w)
        if len(w) > 1 and self._named(w[0]) and w[1] in _NEED and w[1].endswith("s"):
            # "Will needs the umbrella": a name before a third person's verb is its subject,
            # never the "will" of a request (a modal takes no "-s" verb after it)
            said = set(w[1:])
        if told_with_modal(w, self._named):
            return False  # "the coffee could run out": a forecast, no "could" asked
        if self._imperative(w) or said & _WILLING or self._minded(w):
            return True
        return w[0] in ("i", "we", "id", "im", "need", "needs") and bool(set(w[:4]) & _NEED)

    def _lacks(self, w: list[str]) -> bool:
        """ "I've run out of wipes", "no pens left": the speaker's own lack of an item, no
        statement (``screen.unasked`` reads it as asking)."""
        return speaker_lacks(w, given_thing(self.lex))

    @staticmethod
    def doubts_ability(words: list[str]) -> bool:
        """ "can you even carry a tea?", "could you really lift that without dropping it?":
        a question about what the assistant can do, said with doubt, not a request. Only
        after "can/could you"; "could you possibly ..." stays a polite request."""
        w = content(words)
        if w[:3] in (["are", "you", "able"], ["are", "you", "even"], ["are", "you", "really"]):
            return True  # "are you able to ...?": asked of what it can do, not "would you be
            # able to ...", a polite request
        if len(w) < 3 or w[0] not in _MODALS or w[1] not in _YOU:
            return False
        if w[2] in _DOUBTS:
            return True
        return any(
            a == "without" and b.endswith("ing") and bool(language.verb_lemmas(b))
            for a, b in itertools.pairwise(w[2:])
        )

    # -- helpers -------------------------------------------------------------------------
    def _names_item(self, w: list[str]) -> bool:
        """Whether the words name one of the office's items (a phrase of up to three words)."""
        return any(
            " ".join(w[n : n + k]) in self.lex.items for n in range(len(w)) for k in (1, 2, 3)
        )

    def _names_person(self, w: list[str]) -> bool:
        """Whether the words name a person of the office (a name, a role)."""
        mentions = self.lex.scan(self.lex.tokens(" ".join(w)))
        return any(m.kind == "person" for m in mentions)

    def _possessive_name(self, word: str) -> bool:
        """ "franks" from "Frank's": a name of the office with its possessive "s"."""
        return word.endswith("s") and self._named(word[:-1])

    def _has_done(self, w: list[str]) -> bool:
        """ "jonno's asked for ...": a name's "'s" before a past participle is "has", the
        name the subject, never an owner."""
        return len(w) > 1 and self._possessive_name(w[0]) and language.is_past_participle(w[1])

    def _doing_clause(self, w: list[str]) -> bool:
        """A piece that opens with a present participle no errand asks for, its subject left
        out ("covering the river walk for Fen", "standing in for Fen today", "running late"):
        what the speaker is doing, the reason for a request, never one. A person named in it
        ("for Fen") is context, not the one the request's thing goes to. An errand's own
        participle ("bringing me a pen would be great", "printing my slides") is no such
        clause, nor one about a thing of the office ("looking for a hole punch")."""
        first = w[0]
        if not first.endswith("ing") or first in self.lex.items or self._named(first):
            return False
        lemmas = language.verb_lemmas(first)
        if not lemmas or first in lemmas or lemmas & self.lex.cue_words:
            return False  # no verb, a plain verb ("swing by ..."), or an errand's own verb
        if self._names_item(w):
            return False  # "looking for a hole punch": about a thing, read as before
        return not _asks_after_reason(w)  # "standing in for Fen so could I get a vest"

    def _ability_only(self, w: list[str]) -> bool:
        """ "print in colour", "copy double-sided", "scan": a task verb with no object, only
        a manner or nothing after it, so nothing of the office to act on."""
        if not w or w[0] not in self.lex.cue_words:
            return False
        rest = w[1:]
        if rest and rest[0] not in _MANNER:
            return False
        return not any(x in self.lex.items or self._named(x) for x in rest)

    def _kept_in_place(self, w: list[str]) -> bool:
        """ "... in the fridge", "... at the print corner": left where a facility keeps it, not
        taken to anyone ("leave my form on Hal's desk" names a person: a delivery)."""
        if any(self._named(x) for x in w):
            return False
        for n, x in enumerate(w):
            if x in _IN_PLACE:
                after = " ".join(y for y in w[n + 1 : n + 5] if y not in ("the", "a", "our"))
                if any(after.startswith(f) for f in self.lex.facilities):
                    return True
        return False

    def imperative(self, words: list[str]) -> bool:
        """A command: a task word first, after the openers ("please just bring ...")."""
        return self._imperative(content(words))

    def _imperative(self, w: list[str]) -> bool:
        k = 0
        while k < len(w) and w[k] in ("please", "pls", "plz", "kindly", "just", "also", "then"):
            k += 1
        if k < len(w) and w[k] in _PUTTING and _left_at_someones_place(w[k + 1 :]):
            return True  # "leave it / put mine on her desk": where it is delivered, a command
        if self._service_subject(w[k:]):
            return False  # "print is too small on this form": the word is the subject
        if told_with_modal(w[k:], self._named):
            return False  # "frank might be pricey": a modal after it, so it is the subject
        if subject_of_fault(w, k):
            return False  # "print queue 3 is jammed": the subject of a fault, no command
        if opens_with_place_name(w[k:], (*self.lex.facilities, *self.lex.places)):
            return False  # "drying room's roasting again": the room's name, its subject
        return k < len(w) and w[k] in self.lex.cue_words and w[k] not in _NEED

    def _service_subject(self, w: list[str]) -> bool:
        """ "courier leaves at 3", "post goes at 4", "van leaves at 3": a service's word or a
        facility's one-word name as its clause's subject."""
        return service_noun_subject(w, self._subject_words, self.lex.items, self._named)

    def _for_me(self, w: list[str]) -> bool:
        """ "... I could borrow", "... lend me one", "... for me": the asker wants it."""
        joined = " ".join(w)
        return bool(set(w) & _BORROW) or " for me" in f" {joined}" or " me " in f" {joined} "

    def owner_work(self, words: list[str]) -> bool:
        """ "Robin needs to sign my condition report", "P has to stamp our form": someone
        named, obliged to do a person's work on the speaker's own thing, whatever the
        obligation phrase ("needs to", "has to", "must", "should"); not one told as past
        ("had to sign"). Said alone, it is the owner's request for that work."""
        w = content(words)
        for at in range(1, min(len(w), 4)):
            if not all(self._named(x) for x in w[:at]):
                return False
            verb = obliged_verb(w, at)
            if verb is not None:
                past = "had" in w[at:verb]  # "Robin had to sign my report": told as done
                work = w[verb] in PERSON_WORK and bool(_OWN & set(w[verb + 1 : verb + 3]))
                return work and not past
        return False

    def _obliged_on_it(self, w: list[str]) -> bool:
        """ "Wang has to sign it before it goes to HR", "Ida must stamp them": someone named,
        obliged to do a person's work on a thing said before by a pronoun (the speaker's, "I've
        got the incident form"): their need of the thing, said as a fact, as "Wang needs to
        sign it" is (restated and asked, never done unasked); not one told as past ("had
        to"), nor one on "my form" (``owner_work``)."""
        for at in range(1, min(len(w), 4)):
            if not all(self._named(x) for x in w[:at]):
                return False
            verb = obliged_verb(w, at)
            if verb is not None:
                past = "had" in w[at:verb]
                after = [x for x in w[verb + 1 : verb + 3] if x not in _WORK_PARTICLES]
                said_before = after[:1] and after[0] in _SAID_BEFORE
                return w[verb] in PERSON_WORK and bool(said_before) and not past
        return False

    def _named(self, word: str) -> bool:
        return word in self.lex.name_words or word in self.lex.people

    def _one_word_name(self, w: list[str]) -> list[str]:
        """The words with a name of several words that opens them said as one ("Hye-jin's
        cans have packed in" reads as "Hyejin's cans have packed in"): a hyphen or a space
        inside a name splits it into words, and the subject is then no name at the start, so a
        statement about a colleague's thing was read as a request for it. The name is said by
        a word of it that names the person alone (the joined word, else its last word), its
        possessive "s" kept."""
        for n in (3, 2):
            head = w[:n]
            if len(head) < n or len(w) == n:
                continue
            last = head[-1]
            owned = last.endswith("s") and " ".join([*head[:-1], last[:-1]]) in self.lex.people
            if not owned and " ".join(head) not in self.lex.people:
                continue
            bare = [*head[:-1], last[:-1]] if owned else head
            for one in ("".join(bare), bare[-1]):
                if self._named(one):
                    return [one + ("s" if owned else ""), *w[n:]]
        return w

    def _untitled(self, w: list[str]) -> list[str]:
        """The words without a title before the name that opens them ("Dr Osei signed it"
        reads as "Osei signed it"): the subject is the person, the title no verb."""
        if len(w) > 1 and w[0] in _PERSON_TITLES and self._named(w[1]):
            return w[1:]
        if len(w) > 2 and w[0] in _PERSON_TITLES and self._stranger_possessive(w[1]):
            return w[1:]  # "Mr Okafor's order is ...": a stranger's thing, its owner no verb
        return w

    def _stranger_possessive(self, word: str) -> bool:
        """ "okafors" of "Mr Okafor's": a possessive after a title, of a name nobody of the
        office has (a colleague's own is ``_possessive_name``)."""
        return (
            word.endswith("s")
            and not self._named(word[:-1])
            and not self._named(word)
            and word not in _SUBJECTS
            and not _verb_like(word)
        )

    def _causative(self, w: list[str]) -> bool:
        """ "have Ines stamp my lease", "have the Boss sign it": "have", a person's name or
        role (after an article or title), then a verb in its plain form: someone made to do
        something, not "have you got ...?"; and "have my proof signed by Femi": "have", the
        thing, then a task word's participle."""
        if w[1:2] and w[1] in _THING_OPENERS:
            for x in w[2:6]:
                if x in self.lex.cue_words and self._participle(x):
                    return True
        if len(w) > 2 and w[1] in _UNNAMED_DOERS and w[1] not in _GROUP_DOERS:
            # "have somebody sign my contract": someone unnamed made to do it (who, asked),
            # not "have somebody signed it?" nor "have anyone seen my pen?"
            return w[2] in language.verb_lemmas(w[2])
        k = 1
        while k < 3 and k < len(w) and w[k] in _NAME_OPENERS and not self._named_or_role(w[k]):
            k += 1  # "have *the* Boss sign my form", "have Dr Osei sign it"
        start = k
        while k < len(w) and k < start + 3 and self._named_or_role(w[k]):
            k += 1
        for at in (1, start):  # "have (the) Sister Brennan sign it": an alias declared whole
            for n in (3, 2):
                if " ".join(w[at : at + n]) in self.lex.people:
                    start, k = min(start, at), max(k, at + n)
        if k == start or k >= len(w):
            return False
        return w[k] in language.verb_lemmas(w[k])

    def _participle(self, word: str) -> bool:
        """A past participle, also of a task word the dictionary knows only as a noun
        ("couriered" of an office's "courier"): its "-ed" form."""
        if language.is_past_participle(word):
            return True
        return word.endswith("ed") and (
            word[:-2] in self.lex.cue_words or word[:-1] in self.lex.cue_words
        )

    def _named_or_role(self, word: str) -> bool:
        """A word of a colleague's name, or a role only they hold ("boss" of "the Boss")."""
        return self._named(word) or word in self.lex.roles

    def _person_at(self, w: list[str], n: int) -> bool:
        k = n
        while k < len(w) and k < n + 3:
            if w[k] in self.lex.name_words or w[k] in self.lex.people:
                return True
            k += 1
        return False


# what opens a verb's object ("make *the* bay look bright", "make *a* lot of noise")
_VERB_OBJECT_OPENERS = english.words("object_starts") | frozenset({"me", "us", "it", "them"})


# A possessive pronoun that stands for the speaker's or someone's thing ("mine just crackle")
_OWN_ONES = frozenset({"mine", "ours", "yours", "hers", "theirs"})


def _own_one_does(w: list[str]) -> bool:
    """ "mine just crackle", "mine crackle too": a thing said by its owner's pronoun, then
    (past one adverb) a plain verb that ends the clause or takes its object: what it does,
    told (the reason beside a request), never the thing asked for."""
    if len(w) < 2 or w[0] not in _OWN_ONES:
        return False
    n = 2 if len(w) > 2 and "ADV" in language.lemmas(w[1]) else 1
    x = w[n] if n < len(w) else ""
    return (
        bool(x)
        and x in language.verb_lemmas(x)
        and x not in _MODALS | _AUX | _PLEASE  # "mine please": the own one asked for
        and "AUX" not in language.lemmas(x)
        and (n + 1 == len(w) or w[n + 1] in _VERB_OBJECT_OPENERS or w[n + 1] in ("too", "again"))
    )


def _plural_subjects_verb(w: list[str], n: int) -> bool:
    """Whether ``w[n]`` is a plain verb with its object after it, right after the plural
    noun that ends a subject opened by a determiner ("the new lights make the bay ...",
    "these drills make a lot ..."): a verb agreeing with it, told, not a command (which
    opens with its verb); "the standards team need ..." is a compound noun's head."""
    x, before = w[n], w[n - 1]
    if n >= 3 and "ADV" in language.lemmas(before) and not language.is_plural_noun(before):
        before = w[n - 2]  # "my headphones *just* crackle": an adverb before the verb
    return (
        n >= 2
        # "make *the* bay": a verb and its object; or the verb ends the clause ("my
        # headphones just crackle")
        and (n + 1 == len(w) or w[n + 1] in _VERB_OBJECT_OPENERS)
        and w[0] in _SUBJECTS
        and x in language.verb_lemmas(x)
        and x not in _MODALS | _AUX
        and "AUX" not in language.lemmas(x)
        and before not in _YOU
        and language.is_plural_noun(before)
    )


def _asks_after_reason(w: list[str]) -> bool:
    """Whether a request follows a reason in one piece: "so" or "then" right before a
    request modal or marker ("... so could I get a vest", "... so please bring one")."""
    return any(a in _SO and (b in _MODALS or b in _WILLING) for a, b in itertools.pairwise(w))


def _doing_after(rest: list[str]) -> bool:
    """ "(got) a little one going for bloods", "(have) one intern measuring the hall",
    "someone coming in at two": what is had is doing something (a present participle right
    after "one"/"someone", or after the noun "one" counts), a small clause of what is
    happening, not the thing asked for had already."""
    for k, x in enumerate(rest):
        if x not in ("one", "someone", "somebody"):
            continue
        doing = rest[k + 1 : k + 3] if x == "one" else rest[k + 1 : k + 2]
        if x == "one" and doing[:1] and doing[0] in _A_THINGS_WAY:
            continue  # "I've got one coming from stores": the thing itself, on its way
        if any(language.is_present_participle(d) for d in doing):
            return True
    return False


# what a thing had is said to be doing: on its way or waiting somewhere ("got one coming")
_A_THINGS_WAY = frozenset({"coming", "arriving", "being", "waiting", "sitting", "lying"})


def _adjective_subject_told(w: list[str]) -> bool:
    """ "free chlorine looked low", "clean towels ran out": an adjective and a noun, then a past
    verb, is a subject told of, never a command whose verb the adjective also is ("free",
    "clean", "empty"); read as one, the clause's later thing ("on my kit") was asked about."""
    if len(w) < 3 or "ADJ" not in language.lemmas(w[0]):
        return False
    return language.is_noun(w[1]) and language.is_past_verb(w[2])


def returned_told(w: list[str]) -> bool:
    """ "van is back from Pinewood", "the stamp is back": a subject of one to a few words that
    are no asking words, "is"/"are" and "back", then nothing or where it came from: a return
    told, context only, whatever the subject names in the office (an item's word, a service's
    verb: "stamp is back from Leeds" is no stamping asked); the capitalised word after its
    "from" is where it came back from, nobody to look up (blind round 252)."""
    for k in range(1, min(len(w) - 1, _RETURN_SUBJECT + 1)):
        if w[k] not in _RETURN_COPULAS:
            continue
        before = set(w[:k])
        if before & (_YOU | _PLEASE | _MODALS | _AUX | _WH) or w[k + 1] != "back":
            return False
        return len(w) == k + 2 or w[k + 2] in _RETURN_AFTER
    return False
