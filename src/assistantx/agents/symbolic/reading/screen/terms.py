"""The office's terms as the screen reads them: what one office's people, items, facilities,
operations and task words are called, and the questions every rule asks of a piece's words
("which people does it name?", "is this a request verb?", "what can I do here?")."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.asking_forms import asking_forms
from assistantx.agents.symbolic.reading.destination import means_words
from assistantx.agents.symbolic.reading.lexicon import Lexed, Lexicon
from assistantx.agents.symbolic.reading.name_inner_words import name_inner_words
from assistantx.agents.symbolic.reading.screen.english import DETERMINERS, english, split_words
from assistantx.agents.symbolic.reading.speech import SpeechActs
from assistantx.core import language
from assistantx.core.office import Office


class Terms:
    """One office's words, its lexicon and the speech acts read with it."""

    def __init__(self, office: Office, lex: Lexicon) -> None:
        self.office = office
        self.lex = lex
        self.en = english()
        self.acts = SpeechActs(lex)
        # the words of the office's things, people and services; a word that occurs only in
        # a facility's name ("shelf" of "the laundry shelf") is not one: alone it names no
        # place (the whole name is a mention of its own)
        self.thing_words = frozenset(
            w
            for phrase in (
                *lex.items,
                *lex.people,
                *lex.name_words,
                *(o.name for o in office.operations),
                *lex.cue_words,
            )
            for w in split_words(phrase)
        )
        self.office_words = self.thing_words | {
            w for phrase in lex.facilities for w in split_words(phrase)
        }
        # the words said only inside a longer name of a thing ("heat" of "heat pack", "pocket"
        # and "book" of "pocket book" where nothing is called just "book"): alone they name no
        # thing of the office, so one that heads an imperative is its verb
        self.name_inner_words = name_inner_words(office, lex)

        # every form of the verbs of the services that send an item out ("courier", "posted")
        self.send_out_verbs = frozenset(
            form
            for op in office.operations
            if op.sends_out
            for phrase in (*op.verbs, op.name, *means_words(op.name))
            if split_words(phrase)
            for form in language.verb_forms(split_words(phrase)[0])
        )
        # every form of the verbs of the office's own services that can ask for them
        # ("print", "plotted"; not "ran", which only tells: ``asking_forms``)
        self.service_verbs = frozenset(
            form
            for op in office.operations
            for phrase in (*op.verbs, op.name)
            for form in asking_forms(split_words(phrase)[0])
            if split_words(phrase)
        )

        # the plain verbs the services are asked with ("shred", "frank"); not the first word
        # of a service's name ("get water": "got one already" is a having)
        self.service_lemmas = frozenset(
            split_words(verb)[0]
            for op in office.operations
            for verb in op.verbs
            if split_words(verb)
        )
        # every word of the services' verbs and names, bare: "clean" of "dry clean", which
        # ``service_verbs`` keeps only the first word of
        self.service_verb_words = frozenset(
            w
            for op in office.operations
            for phrase in (*op.verbs, op.name)
            for w in split_words(phrase)
        )

    def request_verb(self, words: list[str], at: int) -> bool:
        w = words[at]
        return w in self.lex.cue_words or (
            w in self.en.service_verbs and (at + 1 >= len(words) or words[at + 1] in DETERMINERS)
        )

    def errand_gerund(self, word: str) -> bool:
        """An errand's verb as a gerund ("bringing", "fetching"), where a negation passed on
        by "bother" or "trouble yourself" lands."""
        return word.endswith("ing") and bool(language.verb_lemmas(word) & self.lex.cue_words)

    def names_an_item(self, text: str) -> bool:
        return any(m.kind == "item" for m in self.lex.scan(self.lex.tokens(text)))

    def named(self, lexed: Lexed, kind: str) -> list[str]:
        """The ids of the people, items or facilities a read text names, in order."""
        tokens, mentions = lexed.tokens, lexed.mentions
        found: list[str] = []
        for n, m in enumerate(mentions):
            word = tokens[m.start].word
            if m.kind == kind and len(m.ids) == 1:
                found.append(m.ids[0])
            elif kind == "item" and m.kind == "cue" and word in self.lex.items:
                if n and mentions[n - 1].possessive:  # "Mao's seal": the item, not the verb
                    found.append(self.lex.items[word])
        return list(dict.fromkeys(found))

    @property
    def self_words(self) -> frozenset[str]:
        return frozenset({"i", "me", "my", "we", "us", "our", "im", "id", "ive"})

    def unknown_thing(self, words: list[str]) -> str:
        """ "a tape measure" in "who has a tape measure": the words after an article that
        name no item of this office."""
        for n, w in enumerate(words):
            if w in ("a", "an", "any", "some"):
                rest: list[str] = []
                for x in words[n + 1 :]:
                    if x in DETERMINERS or x in self.en.modifier_prepositions or x in ("i", "me"):
                        break
                    if x == "to" and rest:
                        # "a pen to mark the boxes": the thing's name ends where its purpose
                        # (or whom it goes to) starts; "pen to mark" names nothing
                        break
                    rest.append(x)
                return " ".join(rest[:3])
        return ""

    def place(self, lexed: Lexed) -> str | None:
        """The location a fact names: a facility's, or a location by its name."""
        text = lexed.text
        for m in lexed.mentions:
            if m.kind == "facility":
                return self.office.facility(m.ids[0]).location
        lowered = " ".join(split_words(text))
        for loc in self.office.locations:
            if " ".join(split_words(loc.name)) in lowered:
                return loc.id
        return None

    def capabilities(self) -> str:
        """What this office lets the assistant do, in words, from the office file."""
        things = [t.name for t in self.office.item_types if t.kind == "belonging"]
        machines = [
            f.name
            for f in self.office.facilities
            if any(self.office.runnable(o) for o in f.operations)
        ]
        parts = []
        if things:
            parts.append(f"fetch and deliver things like {listed(things[:5])}")
        parts.append("pass on files")
        if machines:
            parts.append(f"run errands at the {listed(machines)}")
        return f"What I can do here: {listed(parts)}."

    def is_person_word(self, word: str) -> bool:
        tokens = self.lex.tokens(word)
        return any(m.kind == "person" for m in self.lex.scan(tokens))

    def is_one_person(self, phrase: str) -> bool:
        """Whether ``phrase`` is one colleague's name, all of it ("Tom Hughes's"), not two
        names side by side ("Tom Mai's")."""
        tokens = self.lex.tokens(phrase)
        mentions = self.lex.scan(tokens)
        return (
            len(mentions) == 1
            and mentions[0].kind == "person"
            and (mentions[0].start, mentions[0].end) == (0, len(tokens))
        )

    def names_at(self, text: str) -> bool:
        """Whether ``text`` opens with a name of this office ("lunch box", "Sun Li"); a word
        that is only part of one ("box" of "lunch box") is not."""
        mentions = self.lex.scan(self.lex.tokens(text))
        return bool(mentions) and mentions[0].start == 0 and mentions[0].kind != "word"


def article(noun: str) -> str:
    return "an" if noun[:1].lower() in "aeiou" else "a"


def listed(words: list[str]) -> str:
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


def who_has(names: list[str], a_thing: str) -> str:
    """ "As far as I know, Dang Hao and Zhou Yan have a data cable.": colleagues who own
    ``a_thing`` (said with its article), as the assistant knows them."""
    has = "has" if len(names) == 1 else "have"
    return f"As far as I know, {listed(names)} {has} {a_thing}."
