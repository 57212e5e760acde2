"""Stage 2 of the reader: tokens → the office's words (people, items, facilities, places).

Every name comes from the office file (names, aliases, synonyms, plurals, the names of its
locations), so another office works unchanged; the English function words and generic task
verbs are the package's data (``data/english.yaml``), and morphology, word frequency and typo
distance come from libraries (``assistantx.core.language``). Matching is longest-phrase-first,
then single name words, on diacritics-blind keys ("Jose Muller" is José Müller); a word that
names several people is kept as an ambiguous mention, never resolved by guessing.

Small typos ("stapeler", "pirnt", "cpoy") are corrected against the same vocabulary, within a
limit that grows with the word's length, but never a word that is itself ordinary English; a
misspelt name that is nearly as close to another person's name ("Zhnag": Zhang or Zheng) is
ambiguous, since fetching from the wrong colleague is worse than asking.

A person's name that is also an ordinary English word ("grace", "mark", "sun") is read by its
syntax (``name_reading``): "to Mark", "Mark's desk", "Pat hurt her hand" make a person; "the
grace period", "Mark my form", "Will you", "in May" make the word; when the two disagree the
mention carries both readings and the parser asks which was meant.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Collection, Sequence
from dataclasses import dataclass, field, replace
from typing import Literal

from assistantx.agents.symbolic.reading.asking_forms import asking_forms, done_forms, event_noun
from assistantx.agents.symbolic.reading.bare_possessives import (
    doubted_possessives,
    read_bare_possessives,
)
from assistantx.agents.symbolic.reading.called_by import called_alike, only_in_full_name
from assistantx.agents.symbolic.reading.clipped_given import clipped_owner, given_name_clips
from assistantx.agents.symbolic.reading.clipped_names import (
    clipped_item,
    clipped_names,
    place_heads,
    place_openers,
)
from assistantx.agents.symbolic.reading.clipped_phrases import clipped_phrases
from assistantx.agents.symbolic.reading.clipped_verbs import ClippedVerbs
from assistantx.agents.symbolic.reading.compound_heads import (
    modifies_a_noun,
    modifies_one,
    names_a_paper,
)
from assistantx.agents.symbolic.reading.container_names import container_phrase, doubted_container
from assistantx.agents.symbolic.reading.copy_of import read_held_copies
from assistantx.agents.symbolic.reading.courses import Courses
from assistantx.agents.symbolic.reading.described_owner import as_described_roles
from assistantx.agents.symbolic.reading.destination import means_words
from assistantx.agents.symbolic.reading.exact_spelling import exactly_spelled, plainly_called
from assistantx.agents.symbolic.reading.family_of_another import also_meant
from assistantx.agents.symbolic.reading.head_names import head_names
from assistantx.agents.symbolic.reading.head_synonyms import head_synonyms
from assistantx.agents.symbolic.reading.idioms import idiom_at
from assistantx.agents.symbolic.reading.made_objects import MadeObjects
from assistantx.agents.symbolic.reading.measured_items import singular_spans, singulars, unit_of
from assistantx.agents.symbolic.reading.named_work import NamedWork
from assistantx.agents.symbolic.reading.near_forms import NearForms
from assistantx.agents.symbolic.reading.number_labels import after_label, labels_an_item
from assistantx.agents.symbolic.reading.operation_nouns import (
    operation_names,
    operation_nouns,
    read_as_verbs,
)
from assistantx.agents.symbolic.reading.outsider_owner import office_people_words
from assistantx.agents.symbolic.reading.own_made import read_own_made
from assistantx.agents.symbolic.reading.own_papers import OwnPapers, personal_papers
from assistantx.agents.symbolic.reading.paper_head import names_another_paper
from assistantx.agents.symbolic.reading.paper_parts import part_of_paper
from assistantx.agents.symbolic.reading.paper_subject import paper_subjects
from assistantx.agents.symbolic.reading.participle_typos import participle_meant
from assistantx.agents.symbolic.reading.phrase_typos import PhraseTypos
from assistantx.agents.symbolic.reading.subject_adverbs import read_subject_adverbs
from assistantx.agents.symbolic.reading.surnames import after_title, family_names
from assistantx.agents.symbolic.reading.tokens import Token, tokenize
from assistantx.agents.symbolic.reading.unapostrophed import unapostrophed
from assistantx.agents.symbolic.reading.verb_named_places import (
    clipped_verb_places,
    in_a_place_slot,
    verb_named_places,
)
from assistantx.agents.symbolic.reading.verb_phrases import VerbPhrases
from assistantx.core import english, language, name_parts, task_kinds
from assistantx.core.name_reading import is_word_name, numeral, read_name, slot_at
from assistantx.core.office import Office
from assistantx.core.ranks import COURTESY_TITLES, rank_titles, shared_ranks
from assistantx.core.task_schema import SHAPE_KIND
from assistantx.memory.names import TITLES, normalize

MentionKind = Literal["person", "item", "facility", "place", "self", "pronoun", "cue", "word"]
Reading = Literal["person", "word", "ask"]

# Task cues: the English verbs (and nouns) that say what to do, keyed by task kind (the
# package's English data file). Not office-specific: the verbs of the office's own operations
# are added per office (``Lexicon.from_office``), under the task kind of their shape.
CUES: dict[str, frozenset[str]] = english.word_table("cues")
CUE_WORDS = frozenset(w for words in CUES.values() for w in words)

SELF_WORDS = english.words("self_words")
PRONOUNS = english.words("pronouns")
OTHER_POSSESSIVES = english.words("other_possessives")
# A clipped given name never stands after a determiner: "my Mum's ruler" is no Mumtaz's.
# "this week's vouchers", "today's rota": a time's possessive says when, not whose.
_TIME_POSSESSORS = english.words("time_possessors")
_CLIP_NEVER_AFTER = english.words("object_starts") | english.words("other_possessives")
# Words that connect a person to a role in the sentence.
PREPOSITIONS = english.words("party_prepositions")

# Ordinary English function words: never "corrected" into a name, and a name word that is one
# of them is read by its syntax like any other English word.
COMMON = english.words("common")

# Words that open a verb's object: the word before one of them is in a verb's place.
_VERB_OBJECT_STARTS = english.words("object_starts")

_POLITE = english.words("polite")
# Words that may follow a person's name but never an article ("Robin A please", "to Robin A
# and ..."): after them a one-letter word ending a name is an initial.
_AFTER_NAME = _POLITE | frozenset(
    {
        "she",
        "he",
        "they",
        "and",
        "or",
        "to",
        "for",
        "who",
        "if",
        "because",
        "so",
        "when",
        "now",
        "today",
        "asap",
        "is",
        "has",
        "needs",
        "wants",
        "said",
        "thanks",
        "too",
        "as",
    }
)
# the articles an alias may open with ("the Provost", "our Dean")
_ALIAS_ARTICLES = frozenset({"the", "our"})
# A determiner before a name word makes it the ordinary word ("the grace period").
_WORD_BEFORE = english.words("word_before")
_CHAT_SHORTHAND = english.wording("chat_shorthand")
_MODIFIER_DETERMINERS = english.words("modifier_determiners")
# What opens a phrase that says what a paper or a thing is about ("the file *on* the rota")
_TOPIC_PREPOSITIONS = english.words("topic_prepositions")
# ... of those, the ones that also say where a thing is put ("on charge")
_PLACING_PREPOSITIONS = english.words("placing_topic_prepositions")
_MODALS = english.words("request_modals")
# "have the Gaffer sign it", "let the manager stamp it": a verb that has someone do something
_DOER_VERBS_BARE = english.words("doer_verbs_bare")
# The copulas of a distance ("the lab is miles away")
_DISTANCE_COPULAS = frozenset({"is", "s", "are", "was", "were", "isnt", "arent", "feels"})
# "a brew", "a cuppa": everyday names of a thing by the plain name an office may give it
_EVERYDAY = english.phrase_table("everyday_names")
_CLIPS = english.phrase_table("clipped_words")
# What makes one of those names that is also a verb ("brew") a thing: an article before it
# The words before a thing's name that say whose or which one it is ("my ms", "the ms").
_OWNING_WORDS = frozenset({"my", "your", "his", "her", "our", "their", "the", "this", "that"})
# the possessive determiners ("*my* notes"); a name's "'s" is the token's own mark
_OWNED_BY = frozenset({"my", "your", "his", "her", "our", "their", "its"})
_TEXTS_KEPT = 512  # Lexicon.tokens: texts whose tokens are kept

_THING_ARTICLES = frozenset({"a", "an", "another", "the", "some", "quick", "nice", "proper"})


@dataclass(frozen=True)
class Mention:
    """A run of tokens that names something of the office (or a task word, a pronoun, "me")."""

    kind: MentionKind
    start: int  # token index
    end: int  # exclusive
    ids: tuple[str, ...] = ()  # person/item-type/facility ids (several = ambiguous)
    possessive: bool = False
    text: str = ""
    # a person's name that may also be meant as the ordinary word: the words it would then
    # be read as ("the grace period talk"); the parser asks which was meant
    alternative: str = ""
    # an item read from the work asked, not from its noun ("shred my questionnaire": the
    # document shredding takes): restated to the requester before anything is done
    guessed: bool = False
    # a service's word read as a word of a thing's noun phrase or topic ("the *print* queue
    # file", "Gwen's file on the *shred* bins"): it names no work left undone
    in_name: bool = False

    @property
    def id(self) -> str:
        return self.ids[0]


# The words before a participle that describes the item after it ("*my* signed letter").
_PARTICIPLE_OPENERS = english.words("determiners") - {"me"}


def described_by_participles(
    tokens: Sequence[Token], mentions: list[Mention], files: frozenset[str] = frozenset()
) -> list[Mention]:
    """ "courier my *signed* letter to the court", "bring me the *stamped* invoice", "forward
    the *printed* agenda": a task word in its past participle between a determiner (or a
    possessive) and the noun after it says the state the item is already in, a plain word;
    the request is the clause's own verb said before it. Without such a verb ("my printed
    agenda please") and after the item ("get my contract signed") it is read as before; so is
    an office service's participle before a file (``files``): "bring me the printed log" asks
    for the print, a file being no thing to carry."""
    out = list(mentions)
    for n, m in enumerate(out):
        if m.kind != "cue" or m.end - m.start != 1 or m.start == 0 or n + 1 >= len(out):
            continue
        before, after = tokens[m.start - 1], out[n + 1]
        by_person = set(m.ids) <= set(task_kinds.person_kinds())
        if not by_person and after.kind == "item" and set(after.ids) & files:
            continue
        if before.word not in _PARTICIPLE_OPENERS and not before.possessive:
            continue
        if after.start != m.end or tokens[after.start].opens or tokens[after.start].after_pause:
            continue
        if after.kind == "word" and after.ids[0] in COMMON:
            continue  # "this scanned *and* signed": a function word, no noun described
        if after.kind == "word" and not language.is_noun(after.ids[0]):
            if language.lemmas(after.ids[0]):  # a word the dictionary knows, but not as a noun
                continue
        elif after.kind not in ("item", "word"):
            continue
        if not _participle(tokens[m.start].word):
            continue
        if not (_asked_before(tokens, out[:n]) or _asked_after(tokens, out[n + 1 :])):
            continue
        out[n] = Mention("word", m.start, m.end, (tokens[m.start].word,), False, m.text)
    return out


def describing_participles(tokens: Sequence[Token], mentions: Sequence[Mention]) -> set[int]:
    """The tokens of past participles read as plain words before the item they describe
    ("courier my *printed* contract"): no later stage takes them for the service asked for."""
    out: set[int] = set()
    for n, m in enumerate(mentions[:-1]):
        if m.kind != "word" or m.end - m.start != 1 or m.start == 0:
            continue
        before, after = tokens[m.start - 1], mentions[n + 1]
        if before.word not in _PARTICIPLE_OPENERS and not before.possessive:
            continue
        if after.kind == "item" and after.start == m.end and not tokens[after.start].after_pause:
            if _participle(tokens[m.start].word):
                out.add(m.start)
    return out


def _participle(word: str) -> bool:
    """A past participle the dictionary knows ("signed", "bound"), or the "-ed" form of a word
    it does not know, an office's own verb ("couriered", "autoclaved")."""
    return language.is_past_participle(word) or (word.endswith("ed") and not language.lemmas(word))


