"""The speech-act stage: what each piece of a message does, read once from its words and
passed forward with the piece (``Acts``), so the screen's rules judge a piece by what this
stage found instead of reading its words again.

The features are those of ``speech`` (a request, a question, thanks, a wish, a withdrawal, a
statement, a third person's need, a note, a condition, a need put off until later), each
read on the piece's own words; the one feature of the whole message, whether it puts its
need off ("I'll need it later"), is read once per message (``acts_reader``) and given to
every piece's reading.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.asides import without_asides
from assistantx.agents.symbolic.reading.indirect_asks import chance_reworded, indirect_ask
from assistantx.agents.symbolic.reading.modal_subject import modals_as_subjects
from assistantx.agents.symbolic.reading.offers import offered
from assistantx.agents.symbolic.reading.speech import Act, QuestionKind, SpeechActs, content
from assistantx.agents.symbolic.reading.subject_adverbs import without_subject_adverbs
from assistantx.core import english

# Chat's laughs: one that closes a piece ("... if I just walked over myself haha") is no word
# of it, as one that opens it is an opener (``speech_openers``); read without it.
_LAUGHS = english.words("chat_laughs")
# Words that do not change whether a piece withdraws: "oh, never mind", "ok forget it",
# "just skip it".
WITHDRAWAL_FILLERS = frozenset({"actually", "oh", "ok", "okay", "please", "just"})


@dataclass(frozen=True)
class Acts:
    """What one piece of a message does, by its words (``speech``'s readings of them)."""

    request: bool  # request wording: an imperative, a polite question, one's own need
    imperative: bool  # a command ("bring me ...")
    question: QuestionKind | None  # "polite" (a request asked) or "info" (answered in words)
    doubts_ability: bool  # "can you even carry ...?"
    thanks: Act | None  # thanks, and whether it is to be passed on
    wish: bool  # "please keep everyone away from Mao's seal"
    world_wish: bool  # "I wish the printer worked": nothing anyone can bring
    withdrawal: bool  # "forget about the scissors", "never mind"
    had_already: bool  # "Ida already brought me one"
    statement: bool  # "my laptop cable is too short"
    need: bool  # "Min needs scissors": a third person's need said as a fact
    note: tuple[str, ...] | None  # the words of a note to keep, after its opener
    note_asks: bool  # the note's words are themselves a request ("please note I need ...")
    condition: bool  # "if Hal ever needs a ruler": says when, not what to do
    defers: bool  # the piece puts its need off ("not now, later")
    future_need: bool  # a need that may come later, in a message that puts it off
    later: bool  # names a later time ("this afternoon")
    # "Robin needs to sign my report": someone's work by hand on the speaker's own thing;
    # said alone in a message, the owner's request for that work (``owner_work_asked``)
    owner_work: bool = False


def without_fillers(words: list[str]) -> list[str]:
    """A piece's words without the fillers a withdrawal is read through."""
    return [w for w in words if w not in WITHDRAWAL_FILLERS]


def without_closing_laughs(words: list[str]) -> list[str]:
    """A piece's words without the laughs that close it ("... myself haha")."""
    end = len(words)
    while end > 1 and words[end - 1] in _LAUGHS:
        end -= 1
    return words if end == len(words) else words[:end]


def _indirect(speech: SpeechActs, words: list[str], asks: bool) -> QuestionKind | None:
    """A polite indirect ask's kind by the verb it asks for; a doubt of what the assistant
    can do ("could you bring it without dropping it?") is left to be answered and offered."""
    if offered(content(words), asks):
        return None  # "would you like a ruler?": an offer, not a verb asked for
    kind = indirect_ask(content(words), speech.lex.cue_words)
    return None if kind == "polite" and speech.doubts_ability(words) else kind


def acts_reader(
    speech: SpeechActs, self_words: frozenset[str], message_words: list[str]
) -> Callable[[list[str], bool], Acts]:
    """How the pieces of one message are read: ``message_words`` are the whole message's,
    read once for whether it puts its need off; the reader takes a piece's words and
    whether it ends with a question mark."""
    deferred = speech.defers(message_words)
    lex = speech.lex

    def names(word: str) -> bool:
        return word in lex.people or word in lex.name_words

    def read(words: list[str], asks: bool) -> Acts:
        words = without_closing_laughs(words)
        # "any chance I could nab ...": read as the question it softens ("could I nab ...")
        words = chance_reworded(words) or words
        # "Zhang definitely has to sign": the adverb says how sure, the subject is Zhang's
        words = without_subject_adverbs(words, names)
        note = speech.note(words)  # a note keeps its words as said ("note: May needs tape")
        # "May needs her tape back": a name before its verb in -s, no modal (modal_subject);
        # the two acts that read a named subject themselves ("Will needs the umbrella" is
        # Will's need, restated and asked) keep the name as said
        as_said = words
        words = modals_as_subjects(words)
        return Acts(
            request=speech.request(as_said),
            imperative=speech.imperative(words),
            # a polite indirect ask is read by the verb it asks for ("would somebody be able
            # to bring me ...", "would anyone know where ..."), else by the question's shape
            question=_indirect(speech, words, asks) or speech.question(words, asks),
            doubts_ability=speech.doubts_ability(words),
            thanks=speech.thanks(words),
            wish=speech.wish(words),
            world_wish=speech.world_wish(words),
            withdrawal=speech.withdrawal(without_fillers(words)),
            had_already=speech.had_already(words),
            # "..., and a coffee for me while you are at it": the aside's "you are" states
            # nothing, the piece is the thing asked for besides
            statement=speech.statement(without_asides(words)),
            need=speech.need(as_said, self_words),
            note=tuple(note) if note is not None else None,
            note_asks=bool(note) and speech.request(note or []),
            condition=speech.condition(words, asks),
            defers=speech.defers(words),
            future_need=speech.future_need(words, deferred),
            later=speech.later(words),
            owner_work=speech.owner_work(words),
        )

    return read
