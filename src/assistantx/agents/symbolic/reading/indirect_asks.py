"""Polite indirect asks: a question put to someone ("would somebody be able to bring me a glue
stick?", "is anyone able to grab me a pen?", "would it be possible to get ...", "any chance
someone could fetch ...") is read by the verb it asks for, not by its question shape.

The asking frame (a modal or "is/are" and whoever is asked, "would it be possible (for X) to",
"(is there) any chance (that) X could") is set aside with the words that only soften it
("possibly", "please", "be able to"); what is left starts with the verb asked for:

* an office task verb in its plain form with something after it ("bring me ...", "fetch the
  ..."): a polite request;
* a verb followed by a question word ("know where ...", "tell me who ...", "find out
  whether ..."): a question for information, answered in words, whatever the verb;
* anything else (a task verb with only a manner after it, "can you print in colour?"): not
  decided here (``None``), the speech-act stage's own reading stands; so does a doubt of what
  the assistant can do ("could you bring it without dropping it?", ``SpeechActs``).

The frame's words are English function words of the package's data (``data/english.yaml``);
the task verbs are the office's (``Lexicon.cue_words``), so nothing here names an office.
"""

from __future__ import annotations

from assistantx.agents.symbolic.reading.speech import QuestionKind
from assistantx.core import english, language

_MODALS = english.words("request_modals")
_WH = english.words("wh_words") | {"whether", "if"}
_POSSIBLY = english.words("possibility_words")
# Those a request can be put to: the assistant or anyone at all (not "I"/"we": "could I
# have ..." asks for the speaker, the speech stage reads it).
_ASKED = english.words("request_askees") - {"i", "we", "the", "robot"}
# Words that soften the ask without changing what is asked: "possibly", "please", "be able to".
_SOFTENERS = _POSSIBLY | {"please", "kindly", "just", "quickly", "ever", "be", "able", "to"}
# Between a verb and an embedded question: "tell *me* where", "find *out* who".
_BEFORE_WH = frozenset({"me", "us", "out"})
_BE = frozenset({"is", "are"})
# "print *in* colour", "copy *double*-sided": how a task would be done, with nothing to do it on
_MANNER = english.words("manner_openers")
_YOU = frozenset({"you", "u", "ya"})


def asked_verb_at(w: list[str]) -> int | None:
    """Where the verb asked for starts in ``w`` (the words after the openers), or None where
    ``w`` does not open with an asking frame."""
    k = _frame_end(w)
    if k is None:
        return None
    while k < len(w) and (w[k] in _SOFTENERS or w[k] in _MODALS):
        k += 1
    return k if k < len(w) else None


def _frame_end(w: list[str]) -> int | None:
    """The index just after an asking frame at the head of ``w``."""
    if len(w) < 3:
        return None
    if w[0] in _MODALS and w[1] in _ASKED:
        return 2  # "would somebody ...", "could you possibly ..."
    if w[0] in _BE and w[1] in _ASKED - _YOU and w[2] == "able":
        return 2  # "is anyone able to grab me ..." ("are you able to" asks what I can do)
    k = None
    if w[0] in _MODALS and w[1:4] == ["it", "be", "possible"]:
        k = 4  # "would it be possible (for someone) to get ..."
    elif w[0] in _BE and w[1:3] == ["it", "possible"]:
        k = 3  # "is it possible (for someone) to bring ...": the same ask, not "is X on?"
    if k is not None:
        if w[k : k + 1] == ["for"] and w[k + 1 : k + 2] and w[k + 1] in _ASKED:
            k += 2
        return k if w[k : k + 1] == ["to"] else None
    at = w.index("chance") if "chance" in w[:4] else None
    if at is not None and w[at - 1 : at] == ["any"]:
        k = at + 1  # "(is there) any chance (that) someone could fetch ..."
        if w[k : k + 1] == ["that"]:
            k += 1
        if w[k : k + 1] and w[k] in _ASKED and w[k + 1 : k + 2] and w[k + 1] in _MODALS:
            return k + 2
    return None


# Who may follow "any chance (that)": the speaker asking for themself, or anyone asked; or
# the thing the work is asked on, said by a pronoun ("any chance *it* could go through the
# wash") or a noun phrase opened by a determiner ("any chance *my apron* could be washed").
_CHANCE_SUBJECTS = english.words("request_askees") - {"the", "robot"}
_CHANCE_THINGS = english.words("subject_pronouns") | english.words("placeholder_determiners")
_CHANCE_OPENERS = english.words("modifier_determiners")
_CHANCE_PHRASE = 4  # "my old grey apron" before the modal


def _chance_subject_end(w: list[str], k: int) -> int | None:
    """Where the subject that ``w`` says at ``k`` ends, right before a modal: one asked or a
    pronoun ("you", "it"), or a determiner's noun phrase ("my apron"); else None."""
    if len(w) > k + 2 and w[k] in _CHANCE_SUBJECTS | _CHANCE_THINGS and w[k + 1] in _MODALS:
        return k + 1
    if k < len(w) and w[k] in _CHANCE_OPENERS:
        for end in range(k + 2, min(k + 1 + _CHANCE_PHRASE, len(w) - 1)):
            if w[end] in _MODALS:
                return end
            if w[end] in _CHANCE_OPENERS:
                return None
    return None


def chance_reworded(w: list[str]) -> list[str] | None:
    """ "(is there) any chance (that) I could nab Åsa's lens" as the question it softens,
    "could I nab Åsa's lens"; "any chance of a long lens" as "could I have a long lens";
    None where ``w`` does not open so. The speech stage then reads the plain question."""
    k = 2 if w[:2] == ["is", "there"] else 0
    if w[k : k + 2] != ["any", "chance"]:
        return None
    k += 2
    if w[k : k + 1] == ["of"] and len(w) > k + 1:
        return ["could", "i", "have", *w[k + 1 :]]
    if w[k : k + 1] == ["that"]:
        k += 1
    end = _chance_subject_end(w, k)
    if end is None:
        return None
    return [w[end], *w[k:end], *w[end + 1 :]]


def indirect_ask(w: list[str], task_verbs: frozenset[str]) -> QuestionKind | None:
    """ "polite" where an asking frame asks for an office task done on something, "info"
    where it asks to be told or to know something (an embedded question), else None."""
    k = asked_verb_at(w)
    if k is None:
        return None
    rest = w[k + 1 :]
    while rest and rest[0] in _BEFORE_WH:
        rest = rest[1:]
    if rest and rest[0] in _WH:
        return "info"  # "would anyone know where ...", "is anyone able to tell me who ..."
    verb, after = w[k], w[k + 1 : k + 2]
    if verb in task_verbs and verb in language.verb_lemmas(verb) and after:
        if after[0] in _MANNER:
            return None  # "can you print in colour?": what can be done, nothing to do it on
        return "polite"  # "would somebody be able to bring me a glue stick"
    return None
