"""The requester's own paper said in an everyday noun the office does not list: "take my
report to Olive", "email my memo to Sam", where the office's personal paper is a "document"
(its other names "form", "contract"). In a request of two parts ("take my report to Olive,
then bring me a cuppa") the unread noun made the first part vanish while the second was done.

"my" and a noun of the English list ``paper_nouns`` that no name of the office reads (a plain
word, perhaps after a modifier or two: "my draft memo", "my referral letter") is the office's
paper when it has one candidate: its one personal paper (signable, or named by such a noun),
else, asked to be sent on ("email", "forward"), its one electronic file. The stages after the
lexicon then read it as they read the paper's own name (a file forwarded or printed, the paper
carried). Where the office has no such one thing, the phrase is left a plain word and asked
about (``unread_paper``), never dropped. A noun before another noun ("my report card") is the
first part of a compound, not the paper; a colleague's ("Sam's report") is not the
requester's own, and stays as it was; a noun that is a word of one of the office's longer
item names ("notes" of its "session notes") is the office's own word, read as before.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.compound_heads import modifies_a_noun
from assistantx.agents.symbolic.reading.forwarded_theirs import forwarded_phrase
from assistantx.agents.symbolic.reading.mention_view import MentionView as Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language, task_kinds
from assistantx.core.office import Office
from assistantx.memory.names import normalize

PAPER_NOUNS = english.words("paper_nouns")
_COMMON = english.words("common")
_SENDING = english.words("send_words")
FILE_NOUNS = english.words("file_nouns")
# the everyday nouns of papers and files, a phrase's head after a word that says its topic
DOCUMENT_NOUNS = PAPER_NOUNS | english.words("paper_heads") | FILE_NOUNS
_FILE_VERBS = english.words("file_verbs")
_DATA_NOUNS = english.words("data_nouns")
_ASKING = english.words("asking_words")
_PARTICLES = frozenset({"out", "up", "off", "down", "away", "through", "over"})
# The determiners before a kind of people's paper ("*the* trustees' report")
_KIND_DETERMINERS = english.words("modifier_determiners")
# Whom a thing is for, said as the verb's object before it ("print *me* the plan")
_SPEAKER_OBJECTS = frozenset({"me", "us"})
# the verbs that have work done on their object ("get my swab tested")
_CAUSING = frozenset({"get", "have"})
_MODIFIERS = 2  # plain words between "my" and the paper noun ("my draft expenses report")
# the ordinary heads of a paper document, said of the operation's own paper ("document_heads")
_DOCUMENT_HEADS = english.words("document_heads")
_WORKED_MODIFIERS = 4  # "shred my old alarm code sheet": modifiers before such a head
# what ends a noun phrase besides a clause's opening ("my sheet *and* a coffee")
_JOINS = frozenset({"and", "then", "or"})


def personal_papers(office: Office) -> tuple[str, ...]:
    """The office's personal papers: personal item types, not electronic, that are signed or
    named by an everyday paper noun."""
    return tuple(
        t.id
        for t in office.item_types
        if t.kind == "personal"
        and not t.electronic
        and (
            t.signable
            or any(w in PAPER_NOUNS for n in (t.name, *t.synonyms) for w in normalize(n).split())
        )
    )


def paper_phrase(
    mentions: Sequence[Mention],
    n: int,
    tokens: Sequence[Token],
    known: Callable[[str], bool],
    heads: frozenset[str] | set[str] = PAPER_NOUNS,
    openers: tuple[str, ...] = ("self",),
) -> int | None:
    """Where ``mentions[n]`` is "my" (or another possessive of ``openers``' kinds), the index
    of the mention of the paper noun (one of ``heads``) that heads the phrase it opens ("my
    [draft] memo"), or None."""
    opener = mentions[n]
    if opener.kind not in openers or not opener.possessive:
        return None
    end = opener.end
    for k in range(n + 1, min(len(mentions), n + 2 + _MODIFIERS)):
        m = mentions[k]
        if m.kind != "word" or m.start != end or tokens[m.start].opens:
            return None
        word = m.ids[0]
        if word not in heads and (word in _COMMON or not word.replace("-", "").isalpha()):
            return None
        after = mentions[k + 1] if k + 1 < len(mentions) else None
        if (
            after is not None
            and after.kind == "word"
            and after.start == m.end
            and after.ids[0] in heads
        ):
            end = m.end  # "my draft proposal": the last of the nouns is the head
            continue
        if word in heads and not tokens[m.start].corrected:
            if modifies_a_noun(tokens, m.end, known):
                return None  # "my report card": a compound, its head another noun
            if after is not None and after.kind == "item" and after.start == m.end:
                return None  # "my report file": the file
            return k
        end = m.end
    return None


@dataclass(frozen=True)
class OwnPapers:
    """What an office's papers are, read once: its personal papers and the words of its item
    names."""

    papers: tuple[str, ...]
    named: frozenset[str]
    file_type: str | None
    # each form of an operation's verbs → the item types of the operations it names
    worked: tuple[tuple[str, frozenset[str]], ...] = ()
    # the words of the office's names of things and facilities: what a paper may be about
    topics: frozenset[str] = frozenset()
    # each form of a person's work on a paper with a tool ("stamp") → the office's paper
    person_worked: tuple[tuple[str, frozenset[str]], ...] = ()

    @classmethod
    def from_office(cls, office: Office) -> OwnPapers:
        return cls(
            personal_papers(office),
            _item_name_words(office),
            office.file_type(),
            _worked_on(office),
            _item_name_words(office) | _facility_name_words(office),
            _person_worked_on(office),
        )

    def guessed(
        self, tokens: Sequence[Token], mentions: Sequence[Mention], found: Collection[int]
    ) -> dict[int, str]:
        """ "shred my old medical questionnaire", where shredding takes a document: a noun
        after "my" (as typed, not a rewrite) that no name of the office reads, the object of
        a verb of operations that take one item type ("shred my ...", "print out my ..."), is
        the requester's item of that type. A guess from the work asked, never from the noun:
        the reader restates it before acting ("Shall I shred your document for you?").
        ``found``: mentions read already."""
        out: dict[int, str] = {}
        for n, opener in enumerate(mentions):
            # "print me the fire drill plan": the article has no mention; the phrase's first
            # word opens it
            at = opener.start - 1
            article = (
                at >= 0
                and tokens[at].word == "the"
                and opener.kind == "word"
                and (n == 0 or mentions[n - 1].end <= at)
            )
            if not article and (opener.kind != "self" or not opener.possessive):
                continue
            if not article and tokens[opener.start].typed not in ("", "my"):
                continue  # "the rota I typed up", read as "my rota": the speaker's own doing
            first, start = (n, at) if article else (n + 1, opener.start)
            head, end = None, opener.start if article else opener.end
            caused = _causing(tokens, start)
            for k in range(first, min(len(mentions), first + 1 + _MODIFIERS)):
                m = mentions[k]
                if m.kind != "word" or m.start != end or tokens[m.start].opens or k in found:
                    break
                if not _plain(m.ids[0]):
                    break  # "shred my questionnaire please": the phrase ends before it
                head, end = k, m.end
            after = mentions[head + 1] if head is not None and head + 1 < len(mentions) else None
            done = (
                caused
                and after is not None
                and after.start == end
                and self._work_done(tokens[after.start].word)
            )
            if head is None or (
                not done
                and after is not None
                and after.start == end
                and (after.kind == "item" or (after.kind == "word" and _plain(after.ids[0])))
            ):
                continue  # nothing plain after "my", or a noun of a longer phrase
            word = mentions[head].ids[0]
            topic = article and self.topic_paper(mentions, head)
            # "copy the sample log" where "delegation log" names the office's paper: a word of
            # a longer name of the office still heads a topic compound on its own
            if (word in self.named and not topic) or word in _COMMON or not word.isalpha():
                continue
            if tokens[mentions[head].start].corrected or not _may_be_noun(word):
                continue
            if article and not (_for_the_speaker(tokens, start, end) or topic):
                continue  # "print the fire drill plan" for nobody said: whose is not known
            # "get my swab tested": the work is the participle after the thing
            verb = tokens[end].word if done else _verb_before(tokens, start)
            types = {t for form, ts in self.worked if form == verb for t in ts}
            if not types and article and word not in DOCUMENT_NOUNS and _phrase_ends(tokens, end):
                # "seal the cert for me" ("my" papers are the seal's own paper in the frames
                # already: "stamp my lease with his embosser"): a person's work, on a phrase
                # that ends there (a word after it may go on naming the paper: "sign my
                # merch *order* form" is read by the paper's own names); an everyday paper
                # noun ("my lease") is the office's paper by ``found``, no guess
                types = {t for form, ts in self.person_worked if form == verb for t in ts}
            if len(types) == 1 and (not topic or self._paper_or_file(next(iter(types)))):
                out[head] = next(iter(types))
        return out

    def _work_done(self, word: str) -> bool:
        """Whether ``word`` is the past participle of one of the office's operation verbs
        ("tested", "printed"): the work a causative asks done on the thing before it."""
        return language.is_past_participle(word) and any(form == word for form, _ in self.worked)

    def topic_paper(self, mentions: Sequence[Mention], head: int) -> bool:
        """ "copy the *book* list", "print my *fridge* rota": a word the office names a thing
        or a facility by, right before a paper's or a file's everyday noun (``compound_heads``
        read it a plain word), says what that paper is about; the phrase is a paper, and the
        work asked says which of the office's (its paper, its file). "the fire drill plan" (no
        word of the office) and "the tea rota" laminated (laminating takes no paper) stay
        unknown."""
        if head < 1 or mentions[head].ids[0] not in DOCUMENT_NOUNS:
            return False
        before = mentions[head - 1]
        return (
            before.kind == "word"
            and before.end == mentions[head].start
            # a noun before another is said in the singular ("the tube log" of "tubes")
            and (before.ids[0] in self.topics or language.plural(before.ids[0]) in self.topics)
        )

    def _paper_or_file(self, type_id: str) -> bool:
        return type_id in self.papers or type_id == self.file_type

    def found(
        self, tokens: Sequence[Token], mentions: Sequence[Mention], known: Callable[[str], bool]
    ) -> dict[int, str]:
        """Which of ``mentions`` (by index) is the requester's paper said in an everyday
        noun, and the office's one candidate item it is (see the module's text)."""
        found: dict[int, str] = {}
        for n in range(len(mentions)):
            worked = self._worked_paper(tokens, mentions, n)
            if worked is not None:
                found[worked[0]] = worked[1]
                continue
            k = self._colleagues_data(tokens, mentions, n, known)
            if k is not None and self.file_type is not None:
                found[k] = self.file_type
                continue
            k = forwarded_phrase(tokens, mentions, n, self.named)
            if k is not None and self.file_type is not None:
                # "forward me Wang's budget pack": only a file can be forwarded
                found[k] = self.file_type
                continue
            # "the trustees' report": a kind of people's paper is the requester's, as "my"
            openers = ("word",) if kind_of_people(tokens, mentions[n]) else ("self",)
            k = paper_phrase(mentions, n, tokens, known, openers=openers)
            if k is None and self.file_type is not None:
                # "send Sam my profiler capture": a noun of what a computer keeps, with a
                # verb whose input is a file, is the requester's electronic file
                k = paper_phrase(
                    mentions, n, tokens, known, PAPER_NOUNS | FILE_NOUNS, openers=openers
                )
                if k is None or not _file_verb(tokens, mentions[k].start):
                    continue
                said = {t.word for t in tokens[mentions[n].end : mentions[k].end]}
                if not said & self.named:
                    found[k] = self.file_type
                continue
            if k is None or mentions[k].ids[0] in self.named:
                continue  # "my vet notes" where the file is the "session notes": as before
            meant = self.papers[0] if len(self.papers) == 1 else None
            if not self.papers and self.file_type is not None:
                sentence = _sentence(tokens, mentions[k].start)
                # "email my memo", "print my draft": a paper noun sent on, or the object of
                # a verb whose input is a file, is the requester's file
                if {t.word for t in sentence} & _SENDING or _file_verb(tokens, mentions[k].start):
                    meant = self.file_type
            if meant is not None:
                found[k] = meant
        return found

    def _worked_paper(
        self, tokens: Sequence[Token], mentions: Sequence[Mention], n: int
    ) -> tuple[int, str] | None:
        """ "shred my old alarm code sheet", where shredding takes the office's one personal
        paper: "my" (as typed), then plain words ending in an ordinary head of a paper document
        (``document_heads``) that ends the phrase, the object of a verb whose operations take
        that paper and nothing else, is the requester's paper: the mention of the head and the
        paper's item type, or None. The head may be a word of a longer name of the office
        ("job sheet"): the work says which thing it is. A head the office lists as another
        thing, or a noun that is no paper's ("my old coffee"), is read as before."""
        opener = mentions[n]
        if opener.kind != "self" or not opener.possessive:
            return None
        if tokens[opener.start].typed not in ("", "my"):
            return None
        verb = _verb_before(tokens, opener.start)
        types = {t for form, ts in self.worked if form == verb for t in ts}
        if len(types) != 1 or not set(types) <= set(self.papers):
            return None
        end = opener.end
        for k in range(n + 1, min(len(mentions), n + 2 + _WORKED_MODIFIERS)):
            m = mentions[k]
            if m.kind != "word" or m.start != end or tokens[m.start].opens:
                return None
            word = m.ids[0]
            if tokens[m.start].corrected or not _plain(word) or not word.isalpha():
                return None
            end = m.end
            if word in _DOCUMENT_HEADS and (
                _phrase_ends(tokens, end) or tokens[end].word in _JOINS
            ):
                return k, next(iter(types))
        return None

    def _colleagues_data(
        self,
        tokens: Sequence[Token],
        mentions: Sequence[Mention],
        n: int,
        known: Callable[[str], bool],
    ) -> int | None:
        """ "need Ivy's plate reader data", "get me Tom's survey results", "her gel images":
        a colleague's possessive before a noun of what an instrument or a computer records
        (``data_nouns``, after a modifier or two that name none of the office's items) is
        that colleague's electronic file, where the office has one; elsewhere it is left a
        plain word and asked about, as before."""
        if self.file_type is None:
            return None
        k = paper_phrase(mentions, n, tokens, known, _DATA_NOUNS, openers=("person", "pronoun"))
        if k is None:
            return None
        said = {t.word for t in tokens[mentions[n].end : mentions[k].end]}
        return None if said & self.named else k


def kind_of_people(tokens: Sequence[Token], m: Mention) -> bool:
    """ "the trustees'", "the governors'": a plural of people in lower case, its apostrophe
    after the s, after a determiner: a kind of paper's owners, nobody of the office."""
    if m.kind != "word" or not m.possessive or m.start < 1:
        return False
    text = tokens[m.start].text
    if not text[:1].islower() or not text.endswith(("s'", "s’")):
        return False
    return tokens[m.start - 1].word in _KIND_DETERMINERS and language.is_plural_noun(m.ids[0])


def _verb_before(tokens: Sequence[Token], k: int) -> str | None:
    """The word that may govern the phrase at token ``k``: the one just before it, or before
    a particle ("shred my ...", "print out my ..."; in "drop it at my desk" it is "at", no
    verb); None at the message's start."""
    j = k - 1
    if j >= 0 and tokens[j].word in _PARTICLES and not tokens[j].opens:
        j -= 1
    if j >= 1 and tokens[j].word in _SPEAKER_OBJECTS and not tokens[j].opens:
        j -= 1  # "print me my ...", "print me the ...": the verb before whom it is for
    return tokens[j].word if j >= 0 else None


def _causing(tokens: Sequence[Token], k: int) -> bool:
    """Whether the phrase at token ``k`` is the object of a causative's verb ("get my swab
    tested", "have my form stamped"): the work asked is the participle after it."""
    return k >= 1 and not tokens[k].opens and tokens[k - 1].word in _CAUSING


# what may follow a paper's phrase at its end ("stamp the cert *for* me", "... *please*")
_PHRASE_ENDS = frozenset({"for", "with", "please", "pls", "plz", "thanks", "asap", "today"})


def _phrase_ends(tokens: Sequence[Token], end: int) -> bool:
    """Whether the noun phrase ending before token ``end`` ends there: the text's or the
    clause's end, or a word that never goes on naming a thing."""
    if end >= len(tokens):
        return True
    after = tokens[end]
    return after.opens or after.after_pause or after.word in _PHRASE_ENDS


def _for_the_speaker(tokens: Sequence[Token], start: int, end: int) -> bool:
    """Whether the phrase from ``start`` to ``end`` is said to be for the speaker: "me" just
    before it ("print me the fire drill plan") or "for me" just after ("print the plan for
    me")."""
    before = start >= 1 and tokens[start - 1].word in _SPEAKER_OBJECTS
    after = [t.word for t in tokens[end : end + 2]] in (["for", "me"], ["for", "us"])
    return before or after


def _plain(word: str) -> bool:
    """A word that may be part of a noun phrase: not an everyday filler nor a courtesy."""
    return word not in _COMMON and word not in _ASKING


def _may_be_noun(word: str) -> bool:
    """Whether a word may head a noun phrase: the dictionary has it as a noun or a verb (an
    unknown noun is often guessed a verb: "questionnaire"), or does not know it ("payslip");
    never a word it knows only as an adjective or adverb ("old", "quickly")."""
    found = language.lemmas(word)
    return not found or "NOUN" in found or "VERB" in found


def _worked_on(office: Office) -> tuple[tuple[str, frozenset[str]], ...]:
    """Each form of the office's operation verbs (one word), with the item types the
    operations it names take."""
    types: dict[str, set[str]] = {}
    for op in office.operations:
        if op.input is not None:
            for verb in op.verbs:
                _add_forms(types, verb, op.input)
    return tuple((form, frozenset(ts)) for form, ts in types.items())


def _person_worked_on(office: Office) -> tuple[tuple[str, frozenset[str]], ...]:
    """Each form of the verbs of a person's work on a paper done with a tool ("stamp",
    "seal": the task kinds that work on an item of a property with a tool), with the office's
    item of that property ("seal the cert for me": the office's seal is no thing to bring)."""
    types: dict[str, set[str]] = {}
    for kind_id in task_kinds.person_kinds():
        spec = task_kinds.kind(kind_id)
        paper = office.type_with(spec.works_on) if spec.works_on else None
        # only a work done with a tool of the office ("seal", "stamp"), whose verb may be
        # read as the tool's name; signing a paper nobody lists is asked about as before
        if paper is not None and spec.tool is not None:
            for verb in spec.words or english.kind_words(kind_id):
                if language.verb_lemmas(verb):
                    _add_forms(types, verb, paper)
    return tuple((form, frozenset(ts)) for form, ts in types.items())


def _add_forms(types: dict[str, set[str]], verb: str, item: str) -> None:
    words = language.fold(verb).split()
    if len(words) == 1:
        for form in language.verb_forms(words[0]) | {words[0]}:
            types.setdefault(form, set()).add(item)


def _item_name_words(office: Office) -> frozenset[str]:
    """The words of the office's item names and synonyms: a paper noun among them is the
    office's own word, read (or asked about) by the stages that know that name."""
    return frozenset(
        w for t in office.item_types for n in (t.name, *t.synonyms) for w in normalize(n).split()
    )


def _facility_name_words(office: Office) -> frozenset[str]:
    """The words of the office's facility names ("fridge", "laminator"): a paper's topic."""
    return frozenset(
        w for f in office.facilities for n in (f.name, *f.synonyms) for w in normalize(n).split()
    )


def _file_verb(tokens: Sequence[Token], k: int) -> bool:
    """Whether the sentence of token ``k`` says, before it, a verb whose input is a file."""
    start = k
    while start > 0 and not tokens[start].opens:
        start -= 1
    return any(t.word in _FILE_VERBS for t in tokens[start:k])


def _sentence(tokens: Sequence[Token], k: int) -> Sequence[Token]:
    start = k
    while start > 0 and not tokens[start].opens:
        start -= 1
    end = k + 1
    while end < len(tokens) and not tokens[end].opens:
        end += 1
    return tokens[start:end]


def unread_paper(mentions: Sequence[Mention], tokens: Sequence[Token]) -> str | None:
    """ "my memo" left a plain word (the office has several papers it may be, or none): the
    phrase as said, to ask about before anything moves; None when there is none."""
    office_words = {
        tokens[k].word for m in mentions if m.kind != "word" for k in range(m.start, m.end)
    }
    for n, opener in enumerate(mentions):
        k = paper_phrase(mentions, n, tokens, office_words.__contains__)
        if k is not None:
            return " ".join(t.text for t in tokens[opener.start : mentions[k].end])
    return None