def _asked_before(tokens: Sequence[Token], mentions: Sequence[Mention]) -> bool:
    """Whether a task word stands before, in the same sentence: the clause's own verb."""
    for m in reversed(mentions):
        if m.kind == "cue":
            return True
        if any(t.opens for t in tokens[m.start : m.end]):
            return False
    return False


# "my signed contract *needs couriering*", "the printed agenda *has to be posted*": the
# most words between the described thing and the task word of its own clause
_OWN_VERB_REACH = 3


def _asked_after(tokens: Sequence[Token], mentions: Sequence[Mention]) -> bool:
    """Whether the described thing is the subject of a task word said right after it, in the
    same clause ("my signed contract needs couriering to Leeds", "the stamped invoice has to
    be posted"): that word is what is asked, and the participle before the thing its state.
    Past a comma or a new sentence ("my printed agenda, and bring me a pen") it is not."""
    if not mentions:
        return False
    thing = mentions[0]
    for m in mentions[1:]:
        if m.start - thing.end > _OWN_VERB_REACH:
            return False
        if any(t.opens or t.after_pause for t in tokens[thing.end : m.end]):
            return False
        if m.kind == "cue":
            return True
    return False


@dataclass(frozen=True)
class Lexed:
    """What the lexicon stage hands on: the text, its corrected tokens and its mentions."""

    text: str
    tokens: tuple[Token, ...]
    mentions: tuple[Mention, ...]


# who a helping verb that opens an ask is put to ("can *you* ...", "could *someone* ...")
_ASKED_SUBJECTS = english.words("subject_pronouns") | english.words("unnamed_doers")


@dataclass
class Lexicon:
    """Phrase tables built from one office."""

    office: Office
    people: dict[str, set[str]] = field(default_factory=dict)  # phrase → person ids (tier 0)
    name_words: dict[str, set[str]] = field(default_factory=dict)  # word → ids (tier 1)
    # every word of the office's names for its people, "manager" of "Manager Mao" too
    people_words: frozenset[str] = frozenset()
    items: dict[str, str] = field(default_factory=dict)  # phrase → item type id
    facilities: dict[str, str] = field(default_factory=dict)  # phrase → facility id
    places: dict[str, str] = field(default_factory=dict)  # phrase → location id
    # one-word place names that are also a service's verb ("dispatch"): places only in a
    # place's slot ("in dispatch"), the verb elsewhere (``verb_named_places``)
    verb_places: dict[str, str] = field(default_factory=dict)
    clipped_verb_places: dict[str, str] = field(default_factory=dict)
    # the opening words of place names that name a kind of room ("cafe" of "Cafe counter"),
    # whether one place's or several's (``place_openers``)
    room_openers: frozenset[str] = frozenset()
    max_words: int = 1
    cues: dict[str, frozenset[str]] = field(default_factory=dict)  # task kind → words
    cue_words: frozenset[str] = frozenset()
    operation_words: frozenset[str] = frozenset()  # every form of the office's own verbs
    # everyday names of the office's things ("brew" for its tea) that are also generic verbs
    everyday_verbs: frozenset[str] = frozenset()
    vocabulary: list[str] = field(default_factory=list)
    _vocabulary_set: frozenset[str] = frozenset()
    # "the manager": a title that stands in someone's alias ("Manager Mao") names them
    roles: dict[str, set[str]] = field(default_factory=dict)
    # how the office file says a one-word name is used: "Kim" as a bare alias of one person,
    # "Dr. Kim" of another (word → the people it is declared for, bare or after a title)
    bare: dict[str, set[str]] = field(default_factory=dict)
    titled: dict[str, set[str]] = field(default_factory=dict)
    # family name → whose it is ("Mr Yang": Yang Lei, not Liu Yang; ``surnames``)
    family: dict[str, set[str]] = field(default_factory=dict)
    # a one-word title declared with its article ("the Provost"): (article, word) pairs, so
    # "the provost" written so is the person, never the ordinary word
    with_article: set[tuple[str, str]] = field(default_factory=set)
    # one-word aliases that are no word of anyone's full name ("Major", "Gaffer")
    alias_words: set[str] = field(default_factory=set)
    # the reading the requester chose for a name word they were asked about (word → reading)
    chosen: dict[str, Reading] = field(default_factory=dict)
    # one-word names said like another person's name and spelled nearly so ("li": "lee")
    sound_alike: dict[str, frozenset[str]] = field(default_factory=dict)
    # nouns that name one operation ("lamination", "legal review") → its verb
    operation_nouns: dict[str, str] = field(default_factory=dict)
    # the office's verb phrases of several words ("3d print"), each read as one token
    verb_phrases: VerbPhrases = field(default_factory=lambda: VerbPhrases({}, frozenset(), 0))
    # operations named by a verb and its object ("apply corrections"), read as that phrase
    named_work: NamedWork = field(default_factory=lambda: NamedWork(()))
    # the office's names of things and places written with a possessive inside ("reporter's
    # notebook", "St John's room"), by key: the possessive there is part of the name
    inner_possessives: frozenset[str] = frozenset()
    # operations' whole display names of two words or more ("legal read") → its verb
    operation_names: dict[tuple[str, ...], str] = field(default_factory=dict)
    # near forms of the office's verbs ("fire-proof", "flameproofed", "dying" for "dye")
    near_forms: NearForms = field(default_factory=lambda: NearForms({}, 0))
    courses: Courses = field(default_factory=lambda: Courses({}))
    made_objects: MadeObjects = field(default_factory=lambda: MadeObjects({}))
    clipped_verbs: ClippedVerbs = field(default_factory=lambda: ClippedVerbs({}, {}))
    # the office's one personal paper said in an everyday noun ("my report", ``own_papers``)
    own_papers: OwnPapers | None = None
    # the singular of each plural name of a thing ("post it" of "post its"), read as that
    # thing where a counted noun stands (``measured_items``)
    singulars: dict[str, str] = field(default_factory=dict)
    # the nouns that head several names of two item types or more ("roller" of a paint
    # roller and a lint roller) → those types: asked which, never read as one (``head_names``)
    shared_heads: dict[str, tuple[str, ...]] = field(default_factory=dict)
    # the head nouns read as one type ("gel"), no name the office gave it: not a thing said
    # as someone's where no one owns one ("my notes" beside a cupboard's sticky notes)
    head_forms: frozenset[str] = frozenset()
    # the tokens of the texts last read: one message is tokenized four or five times over
    # (the parser's frame, its pieces, the request screen, the drinks screen) and stage 1
    # reads only the tables above, which are fixed once the lexicon is built
    _tokens_of: dict[str, tuple[Token, ...]] = field(
        default_factory=dict, init=False, repr=False, compare=False
    )
    # the readings of the texts last read: the parser's early rewrites (a description said
    # later, a hyphened description, a file's subject, an emailed paper, a recipient in
    # doubt) each look at the same message before any of them changes it
    _read_of: dict[str, Lexed] = field(default_factory=dict, init=False, repr=False, compare=False)

    @classmethod
    def from_office(cls, office: Office) -> Lexicon:
        lex = cls(office)
        cues = {k: set(v) for k, v in CUES.items()}
        for spec in task_kinds.kinds():
            # a kind added to the live table is asked for by its own words ("endorse",
            # "endorsement"), every form of them; the built-in ones keep english.yaml's
            if spec.words and spec.id not in CUES:
                forms = {form for w in spec.words for form in inflections(key_of(w))}
                cues.setdefault(spec.id, set()).update(forms)
        ops: set[str] = set()
        for op in office.operations:
            # "ran" of "run" tells, never asks: not a cue of the operation
            # a send-out service's means asks for it too ("send by courier": "courier it",
            # "have it couriered")
            means = means_words(op.name) if op.sends_out else ()
            forms = {form for verb in (*op.verbs, *means) for form in asking_forms(key_of(verb))}
            forms |= done_forms(op, office)  # "restrung": the office's own word for what it did
            ops |= forms
            kind = SHAPE_KIND.get(op.shape(office))
            if kind is not None:
                cues.setdefault(kind, set()).update(forms)
        lex.verb_phrases = VerbPhrases.from_office(office)
        lex.named_work = NamedWork.from_office(office)
        lex.people_words = office_people_words(office)
        lex.near_forms = NearForms.from_office(office, inflections)
        lex.courses = Courses.from_office(office)
        lex.made_objects = MadeObjects.from_office(office)
        lex.clipped_verbs = ClippedVerbs.from_office(office, lex.verb_phrases.forms)
        lex.own_papers = OwnPapers.from_office(office)
        for form, op_id in lex.verb_phrases.forms.items():
            # a joined phrase ("3d print") is one token: its whole form is the cue
            ops.add(form)
            kind = SHAPE_KIND.get(office.operation(op_id).shape(office))
            if kind is not None:
                cues.setdefault(kind, set()).add(form)
        lex.cues = {k: frozenset(v) for k, v in cues.items()}
        lex.cue_words = frozenset(w for v in cues.values() for w in v)
        lex.operation_words = frozenset(w for form in ops for w in form.split()[:1]) | frozenset(
            lex.verb_phrases.forms
        )
        for p in office.people:
            for name in (p.id, p.name, *p.aliases):
                key = key_of(name)
                if key:
                    lex.people.setdefault(key, set()).add(p.id)
            # "Nguyễn Thị Mai": no middle word names her alone (``core.name_parts``), but
            # her surname with its particles does ("de la Cruz", "van Dijk")
            for phrase in name_parts.surname_phrases(p):
                # a phrase of one word once its function words are dropped ("Văn An":
                # "van") would make that word a name after all
                if " " in (key := key_of(phrase)):
                    lex.people.setdefault(key, set()).add(p.id)
            for word in name_parts.calling_words(p):
                # "An" (Trần Văn An): a name that is also an article or a title is still a
                # name, kept as its own word, never as the empty key of nothing said
                key = key_of(word) or _name_word(word)
                if not key:
                    continue
                # "Anne-Marie" is two words to the tokenizer: the given name alone is
                # the phrase of both ("Anne-Marie's calculator")
                found = lex.people if " " in key else lex.name_words
                found.setdefault(key, set()).add(p.id)
            # "Dan" of an alias "Dan Okonkwo" for Daniel Okonkwo (the given name shortened,
            # and the surname): it calls them as the full name's first word does, and where
            # two people are so called, which is asked; a role before the surname ("Chef
            # Ortiz") shortens no given name, and stays the alias it is
            own = [key_of(w) for w in p.name.split()]
            for alias in p.aliases:
                said = language.fold(alias).replace(".", " ").split()
                if len(said) != 2 or key_of(said[1]) not in own or said[0] in TITLES:
                    continue
                key = key_of(said[0])
                if key and key not in own and own[0].startswith(key[:2]):
                    lex.name_words.setdefault(key, set()).add(p.id)
            # "Owen A": the given name and the initial of the surname, as a sign-off or chat
            # tells two colleagues of one given name apart (an initial after the name is read
            # as one only where no thing follows it: "give Owen a flashgun")
            parts = key_of(p.name).split()
            if len(parts) > 1:
                initialled = " ".join((*parts[:-1], parts[-1][0]))
                lex.people.setdefault(initialled, set()).add(p.id)
            for alias in p.aliases:
                said = language.fold(alias).replace(".", " ").split()
                for word in said:
                    if word in TITLES and word not in COURTESY_TITLES:
                        lex.roles.setdefault(word, set()).add(p.id)
                lex._declare(p.id, said)
            lex._declare(p.id, language.fold(p.name).replace(".", " ").split())
        lex.family = family_names(office, key_of)
        lex.alias_words = {
            key_of(alias)
            for p in office.people
            for alias in p.aliases
            if len(alias.split()) == 1 and key_of(alias) not in lex.name_words and key_of(alias)
        }
        for phrase, holders in rank_titles(office).items():
            if phrase not in lex.people:  # "the Station Officer": the one who holds the rank
                lex.people[phrase] = set(holders)
            if " " not in phrase:  # "the Director" (of "Director Watanabe"): as a nickname
                lex.alias_words.add(phrase)
                # "give it to the curator" (of "Curator Moreau"): a rank is a role, said in
                # lower case too, as "the manager" of "Manager Mao" is
                lex.roles.setdefault(phrase, set()).update(holders)
        for phrase, holders in shared_ranks(office).items():
            if " " not in phrase and phrase not in lex.people and phrase not in lex.name_words:
                # "drop it off with the driver" (of "Driver Lund" and "Driver Park"): one of
                # them, asked which, never somebody outside the office
                lex.roles.setdefault(phrase, set()).update(holders)
        # a name as the office writes it first, then the forms made from names: "scales" named
        # for the weighing scales is never the plural of another thing's "scale"
        derived: list[tuple[str, str]] = []
        for t in office.item_types:
            for name in (t.id.replace("_", " "), t.name, *t.synonyms):
                key = key_of(name) or _title_word(name)  # "ms" for a manuscript
                if not key:
                    continue
                # "walkietalkie", "headtorch": a name of several words written as one
                joined = key.replace(" ", "") if " " in key else ""
                # "bills of lading": a name "N of M" is made plural on its head, N
                head_plural = language.head_plural(key)
                # "carpenters rule": a possessive word of the name written without its
                # apostrophe, as people type it ("carpenter's rule")
                bare = key_of(unapostrophed(name))
                lex.items.setdefault(key, t.id)
                for variant in (
                    _plural(key),
                    head_plural,
                    joined,
                    _plural(joined) if joined else "",
                    bare if bare != key else "",
                ):
                    if variant:
                        derived.append((variant, t.id))
        for variant, type_id in derived:
            lex.items.setdefault(variant, type_id)
        lex.everyday_verbs = lex._everyday_names(office, ops)
        for f in office.facilities:
            for name in (f.name, *f.synonyms, f.id.replace("_", " ")):
                key = key_of(name)
                if key:
                    lex.facilities.setdefault(key, f.id)
        # "on the charger" of a "radio charger": its head word, the agent noun of its work
        for word, facility_id in _agent_names(office).items():
            if not lex._known(word) and not any(word in k.split() for k in lex.items):
                for variant in (word, _plural(word)):
                    lex.facilities.setdefault(variant, facility_id)
        for loc in office.locations:  # "the mail room", "the post desk": places, not verbs
            for name in (loc.name, loc.id.replace("_", " ")):
                key = key_of(name)
                if key and (len(key.split()) > 1 or key not in lex.cue_words):
                    lex.places.setdefault(key, loc.id)
        lex.verb_places = verb_named_places(
            ((key_of(loc.name), loc.id) for loc in office.locations), lex.cue_words
        )
        lex.clipped_verb_places = clipped_verb_places(
            ((key_of(loc.name), loc.id) for loc in office.locations), lex.cue_words
        )
        # "down to repro": a place's one-word name clipped as people say it
        taken = {*lex.people, *lex.name_words, *lex.items, *lex.facilities, *lex.places}
        clipped = clipped_names(
            ((key_of(loc.name), loc.id) for loc in office.locations), taken | lex.cue_words
        )
        for clip, loc_id in clipped.items():
            lex.places.setdefault(clip, loc_id)
        # "down to the studio": a place named by the last word of its name, when only it ends so
        heads = place_heads(
            ((key_of(loc.name), loc.id) for loc in office.locations), taken | lex.cue_words
        )
        for head, loc_id in heads.items():
            lex.places.setdefault(head, loc_id)
        # "from the cafe": a place named by the kind of room its name opens with, when only
        # one place's name opens so (several: ``room_openers``, the office's all the same)
        openers = place_openers((key_of(loc.name), loc.id) for loc in office.locations)
        lex.room_openers = frozenset(openers)
        for opener, ids in openers.items():
            if len(ids) == 1 and opener not in {*taken, *lex.cue_words}:
                lex.places.setdefault(opener, next(iter(ids)))
        named = [
            *(n for t in office.item_types for n in (t.name, *t.synonyms)),
            *(n for f in office.facilities for n in (f.name, *f.synonyms)),
            *(loc.name for loc in office.locations),
            *(a for p in office.people for a in p.aliases),  # "the Judge's Clerk"
        ]
        lex.inner_possessives = frozenset(
            variant
            for n in named
            if _INNER_POSSESSIVE.search(language.fold(n))
            for variant in (key_of(n), _plural(key_of(n)))
        )
        one_word = {k for k in (*lex.people, *lex.name_words) if " " not in k}
        lex.sound_alike = language.sound_alike_spellings(one_word)
        phrases = [*lex.people, *lex.items, *lex.facilities, *lex.places]
        lex.max_words = max(len(p.split()) for p in phrases)
        words = {w for p in phrases for w in p.split()} | set(lex.name_words) | lex.cue_words
        lex.vocabulary = sorted(w for w in words if language.typo_limit(w) > 0)
        lex._vocabulary_set = frozenset(lex.vocabulary)
        # "a temp pass": a name of several words with its first word clipped (after the
        # typo vocabulary, so no clipped word is ever a typo's correction)
        compounds = [(k, i) for k, i in lex.items.items() if " " in k]
        used = {*lex.items, *lex.people, *lex.facilities}
        for form, type_id in clipped_phrases(compounds, used).items():
            lex.items.setdefault(form, type_id)
        # "a charging lead": another word for the head noun of a name ("charging cable")
        type_keys = [(key_of(n), t.id) for t in office.item_types for n in (t.name, *t.synonyms)]
        for form, type_id in head_synonyms(type_keys, used | lex.items.keys()).items():
            lex.items.setdefault(form, type_id)
        # "any gel going?": the noun that heads several names of one type ("hand gel",
        # "alcohol gel") is that type (``head_names``)
        type_names = [(key_of(n), t.id) for t in office.item_types for n in (t.name, *t.synonyms)]
        others = [key_of(n) for f in office.facilities for n in (f.name, *f.synonyms)]
        others += [key_of(loc.name) for loc in office.locations]
        heads, lex.shared_heads = head_names(type_names, others, lex._known)
        for form, type_id in heads.items():
            lex.items.setdefault(form, type_id)
        lex.head_forms = frozenset(f for f, t in heads.items() if lex.items[f] == t)
        # "a pic", "the spec": an English clip of a word of a thing's name
        places = {w for k in (*lex.facilities, *lex.places) for w in k.split()}
        taken = {*lex.items, *lex.people, *lex.name_words, *lex.cue_words, *places}
        for form, type_id in _clipped_words(lex.items, taken).items():
            lex.items.setdefault(form, type_id)
        lex.operation_nouns = operation_nouns(office, lex._known)
        lex.operation_names = operation_names(office)
        lex.singulars = singulars(list(lex.items.items()), lex._known)
        return lex

    def _everyday_names(self, office: Office, verbs: set[str]) -> frozenset[str]:
        """Adds the everyday names of the office's things ("a cuppa", "a brew" for its tea)
        as names of them, after the office's own names; a name that is a verb of one of the
        office's operations (a "brew" coffee service) stays that verb. Returns the names
        added that are also generic verbs, read as the thing only after an article."""
        verb_names: set[str] = set()
        taken = {*self.items, *self.people, *self.name_words, *self.facilities}
        names = {t.id: {key_of(n) for n in (t.name, *t.synonyms)} for t in office.item_types}
        heads: dict[str, set[str]] = {}  # "cup of tea", "builder's tea": their "tea"
        for type_id, keys in names.items():
            for key in keys:
                heads.setdefault(key.split()[-1] if key else "", set()).add(type_id)
        for t in office.item_types:
            own = set(names[t.id])
            # its own name, or a head noun no other thing of the office has
            own |= {k.split()[-1] for k in own if k and heads.get(k.split()[-1]) == {t.id}}
            for name in sorted(own):
                for said in _EVERYDAY.get(name, ()):
                    key = key_of(said)
                    if not key or key in verbs or key in taken:
                        continue
                    for variant in (key, _plural(key)):
                        self.items.setdefault(variant, t.id)
                        if any(variant in words for words in CUES.values()):
                            verb_names.add(variant)
        return frozenset(verb_names)

    def _thing_named(self, tokens: Sequence[Token], i: int) -> bool:
        """ "make me a brew": an everyday name that is also a generic verb, after an article."""
        return tokens[i].word in self.everyday_verbs and (
            i > 0 and tokens[i - 1].word in _THING_ARTICLES
        )

    def _declare(self, person: str, words: list[str]) -> None:
        """Record how a name or alias of ``person`` is written: a bare word ("Kim"), a title
        and a word ("Dr. Kim"), or a role with its qualifier ("the lab manager")."""
        names = [w for w in words if w not in TITLES]
        roles = [w for w in words if w in TITLES and w not in COURTESY_TITLES]
        if len(words) == 2 and words[0] in _ALIAS_ARTICLES and names == words[1:]:
            self.with_article.add((words[0], key_of(words[1])))
        if len(names) == 1 and not roles and len(words) == len(names):
            self.bare.setdefault(key_of(names[0]), set()).add(person)
        elif len(names) == 1 and words[-1] == names[0]:
            self.titled.setdefault(key_of(names[0]), set()).add(person)
        if roles and names:  # "the lab manager": the whole role phrase names them
            phrase = " ".join(w for w in words if w not in COURTESY_TITLES or w in roles)
            self.people.setdefault(phrase, set()).add(person)

    def _word_people(self, tokens: Sequence[Token], i: int, word: str) -> set[str]:
        """Who a one-word name means: after a title, those the office calls so with a title
        ("Dr Kim"); else those it calls so bare ("Kim"); else everyone with that name word
        ("Yang": Yang Lei, and Liu Yang's given name), to be settled by the words around it
        or asked. A name word said the same as another person's name and spelled nearly so
        may mean either ("Li": Sun Li, or Lee Ming, called "Lee"); a bare alias is how the
        office says that person is called, and wins."""
        prev = tokens[i - 1].word if i > 0 else ""
        if prev in TITLES and prev not in ("a", "an", "the", "our") and word in self.titled:
            return self.titled[word]
        found = self.people.get(word, set()) | self.name_words.get(word, set())
        family = self.family.get(word, set()) & found
        if after_title(prev) and family and len(found) > 1:
            return family  # "Mr Yang": a title goes with a family name
        if word in self.bare:
            # "Morgan": Morgan Tallis's alias, and Priya Morgan's family name: either (asked)
            chosen = self.bare[word] | (also_meant(word, self.bare, self.family) & found)
            # "sean" where the alias is "Seán" and Sean Baker is called Sean: both (asked)
            candidates = [self.office.person(p) for p in found]
            return plainly_called(candidates, chosen, tokens[i].text) if len(found) > 1 else chosen
        alike = {
            p
            for other in self.sound_alike.get(word, ())
            for p in self.people.get(other, set()) | self.name_words.get(other, set())
        }
        return found | alike if found else found

    # -- stage 2: tokens → the office's words ----------------------------------------------
    def read(self, text: str) -> Lexed:
        """The lexicon's reading of a text: its tokens with typos corrected, and the mentions
        of this office's people, items, facilities and places in them."""
        kept = self._read_of.get(text)
        if kept is None:
            if len(self._read_of) >= _TEXTS_KEPT:
                self._read_of.clear()
            tokens = tuple(self.tokens(text))
            # "the Acme account manager's report": a described role, never Manager Mao
            mentions = as_described_roles(tokens, self.scan(tokens), self.people_words)
            kept = self._read_of[text] = Lexed(text, tokens, tuple(mentions))
        return kept

    def tokens(self, text: str) -> list[Token]:
        """The tokens of ``text`` (stage 1), each corrected against this office's words."""
        kept = self._tokens_of.get(text)
        if kept is None:
            if len(self._tokens_of) >= _TEXTS_KEPT:
                self._tokens_of.clear()
            kept = self._tokens_of[text] = tuple(self._read_tokens(text))
        return list(kept)

    def _read_tokens(self, text: str) -> list[Token]:
        # "bring idas ruler": a name's possessive without its apostrophe, before correction
        raw = read_bare_possessives(
            tokenize(text), self._one_word_names, self._item_openers, self._owned_openers
        )
        raw = read_held_copies(raw)  # "Kenji's copy of the contract": Kenji's contract
        # "the note I just saved": the speaker's own, as "my note"
        raw = read_own_made(
            raw, self._one_word_names.__contains__, self._physical_openers.__contains__
        )
        # "Rose really needs an umbrella": the adverb says how badly, not who needs it
        raw = read_subject_adverbs(raw, self._one_word_names.__contains__)
        out: list[Token] = []
        for n, t in enumerate(raw):
            # a word right before a determiner is a verb: "printe my file" is print, not printer
            verb_slot = n + 1 < len(raw) and raw[n + 1].text.lower() in _VERB_OBJECT_STARTS
            out.append(t.corrected_to(self._correct(t.word, verb_slot=verb_slot)))
        # "blu tac", "gaffa tap": one word of a thing's name of several words mistyped
        out = self._phrase_typos.read(out)
        # "flame-proofed", "dying": near forms of the office's own verbs are those verbs
        out = self.near_forms.join(out, self._known)
        # "14 days of meloxicam" with a making service's verb: that service's product
        out = self.courses.read(out, self._known)
        # "needs a lamination": an operation named by a noun is read as its verb
        out = read_as_verbs(out, self.operation_nouns, self._modifier_word, self.operation_names)
        # "apply this week's corrections to my charts": the operation named by verb and object
        out = self.named_work.read(out)
        # "3D print my file": a declared phrase is one verb, not the plotter's "print"
        out = self.verb_phrases.join(out, text)
        # "vac my prep": a compound verb said by its first word, clipped ("vac pack")
        return self.clipped_verbs.read(out, self._known)

    def doubted_possessives(self, text: str) -> list[tuple[str, str, str]]:
        """The (name word, item word, word as written) of each "<name>s ITEM" in ``text``
        where the name is also an English word and its colleague keeps no such item: Bill's,
        or anyone's?
        Read on the tokens before correction, as ``read_bare_possessives``."""
        return doubted_possessives(
            tokenize(text), self._one_word_names, self._item_openers, self._owned_openers
        )

    @functools.cached_property
    def _one_word_names(self) -> frozenset[str]:
        return frozenset(k for k in (*self.people, *self.name_words) if " " not in k)

    @functools.cached_property
    def _given_clips(self) -> dict[str, tuple[str, ...]]:
        taken = {*self.people, *self.name_words, *self.items, *self.facilities, *self.places}
        return given_name_clips(((p.name, p.id) for p in self.office.people), taken)

    @functools.cached_property
    def _phrase_typos(self) -> PhraseTypos:
        """The office's names of things of several words, for a slip in one of their words."""
        return PhraseTypos(self.items, self._known)

    @functools.cached_property
    def _item_words(self) -> frozenset[str]:
        """Every word of the office's names of things."""
        return frozenset(w for k in self.items for w in k.split())

    @functools.cached_property
    def item_heads(self) -> frozenset[str]:
        """The last words of the office's names of things ("marker" of "whiteboard marker")."""
        return frozenset(k.split()[-1] for k in self.items)

    @functools.cached_property
    def _item_openers(self) -> frozenset[str]:
        return frozenset(k.split()[0] for k in self.items)

    @functools.cached_property
    def _physical_openers(self) -> frozenset[str]:
        """The first words of the names of the office's things that are no file."""
        return frozenset(
            k.split()[0]
            for k, type_id in self.items.items()
            if self.office.item_type(type_id).kind != "electronic"
        )

    @functools.cached_property
    def _owned_openers(self) -> dict[str, frozenset[str]]:
        """Each one-word name of a person → the first words of the names of the items that
        every person it names owns ("hunter" → "pad" where Hunter keeps a pad)."""
        owned: dict[str, frozenset[str]] = {}
        for word in self._one_word_names:
            ids = {*self.people.get(word, ()), *self.name_words.get(word, ())}
            if not ids:
                continue
            kinds = [
                {o.type for o in self.office.person(i).owns} if self.office.is_person(i) else set()
                for i in ids
            ]
            common = set.intersection(*kinds)
            owned[word] = frozenset(k.split()[0] for k, t in self.items.items() if t in common)
        return owned

    def _modifier_word(self, word: str) -> bool:
        """A word that may describe an operation's noun ("a *quick* proofread", "a *legal*
        review"): an English word that is no function word and no word of the office."""
        return word.isalpha() and word not in COMMON and not self._known(word)

    def _correct(self, word: str, *, verb_slot: bool = False) -> str:
        """Fix a small typo in an office word or a cue; leave English and numbers alone.

        In a verb's place the task verbs are tried first, so a misspelt verb is never turned
        into a noun that is closer by letters (a typo keeps its part of speech). A typo as
        near to two words is left alone, unless both are names (the parser then asks whom)."""
        if word in _CHAT_SHORTHAND:  # "frm": from, as typed in chat
            return _CHAT_SHORTHAND[word]
        if (
            language.typo_limit(word) == 0
            or not word.isalpha()
            or word in COMMON
            or self._known(word)
            or word in self._item_words  # "walkie" of "walkie talkie": never "talkie"
            # a word of any name of the office ("Lopes" of Marta Ferreira-Lopes, a name the
            # tokenizer splits at its hyphen) is that name's word, never a typo of another's
            or word in self._vocabulary_set
            or language.zipf(word) >= language.COMMON_ZIPF
        ):
            return word
        if any(_agent_noun(word, cue) for cue in self.operation_words):
            return word  # "recharger": a device named after the service, not the service
        # "get my form signd by Wang": a service's participle with "-ed" clipped to "d"
        # (outside a verb's place, where "printd my file" stays the verb asked for)
        if not verb_slot and (past := participle_meant(word, self.cue_words)) is not None:
            return past
        # an English word or word form ("reprint", "rebacking") is never made a task verb
        is_word = language.is_word_form(word)
        if verb_slot and not is_word:
            verbs = language.closest(word, self.cue_words)
            if len(verbs) == 1 or (verbs and _one_verb(verbs)):  # "print" or "printed"
                return min(verbs, key=len)
        close = language.closest(word, self.vocabulary)
        if is_word:
            close = [c for c in close if c not in self.cue_words]
        if len(close) == 1 or (close and all(c in self.name_words for c in close)):
            return close[0]
        return clipped_item(word, self.items) or word  # "steth": a clipped item name

    def _known(self, word: str) -> bool:
        return (
            word in self.cue_words
            or word in self.name_words
            or word in self.people
            or word in self.items
            or word in self.facilities
            or word in self.places
            or word in TITLES
        )

    # -- mentions ------------------------------------------------------------------------
    def scan(self, tokens: Sequence[Token]) -> list[Mention]:
        """Mentions in text order; titles and articles are skipped inside phrases."""
        content = [
            i
            for i, t in enumerate(tokens)
            if t.word not in TITLES
            or self._role_at(tokens, i)
            or self._initial_at(tokens, i)
            or self._place_letter_at(tokens, i)
            or self._title_naming_a_thing(tokens, i)
            or self._function_word_name_at(tokens, i)
        ]
        mentions: list[Mention] = []
        k = 0
        while k < len(content):
            found = self._match_at(tokens, content, k)
            if found is None:
                i = content[k]
                mentions.append(self._single(tokens, i))
                k += 1
                continue
            mention, used = found
            mentions.append(mention)
            k += used
        mentions = self._unowned_heads(tokens, self._measured(tokens, mentions))
        mentions = self._paper_parts(tokens, mentions)  # "my CRF pages": the CRF
        files = frozenset(t.id for t in self.office.item_types if t.kind == "electronic")
        mentions = described_by_participles(tokens, self._compound_heads(tokens, mentions), files)
        mentions = self._paper_subjects(tokens, self._own_papers(tokens, mentions))
        mentions = self._modals_asking(tokens, mentions)
        return self._exactly_spelled(tokens, self._settled_by_owner(tokens, mentions))

    def _modals_asking(self, tokens: Sequence[Token], mentions: list[Mention]) -> list[Mention]:
        """ "can you rotavate plot 12", "Can I borrow Björn's can?": a thing's one-word name
        that is also a helping verb ("can", "will"), said before its subject (a pronoun or a
        colleague's name) opens a question or an ask, no thing (a watering can called "can"
        had been fetched for every "can you ...")."""
        out: list[Mention] = []
        for m in mentions:
            if (
                m.kind == "item"
                and m.end == m.start + 1
                and not tokens[m.start].possessive
                and "AUX" in language.lemmas(tokens[m.start].word)
                and m.end < len(tokens)
                and not tokens[m.end].opens
                and (
                    tokens[m.end].word in _ASKED_SUBJECTS
                    or tokens[m.end].word in self.name_words
                    or tokens[m.end].word in self.people
                )
                and (m.start == 0 or tokens[m.start].opens or tokens[m.start].after_pause)
            ):
                out.append(Mention("word", m.start, m.end, (_said(tokens, m),), False, m.text))
            else:
                out.append(m)
        return out

    def _paper_subjects(self, tokens: Sequence[Token], mentions: list[Mention]) -> list[Mention]:
        """ "sign my requisition for the new staplers": a thing after a worked paper's "for"
        is what the paper is about (``paper_subject``), a plain word, no thing to fetch."""
        found = paper_subjects(tokens, mentions, self._papers)
        return [
            Mention("word", m.start, m.end, (_said(tokens, m),), m.possessive, m.text)
            if n in found
            else m
            for n, m in enumerate(mentions)
        ]

    def _measured(self, tokens: Sequence[Token], mentions: list[Mention]) -> list[Mention]:
        """ "a post-it pad", "a box of staples": an item named by a unit of it, or by the
        singular of its plural name (``measured_items``)."""
        kinds = {k: m.kind for m in mentions for k in range(m.start, m.end)}
        items = {
            k: (m.start, m.end) for m in mentions if m.kind == "item" for k in range(m.start, m.end)
        }
        spans = singular_spans(tokens, kinds, self.singulars, self.max_words, items)
        for start, end, type_id in spans:
            text = " ".join(t.text for t in tokens[start:end])
            found = Mention("item", start, end, (type_id,), tokens[end - 1].possessive, text)
            mentions = _replaced(mentions, found)
        for m in list(mentions):
            after = [n for n in mentions if n.start == m.start + 2 and n.kind == "item"]
            if m.end == m.start + 1 and unit_of(tokens, m.start) and after:
                thing = after[0]  # "a box of staples": the staples, the box their measure
                text = " ".join(t.text for t in tokens[m.start : thing.end])
                merged = Mention("item", m.start, thing.end, thing.ids, thing.possessive, text)
                mentions = _replaced(mentions, merged)
        return mentions

    @functools.cached_property
    def _papers(self) -> frozenset[str]:
        """The office's papers and files, whose parts' nouns name them (``paper_parts``)."""
        return frozenset(
            t.id for t in self.office.item_types if t.signable or t.kind == "electronic"
        ) | frozenset(personal_papers(self.office))

    def _paper_parts(self, tokens: Sequence[Token], mentions: list[Mention]) -> list[Mention]:
        """ "my CRF pages", "Rose's contract sheets": a paper's name with a noun of its parts
        after it is the paper, the part noun no thing of its own (``paper_parts``)."""
        for m in list(mentions):
            if m.kind != "item" or len(m.ids) != 1:
                continue
            end = part_of_paper(tokens, m.start, m.end, m.ids[0], self._papers)
            # "my rota form": a part noun that names another of the office's papers heads
            # the phrase (``paper_head``), no part of the paper before it
            if end is not None and not names_another_paper(
                mentions, mentions.index(m), end, self._papers
            ):
                text = " ".join(t.text for t in tokens[m.start : end])
                found = Mention("item", m.start, end, m.ids, tokens[end - 1].possessive, text)
                mentions = _replaced(mentions, found)
        return mentions

    def is_paper_part(self, tokens: Sequence[Token], m: Mention) -> bool:
        """Whether mention ``m`` is a paper's name with a noun of its parts as its last word,
        as ``_paper_parts`` read it ("CRF pages"), not a name of the office that ends so."""
        return (
            len(m.ids) == 1
            and part_of_paper(tokens, m.start, m.end - 1, m.ids[0], self._papers) == m.end
            and " ".join(t.word for t in tokens[m.start : m.end]) not in self.items
            and " ".join(t.word for t in tokens[m.start : m.end - 1]) in self.items
        )

    def _unowned_heads(self, tokens: Sequence[Token], mentions: list[Mention]) -> list[Mention]:
        """ "my notes", "Tomas's gel": a head noun read as a type (``head_names``) said as
        someone's where no one in the office owns one is no guess to make: a plain word; so is
        one said as a unit after a number ("150 bar" where a hydrant bar is a thing)."""
        out: list[Mention] = []
        for m in mentions:
            said = " ".join(t.word for t in tokens[m.start : m.end])
            if m.kind == "item" and said in self.head_forms and m.start > 0:
                before = tokens[m.start - 1]
                owned = before.possessive or before.word in _OWNED_BY
                # "down to 150 bar": a head noun in the singular after a count above one is
                # a unit the count measures, never that many of the thing ("2 bars" is)
                measured = before.word.isdigit() and int(before.word) > 1 and not said.endswith("s")
                if (owned and not self.office.owners_of(m.ids[0])) or measured:
                    m = Mention("word", m.start, m.end, (said,), m.possessive, m.text)
                elif self._other_kind(before, m.ids[0]):
                    m = Mention("word", m.start, m.end, (said,), m.possessive, m.text)
            out.append(m)
        return out

    def _other_kind(self, before: Token, type_id: str) -> bool:
        """ "a microfiche reader" where the office has a card reader: a noun before a head
        read as a type (``head_names``) that none of the type's own names puts there says
        another kind of the thing, one the office does not have; an adjective ("the new
        reader") or a word of the office ("the sd reader") says which of its own."""
        word = before.word
        if not word.isalpha() or before.possessive or word in _OWNED_BY or word in COMMON:
            return False  # "2 bars": a count, no kind
        if self._known(word):
            return False
        t = self.office.item_type(type_id)
        own = {w for n in (t.name, t.id.replace("_", " "), *t.synonyms) for w in key_of(n).split()}
        if word in own or before.corrected:
            return False
        kinds = language.lemmas(word)
        if not kinds:  # "barcode": a word in use the dictionary lacks names a kind too
            return language.zipf(word) >= language.WORD_IN_USE_ZIPF
        return "NOUN" in kinds and "ADJ" not in kinds

    def _exactly_spelled(self, tokens: Sequence[Token], mentions: list[Mention]) -> list[Mention]:
        """ "Tomás" beside Tomáš Novák: a name written with its diacritics means the people
        who spell it so (``exact_spelling``)."""
        out: list[Mention] = []
        for m in mentions:
            if m.kind == "person" and m.ids:
                written = [t.text for t in tokens[m.start : m.end] if t.word not in TITLES]
                ids = exactly_spelled(self.office, written, m.ids)
                m = replace(m, ids=ids) if ids != m.ids else m
            out.append(m)
        return out

    def _function_word_name_at(self, tokens: Sequence[Token], i: int) -> bool:
        """ "take my stapler to An", "give An my tape": a colleague's one-word name that is
        also an article or a title ("An" of Trần Văn An), in a clear name slot: capitalised
        inside a sentence, or after "to", "for" or "from" with nothing after it that the
        article could open ("to an office" is the article)."""
        t = tokens[i]
        if t.word not in self.name_words:
            return False
        if t.text[:1].isupper() and not t.opens and i > 0:
            return True
        nxt = tokens[i + 1] if i + 1 < len(tokens) else None
        ends = nxt is None or nxt.opens or nxt.word in _SLOT_ENDS
        return i > 0 and tokens[i - 1].word in ("to", "for", "from") and ends

    def _own_papers(self, tokens: Sequence[Token], mentions: list[Mention]) -> list[Mention]:
        """ "take my report to Olive": the requester's paper in an everyday noun the office
        does not list is its one personal paper (``own_papers``)."""
        if self.own_papers is None:
            return mentions
        found = self.own_papers.found(tokens, mentions, self._known)
        guessed = self.own_papers.guessed(tokens, mentions, found)
        # "print the floor 2 plans for me": a noun after a label names the requester's papers
        # of that number, no guess to restate; the work asked says which item they are
        # "copy the book list": a paper named by its topic is the requester's, as labelled
        labelled = {
            n: t
            for n, t in guessed.items()
            if after_label(tokens, mentions[n].start) or self.own_papers.topic_paper(mentions, n)
        }
        found = {**found, **labelled}
        return [
            Mention("item", m.start, m.end, (found[n],), m.possessive, m.text)
            if n in found
            else Mention("item", m.start, m.end, (guessed[n],), m.possessive, m.text, guessed=True)
            if n in guessed
            else m
            for n, m in enumerate(mentions)
        ]

    def _compound_heads(self, tokens: Sequence[Token], mentions: list[Mention]) -> list[Mention]:
        """ "my wine list file": an item's name before a noun the office does not know is
        the first part of a compound (``compound_heads``), a plain word, not the item. So is
        a facility's name inside an item's noun phrase that it does no work on ("my
        *autoclave* log spreadsheet": a file, no sterilising; ``_facility_modifies``), or
        before a paper's noun that heads the phrase ("the van schedule": ``names_a_paper``)."""
        item_starts = {m.start for m in mentions if m.kind == "item"}
        return [
            Mention(
                "word",
                m.start,
                m.end,
                (" ".join(t.word for t in tokens[m.start : m.end]),),
                m.possessive,
                m.text,
            )
            if (
                m.kind == "item"
                and (
                    modifies_a_noun(tokens, m.end, self._head_known(tokens, m.start), m.start)
                    or labels_an_item(tokens, m.end, item_starts)
                    or modifies_one(tokens, m.start, m.end)  # "the coffee one"
                )
            )
            or (
                m.kind == "facility"
                and (
                    self._facility_modifies(tokens, mentions, n)
                    # "the laminator budget": a paper named by its topic, no laminating
                    or names_a_paper(tokens, m.end, self._known)
                    or modifies_one(tokens, m.start, m.end)  # "the printer one"
                )
            )
            else m
            for n, m in enumerate(mentions)
        ]

    def _head_known(self, tokens: Sequence[Token], start: int) -> Callable[[str], bool]:
        """The office's words that keep a noun after an item's name from heading a compound
        with it. After "my", "your", ... the item's phrase is a noun phrase ("my works
        order"), so a task's verb there ("order") can only be its head noun: no request's
        verb follows its object; names, items, people and places still block."""
        if start and tokens[start - 1].word in _OWNED_BY:
            return lambda word: word not in self.cue_words and self._known(word)
        return self._known

    def _inner_noun(self, t: Token) -> bool:
        """A word inside a noun phrase whose head comes later ("log", "cleaning", "rota" of
        "my kiln cleaning rota spreadsheet"): in lower case, no word of the office and no
        function word (the dictionary knows many such nouns as verbs only: "log")."""
        word = t.word
        if not t.text.isalpha() or not t.text[:1].islower() or t.corrected:
            return False
        return word not in COMMON and not self._known(word)

    def _facility_modifies(self, tokens: Sequence[Token], mentions: list[Mention], n: int) -> bool:
        """Whether facility mention ``n`` only says which of an item is meant: the item's
        name follows it in the same noun phrase, after nothing or after nouns the office does
        not know (``_inner_noun``: "my kiln log *spreadsheet*", "the microwave
        *spreadsheet*"), and the facility makes no such item and works on none: "a vending
        machine snack" is its product, "my microwave lunch" may be for heating, read as
        before."""
        m = mentions[n]
        head = next((h for h in mentions[n + 1 :] if h.kind != "word"), None)
        if m.possessive or head is None or len(m.ids) != 1:
            return False
        if head.kind != "item" or len(head.ids) != 1 or head.start - m.end > 2:
            return False
        for k in range(m.end, head.start + 1):
            if tokens[k].opens or tokens[k].after_pause or tokens[k - 1].possessive:
                return False
            if k < head.start and not self._inner_noun(tokens[k]):
                return False
        facility = self.office.facility(m.ids[0])
        item = head.ids[0]
        if item in facility.products:
            return False
        return not any(
            item in (self.office.operation(op).input, self.office.operation(op).product)
            for op in facility.operations
        )

    def _settled_by_owner(self, tokens: Sequence[Token], mentions: list[Mention]) -> list[Mention]:
        """ "Yang's book", "Yang said I could borrow his book": a name several people share
        means the one of them who owns the item it is said to own, when only one does (a typo
        stays in doubt: the name itself is uncertain). Only ownership the assistant knows
        counts: a thing the office lists as a colleague's but unknown to the assistant
        (``known: false``) is no ground to pick them, so the name is asked. It settles only
        who is called by the name against who merely has it in their full name ("Yang's
        book": Yang Lei, not Liu Yang); two who are both called so are asked about."""
        out = list(mentions)
        for n, m in enumerate(out):
            if m.kind != "person" or len(m.ids) < 2 or tokens[m.start].corrected:
                continue
            item = self._owned_item(out, n)
            if item is None:
                continue
            owners = set(self.office.owners_of(item, known_only=True))
            candidates = tuple(i for i in m.ids if i in owners)
            word = tokens[m.start].word
            spelled = self.people.get(word, set()) | self.name_words.get(word, set())
            if candidates and spelled and not set(candidates) & spelled:
                continue  # "Li's book" where only Lee owns one: the spelling says Sun Li; ask
            if len(candidates) == 1 and m.end - m.start == 1:
                others = [self.office.person(i) for i in m.ids if i != candidates[0]]
                if only_in_full_name(self.office.person(candidates[0]), others, word):
                    continue  # "cliff's running order", only Marcus Cliff keeps one: ask
                if called_alike(self.office.person(candidates[0]), others, word):
                    continue  # "Noor's controller", two called Noor: the other may keep one
            if len(candidates) == 1:
                out[n] = Mention("person", m.start, m.end, candidates, m.possessive, m.text)
        return out

    @staticmethod
    def _owned_item(mentions: Sequence[Mention], n: int) -> str | None:
        """The item type the person at ``n`` is said to own: "X's stapler", or "his stapler"
        later with nobody else named in between."""
        m = mentions[n]
        following = mentions[n + 1 :]
        if m.possessive:
            return following[0].id if following and following[0].kind == "item" else None
        for k, later in enumerate(following):
            if later.kind == "person":
                return None
            after = following[k + 1] if k + 1 < len(following) else None
            if later.kind == "pronoun" and later.possessive and after and after.kind == "item":
                return after.id
        return None

    def _initial_at(self, tokens: Sequence[Token], i: int) -> bool:
        """ "Robin A's clippers": a one-letter word after a name that, with it, is someone's
        name ("Robin A" beside "Robin C") is their initial, not an article."""
        if i == 0 or len(tokens[i].word) != 1:
            return False
        if f"{tokens[i - 1].word} {tokens[i].word}" not in self.people:
            return False
        # "give Robin a timer": an article before a thing; the initial ends the name
        nxt = tokens[i + 1] if i + 1 < len(tokens) else None
        ends = nxt is None or nxt.opens or nxt.after_pause or nxt.word in _AFTER_NAME
        return tokens[i].possessive or ends

    def _place_letter_at(self, tokens: Sequence[Token], i: int) -> bool:
        """ "in Studio A", "to Lab A": a one-letter word that, with the words before it, is
        the whole name of a place or facility of the office is the last word of that name,
        not the article "a" (which the titles' list would skip, leaving "Studio" and a
        message that seemed cut off after "a"); capitalised, or ending the clause ("to
        Studio A please"): "to the studio a bit later" keeps its article."""
        t = tokens[i]
        if i == 0 or len(t.word) != 1 or t.opens:
            return False
        nxt = tokens[i + 1] if i + 1 < len(tokens) else None
        ends = nxt is None or nxt.opens or nxt.after_pause or nxt.word in _AFTER_NAME
        if not (t.text.isupper() or ends):
            return False
        for k in range(1, self.max_words):
            if i - k < 0 or (tokens[i - k + 1].opens and k > 1):
                break
            phrase = " ".join(x.word for x in tokens[i - k : i + 1])
            if phrase in self.places or phrase in self.facilities:
                return True
        return False

    def _title_naming_a_thing(self, tokens: Sequence[Token], i: int) -> bool:
        """ "my ms": a title's word ("Ms") that is also a name of one of the office's things
        ("ms" for its manuscript), after a possessive or an article and with no name after
        it, is the thing; "Ms Pike" stays a title."""
        if tokens[i].word not in self.items or i == 0 or tokens[i].word in _THING_ARTICLES:
            return False
        before = tokens[i - 1]
        if not (before.possessive or before.word in _OWNING_WORDS):
            return False
        nxt = tokens[i + 1].word if i + 1 < len(tokens) else ""
        return nxt not in self.people and nxt not in self.name_words

    def _titled_initial(self, tokens: Sequence[Token], i: int, word: str) -> bool:
        """ "Mr K", "Dr N": a title and an initial the office declares as someone's alias,
        said as declared (the initial alone is nobody's name, so it has no key of its own)."""
        if len(word) != 1 or word not in self.titled or word in self.people or i == 0:
            return False
        prev = tokens[i - 1].word
        return prev in TITLES and prev not in _THING_ARTICLES and prev not in ("our",)

    def _role_at(self, tokens: Sequence[Token], i: int) -> bool:
        """ "by the manager": a role title with no name after it names the one it stands for."""
        if tokens[i].word not in self.roles:
            return False
        nxt = tokens[i + 1].word if i + 1 < len(tokens) else ""
        return nxt not in self.people and nxt not in self.name_words

    def _match_at(
        self, tokens: Sequence[Token], content: list[int], k: int
    ) -> tuple[Mention, int] | None:
        for n in range(min(self.max_words, len(content) - k), 0, -1):
            idx = content[k : k + n]
            phrase = " ".join(tokens[i].word for i in idx)
            # a possessive ends a phrase ("zhang's stapler" is two mentions), unless the
            # office's own name of a thing has it inside ("a reporter's notebook")
            if any(tokens[i].possessive for i in idx[:-1]) and phrase not in self.inner_possessives:
                continue
            start, end = idx[0], idx[-1] + 1
            poss = tokens[idx[-1]].possessive
            text = " ".join(tokens[i].text for i in idx)
            if phrase in self.people:
                reading = self.name_reading(tokens, idx[0]) if n == 1 else "person"
                chosen = n == 1 and tokens[start].word in self.chosen
                modifier = reading == "person" and not chosen and self._modifier(tokens, start, end)
                if modifier:  # "the Zhang Wei meeting": not a party
                    return Mention("word", start, end, (phrase,), poss, text), n
                if reading != "word":
                    named = self._word_people(tokens, start, phrase) if n == 1 else set()
                    ids = self._person_ids(tokens, idx, named or self.people[phrase])
                    alt = self.word_phrase(tokens, idx[0]) if reading == "ask" else ""
                    return Mention("person", start, end, ids, poss, text, alt), n
            if n == 1 and self._titled_initial(tokens, start, phrase):
                ids = tuple(sorted(self.titled[phrase]))
                return Mention("person", start, end, ids, poss, text), n
            in_verb_slot = n == 1 and phrase in self.cue_words and self._verb_slot(tokens, start)
            # a declared phrase joined into one token ("heat press" my file) is the verb: the
            # joining left it as the thing where a determiner stood before it
            in_verb_slot = in_verb_slot or (n == 1 and phrase in self.verb_phrases.forms)
            if phrase in self.facilities and not in_verb_slot:  # "fax my letter": the verb
                return Mention("facility", start, end, (self.facilities[phrase],), poss, text), n
            if phrase in self.places and not in_verb_slot:
                return Mention("place", start, end, (self.places[phrase],), poss, text), n
            verb_only = n == 1 and phrase in self.cue_words and not self._thing_named(tokens, start)
            if phrase in self.items and not verb_only:
                return Mention("item", start, end, (self.items[phrase],), poss, text), n
        return None

    @staticmethod
    def _verb_slot(tokens: Sequence[Token], i: int) -> bool:
        prev = tokens[i - 1].word if i > 0 else ""
        nxt = tokens[i + 1].word if i + 1 < len(tokens) else ""
        opens = tokens[i].opens or prev in _POLITE or prev in ("to", "and", "then", "pls")
        return opens and (nxt in _VERB_OBJECT_STARTS or nxt == "")

    def _modifier(self, tokens: Sequence[Token], start: int, end: int) -> bool:
        """A name between a determiner and a noun modifies the noun: "for the Zhang meeting",
        "my Sun Li notes"."""
        if start == 0 or end >= len(tokens) or tokens[end - 1].possessive:
            return False
        if start >= 2 and tokens[start - 2].word in _MODALS:
            return False  # "could the office manager sign ...": the subject, not a modifier
        nxt = tokens[end]
        if start >= 2 and tokens[start - 2].word in _DOER_VERBS_BARE and _bare_verb(nxt):
            return False  # "have the Gaffer sign my form": the one made to sign it
        return (
            tokens[start - 1].word in _MODIFIER_DETERMINERS
            and not nxt.opens
            and nxt.word not in COMMON
            and nxt.word not in self.name_words
            and nxt.word not in self.items
            and language.is_noun(nxt.word)
        )

    def _single(self, tokens: Sequence[Token], i: int) -> Mention:
        t = tokens[i]
        w = t.word
        if w in self.roles and self._role_at(tokens, i):
            return Mention("person", i, i + 1, tuple(sorted(self.roles[w])), t.possessive, t.text)
        if w in self.name_words:
            reading = self.name_reading(tokens, i)
            chosen = w in self.chosen  # the requester said whom they meant
            if reading == "person" and not chosen and self._modifier(tokens, i, i + 1):
                reading = "word"  # "for the Zhang review": not a party
            if reading != "word":
                ids = self._person_ids(tokens, [i], self._word_people(tokens, i, w))
                alt = self.word_phrase(tokens, i) if reading == "ask" else ""
                return Mention("person", i, i + 1, ids, t.possessive, t.text, alt)
        if w in SELF_WORDS:
            return Mention("self", i, i + 1, (), w in ("my", "mine"), t.text)
        if w in PRONOUNS or w in OTHER_POSSESSIVES:
            return Mention("pronoun", i, i + 1, (), w in OTHER_POSSESSIVES, t.text)
        if w in self.verb_places and in_a_place_slot(tokens, i):  # "Mateus in dispatch"
            return Mention("place", i, i + 1, (self.verb_places[w],), t.possessive, t.text)
        room = self.clipped_verb_places.get(w)  # "in dispatch" of the "Dispatch room"
        if room is not None and in_a_place_slot(tokens, i, by_too=False):
            return Mention("place", i, i + 1, (room,), t.possessive, t.text)
        if self._thing_named(tokens, i):  # "a brew": the office's tea
            return Mention("item", i, i + 1, (self.items[w],), t.possessive, t.text)
        made = self.made_objects.product_at(tokens, i, self._known)
        if made is not None:  # "print labels": the label run's product, not its verb
            return Mention("item", i, i + 1, (made,), t.possessive, t.text)
        if self._noun_use(tokens, i) or self._topic_of_thing(tokens, i):
            # "the print queue file", "my file on the shred bins": a word of a noun phrase
            return Mention("word", i, i + 1, (w,), t.possessive, t.text, in_name=True)
        if w in self.cue_words and (
            idiom_at(tokens, i)  # "take care of it": handle it
            or (event_noun(tokens, i, self.operation_words) and not self._work_asked(tokens, i))
        ):
            return Mention("word", i, i + 1, (w,), t.possessive, t.text)  # "the print run"
        if w in self.cue_words:
            kinds = tuple(k for k, words in self.cues.items() if w in words)
            return Mention("cue", i, i + 1, kinds, t.possessive, t.text)
        if w in self.items:  # a cue word that is also an item name ("print", "copy")
            return Mention("item", i, i + 1, (self.items[w],), t.possessive, t.text)
        clipped = clipped_owner(w, t.text, t.possessive, self._given_clips)
        after_determiner = i > 0 and tokens[i - 1].word in _CLIP_NEVER_AFTER  # "my Mum's"
        if clipped and not self._known(w) and not after_determiner:  # "Rhi's": Rhiannon's
            return Mention("person", i, i + 1, clipped, True, t.text)
        if t.possessive and w in _TIME_POSSESSORS:
            return Mention("word", i, i + 1, (w,), False, t.text)  # "this week's": when
        return Mention("word", i, i + 1, (w,), t.possessive, t.text)

    def _work_asked(self, tokens: Sequence[Token], i: int) -> bool:
        """ "to Ines for a signature", "for the countersignature": a person's work named as
        what the thing goes to them for, a request for that work (its doer is whom it goes
        to), not an event ("after the print run")."""
        work = {w for k in task_kinds.person_kinds() for w in self.cues.get(k, ())}
        return tokens[i].word in work and i >= 2 and tokens[i - 2].word == "for"

    def _noun_use(self, tokens: Sequence[Token], i: int) -> bool:
        """ "for the printing job", "my rebind queue", "Gwen's fitness test results": a
        service's verb between a determiner (or a possessive, with nouns the office does not
        know between: "fitness") and a noun the office does not know modifies that noun; it
        asks for no work ("get the printing done" still does: no noun follows)."""
        if tokens[i].word not in self.operation_words or i == 0 or tokens[i].opens:
            return False
        k = i - 1
        while (
            k > 0
            and i - k <= 2
            and (self._modifier_noun(tokens, k) or self._describing_word(tokens, k))
        ):
            # "Gwen's *fitness* test results", "for a *massive* print run": a noun or a
            # describing word of the same phrase before it
            k -= 1
        before = tokens[k]
        if before.word not in _MODIFIER_DETERMINERS and not before.possessive:
            return False
        if i + 1 >= len(tokens) or tokens[i + 1].opens or tokens[i].possessive:
            return False
        if tokens[i + 1].after_pause:
            return False  # "needs a proofread, deal with it": a comma ends the noun
        nxt = tokens[i + 1].word
        if nxt in COMMON or self._known(nxt):
            return False
        if (
            i + 2 < len(tokens)
            and tokens[i + 2].word in self.items
            and tokens[i + 1].text.isalpha()
        ):
            # "my test log file": the phrase goes on to a thing of the office, its head
            return not (tokens[i + 2].opens or tokens[i + 2].after_pause)
        if not language.is_noun(nxt):
            return False
        if not language.is_finite_verb(nxt):
            return True
        # "the test results", "my print notes": a plural noun that is also a verb's -s form
        # is the noun where the phrase ends after it or goes on with a thing; "my print
        # looks faded" is a subject and its verb
        if not language.is_plural_noun(nxt):
            return False
        if i + 2 >= len(tokens) or tokens[i + 2].opens or tokens[i + 2].after_pause:
            return True
        after = tokens[i + 2].word
        return after in COMMON or after in self.items or self._modifier_noun(tokens, i + 2)

    def _topic_of_thing(self, tokens: Sequence[Token], i: int) -> bool:
        """ "Gwen's file on the shred bins", "my doc about laminating", "the report on the
        print costs": a service's word inside a phrase of topic (english.yaml
        topic_prepositions) right after the name of a thing of the office says what the
        thing is about; it asks for no work ("put my file on the laminator" names a
        facility, no service word)."""
        if tokens[i].word not in self.operation_words or tokens[i].opens:
            return False
        k = i - 1
        while k > 0 and i - k <= 3 and not tokens[k + 1].after_pause:
            t = tokens[k]
            if t.word in _TOPIC_PREPOSITIONS:
                break
            if t.word not in _MODIFIER_DETERMINERS and not self._modifier_noun(tokens, k):
                return False
            k -= 1
        else:
            return False
        if k < 1 or tokens[k].word not in _TOPIC_PREPOSITIONS or tokens[k].after_pause:
            return False
        if k == i - 1 and tokens[k].word in _PLACING_PREPOSITIONS:
            return False  # "stick my jump pack on charge": where it goes, the work asked
        thing = tokens[k - 1]
        return not thing.opens and thing.word in self.item_heads

    def _describing_word(self, tokens: Sequence[Token], k: int) -> bool:
        """A plain adjective inside a noun phrase ("a massive print run"): in lower case, no
        word of the office, no function word and no service's word."""
        t = tokens[k]
        if t.opens or t.after_pause or t.possessive or not t.text.isalpha():
            return False
        if not t.text[:1].islower() or t.corrected or t.word in COMMON or self._known(t.word):
            return False
        if t.word in self.operation_words or t.word in self.cue_words:
            return False
        return "ADJ" in language.lemmas(t.word)

    def _modifier_noun(self, tokens: Sequence[Token], k: int) -> bool:
        """A plain noun inside a noun phrase: in lower case, no word of the office, no
        function word, no verb's finite form nor a describing word only."""
        t = tokens[k]
        if t.opens or t.after_pause or t.possessive or not t.text.isalpha():
            return False
        if not t.text[:1].islower() or t.corrected or t.word in COMMON or self._known(t.word):
            return False
        return language.is_noun(t.word) and not language.is_finite_verb(t.word)

    def _person_ids(
        self, tokens: Sequence[Token], idx: list[int], ids: set[str]
    ) -> tuple[str, ...]:
        """The people a name may mean; a corrected one-word name adds everyone nearly as
        close (one edit more than the typo limit)."""
        found = set(ids)
        if len(idx) == 1 and tokens[idx[0]].corrected:
            typed = tokens[idx[0]].typed
            if typed.endswith("s") and typed[:-1] == tokens[idx[0]].word:
                return tuple(sorted(found))  # "wangs": Wang's without its apostrophe, no typo
            keys = [k for k in (*self.people, *self.name_words) if " " not in k]
            for key in language.within(typed, keys, language.typo_limit(typed) + 1):
                found |= self.people.get(key, set()) | self.name_words.get(key, set())
        return tuple(sorted(found))

    def name_reading(self, tokens: Sequence[Token], i: int) -> Reading:
        """Whether a one-word name means the person, the ordinary English word, or either:
        ``core.name_reading.read_name`` (the consent guard reads names with it too), unless
        the word was a typo's correction (then only a name) or the requester already said
        which they meant."""
        t = tokens[i]
        counted = i > 0 and (tokens[i - 1].word in ("a", "an") or numeral(tokens[i - 1].word))
        if counted and not t.possessive and not t.opens:
            return "word"  # "for a min", "for 5 min": nobody is "a Min" (``read_name`` too)
        if t.corrected or not is_word_name(t.word):
            return "person"
        if t.word in self.chosen:
            return self.chosen[t.word]
        if self._distance(tokens, i):
            return "word"
        if self._alias_after_the(tokens, i):
            return "person"
        if i > 0 and after_title(tokens[i - 1].word) and t.word in self.family:
            # "could Ms Grant sign my form?": a title of address goes with a family name;
            # nobody puts "Ms" before the word "grant"
            return "person"
        slot = slot_at(
            tokens,
            i,
            items=self.items,
            name_words=self.name_words,
            with_article=self.with_article,
        )
        reading = read_name(slot)
        if reading == "person" and doubted_container(tokens, i):
            return "ask"  # "give my report to skip": Skip Larsen, or the skip?
        return reading

    def _alias_after_the(self, tokens: Sequence[Token], i: int) -> bool:
        """ "bring my form to the Major": a one-word nickname or rank the office declares
        (not a word of anyone's name), capitalised after "the", is the colleague; "the
        major" as a word names nothing of the office, so no choice is offered, unless the
        words after it name a thing the office has ("the Major printer")."""
        t = tokens[i]
        if t.word not in self.alias_words or t.opens or not t.text[:1].isupper():
            return False
        if i == 0 or tokens[i - 1].word != "the":
            return False
        nxt = tokens[i + 1].word if i + 1 < len(tokens) and not tokens[i + 1].opens else ""
        return not (nxt in self.items or nxt in self.facilities or nxt in self.places)

    def _distance(self, tokens: Sequence[Token], i: int) -> bool:
        """ "the prep room is Miles away from S4": a plural noun of measure between a
        thing's "is" and "away" says how far, whoever is called Miles; not "is Miles away?"
        (the copula opens a question about him) nor "Rory is Miles' deputy"."""
        if i < 2 or i + 1 >= len(tokens) or tokens[i + 1].word != "away" or tokens[i].possessive:
            return False
        copula, subject = tokens[i - 1], tokens[i - 2]
        if copula.word not in _DISTANCE_COPULAS or copula.opens or tokens[i + 1].opens:
            return False
        if subject.word in self.people or subject.word in self.name_words:
            return False  # "Penny is Miles away ...": not a place's distance
        singular = language.lemmas(tokens[i].word).get("NOUN", ())
        return any(s != tokens[i].word for s in singular)

    def word_phrase(self, tokens: Sequence[Token], i: int) -> str:
        """The words a name word would be part of if meant as the ordinary word: "the grace
        period talk" (a determiner before it, the nouns after it)."""
        if language.is_month(tokens[i].word):
            return f"the month of {tokens[i].text.capitalize()}"
        if doubted_container(tokens, i):
            return container_phrase(tokens, i)  # "to skip": the skip
        start = i - 1 if i > 0 and tokens[i - 1].word in _WORD_BEFORE else i
        end = i + 1
        while (
            end < len(tokens)
            and end - i <= 3
            and not tokens[end].opens
            and tokens[end].word not in COMMON
            and not tokens[end - 1].possessive
            and language.is_noun(tokens[end].word)
        ):
            end += 1
        said = [tokens[k].text for k in range(start, end)]
        said[i - start] = said[i - start].lower()
        return " ".join(said)


def _bare_verb(token: Token) -> bool:
    """Whether a word is a verb in its plain form, its own lemma ("sign", "stamp")."""
    return not token.opens and token.word in language.verb_lemmas(token.word)


def _agent_names(office: Office) -> dict[str, str]:
    """The words that name a facility by what it does ("the charger" of a charging rack
    whose synonym is "radio charger"): the head word of a name of several words of the
    facility that is the agent noun of a one-word verb of one of its operations; a word two
    facilities would share names neither. An agent noun the office never uses for the
    facility ("poster" of a facility that posts) keeps its everyday meaning."""
    found: dict[str, set[str]] = {}
    for f in office.facilities:
        verbs = {
            key_of(v)
            for op_id in f.operations
            for v in office.operation(op_id).request_phrases
            if " " not in v.strip()
        }
        for name in (f.name, *f.synonyms):
            words = key_of(name).split()
            if len(words) > 1 and any(_agent_noun(words[-1], v) for v in verbs):
                found.setdefault(words[-1], set()).add(f.id)
    return {w: next(iter(ids)) for w, ids in found.items() if len(ids) == 1}


def _agent_noun(word: str, verb: str) -> bool:
    """Whether ``word`` is a noun made from ``verb`` with -er/-or ("charger", "recharger",
    "shredder", "dispatchers"): the thing or person that does it."""
    stem = word.removesuffix("s")
    base = verb.removesuffix("e")
    return any(stem == f"{b}{suffix}" for b in (base, verb + verb[-1:]) for suffix in ("er", "or"))


def _one_verb(forms: list[str]) -> bool:
    """Whether words are all forms of one verb ("print", "printed")."""
    shared = set.intersection(*(set(language.verb_lemmas(f)) for f in forms))
    return bool(shared)


_INNER_APOSTROPHE = re.compile(r"(?<=[^\W_])'(?=[^\W_])")


# A possessive "'s" inside a name, before another word ("reporter's notebook").
_INNER_POSSESSIVE = re.compile(r"\w['’]s\s+\w")


def _clipped_words(items: dict[str, str], taken: Collection[str]) -> dict[str, str]:
    """ "pic" of "picture", "spec sheet" of "specification sheet": each name of a thing
    (a key of ``items``, name → item type id) with one of its words said as its English clip
    (english.yaml ``clipped_words``, a prefix of the word). Only where no word of another
    thing's name starts with the clip ("mic" with a microphone and a microscope names
    neither: asked about) and the clip is no name or word of the office (``taken``: "car" of
    a car park)."""
    starts: dict[str, set[str]] = {}
    for key, type_id in items.items():
        for word in key.split():
            starts.setdefault(word, set()).add(type_id)
    found: dict[str, str] = {}
    for key, type_id in items.items():
        words = key.split()
        for n, word in enumerate(words):
            for clip in _CLIPS.get(word, ()):
                if not word.startswith(clip) or clip == word or clip in taken:
                    continue
                owners = {i for w, ids in starts.items() if w.startswith(clip) for i in ids}
                if owners != {type_id}:
                    continue
                said = " ".join([*words[:n], clip, *words[n + 1 :]])
                for variant in (said, _plural(said)):
                    found.setdefault(variant, type_id)
    return found


def _replaced(mentions: list[Mention], found: Mention) -> list[Mention]:
    """``mentions`` with ``found`` in place of every mention inside its tokens."""
    kept = [m for m in mentions if m.end <= found.start or m.start >= found.end]
    return sorted([*kept, found], key=lambda m: m.start)


def key_of(name: str) -> str:
    """The lookup key of a name or phrase: folded, titles and punctuation dropped. An
    apostrophe inside a word is dropped as the tokenizer drops it ("O'Keeffe" is one word,
    ``okeeffe``, so "First O'Surname's ruler" finds the name), after a possessive "'s"."""
    folded = re.sub(r"'s\b", "", language.fold(name))
    return normalize(_INNER_APOSTROPHE.sub("", folded))


# What may follow a name that ends a clause ("to An please", "for An, thanks", "from An now").
_SLOT_ENDS = english.words("polite") | frozenset({"now", "today", "asap", "thanks", "too"})


def _name_word(word: str) -> str:
    """A one-word name that ``key_of`` drops as a title or an article ("An", "Don"): the
    folded word itself, as the tokenizer reads it."""
    return re.sub(r"[^\w]", "", language.fold(word))


def _title_word(name: str) -> str:
    """A thing's name that is one title's word ("ms" for a manuscript), which ``key_of``
    drops as a title: kept as the thing's name (read as one only where no name follows)."""
    folded = language.fold(name).strip(". ")
    return folded if folded in TITLES and folded not in _THING_ARTICLES else ""


def inflections(verb: str) -> set[str]:
    """Every form of a verb ('bind' → bind, binds, binding, bound), from ``lemminflect``."""
    if not verb:
        return set()
    return set(language.verb_forms(verb))


def _plural(phrase: str) -> str:
    return language.plural(phrase)


def _said(tokens: Sequence[Token], m: Mention) -> str:
    """The words of mention ``m`` as the tokens read them."""
    return " ".join(t.word for t in tokens[m.start : m.end])
