"""The request screen: ask or decline, never guess — before any task is read from a request.

A request is cut into pieces (sentences, and the comma/"and"/"then" parts of one); a table of
rules, tried in priority order, says what each piece is. The first rule that matches a piece
decides it:

==============  ==================================================================  ==========
rule            matches                                                             effect
==============  ==================================================================  ==========
withdrawn       "never mind", "forget it", "forget about the scissors"              drops all
                                                                                    said before
exclusion       "not from Wang though", "not Chen's"                                a hint that
                                                                                    keeps them out
purpose         "... so he can book the courier", "... if anyone needs it",         context
                "..., need it for the report": why or for whom, never what to do
wish            "keep everyone away from Mao's seal", "nobody take my mug"          words only
thanks          "thanks for the pen!", "say thanks to Wang for the pen"             words only
negated         "don't bring me ...", "no need to print ..."                        drops piece
unsafe          "set light to Reed's banner", "set off the fire alarm", "torch      declines
                Reed's banner" (not "bring me a torch")
running_machine "get my mug out of the coffee machine while it's still brewing",     declines
                "..., I know it's mid-job" (not "... once it's done")
destructive     "throw away Wang's stapler", "hide ...", "get rid of ...",          declines
                "chuck Reed's clipboard in the skip" (any verb, a waste container)
unplaced        "stick Reed's clipboard in the van": a verb that is no errand, to   asks what
                a place that names nothing of the office                            to do
elliptical      the reason after "got a loupe anywhere?" ("want to check the        context; the
                plates"): the ask before it is a request for one                    ask kept
fact            "Wang is away", "Zhang is in the meeting room",                     a hint;
                "Zhang's stapler is broken"                                         drops piece
question        "who has a tape measure?", "is the printer working?" (not "could    answered;
                you bring me ...?", a request)                                      "Shall I?"
statement       "my laptop cable is too short", "I spilled my tea"                  context
which           "Jürgen's curry from the staff fridge", where he keeps several      asks which
                things (one: the rewrites name it)
variant         a made thing in a variant the office does not make: "a master key   declines;
                card" (more authority), "an iced tea" (not "a strong tea")          "Shall I
                                                                                    make an
                                                                                    ordinary
                                                                                    one?"
asked_doer      a colleague asked to do a facility's work they do not run ("get     "Shall I get
                Zhang to make me a copy" where Zhang keeps no printer)              it done at
                                                                                    the printer
                                                                                    instead?"
outsider        a recipient who is nobody of the office ("for the man at the        declines a
                desk", "bring the courier guy a tea")                               credential;
                                                                                    "Shall I
                                                                                    bring it to
                                                                                    you?"
unsupported     a service the office does not offer ("scan my contract",            declines
                "make me a cup of tea"), a send to an outside account ("to my
                personal gmail"), a request behind an owner's back ("borrow
                Zhang's stapler without telling him"), an absent owner's yes
                said for them ("Otto is away, take his ruler, he won't mind"),
                or every one of a kind colleagues own ("wipe all the drives")
==============  ==================================================================  ==========

The speech acts (wish, thanks, question, statement) are read by ``speech``: only a request moves the
robot, the others are answered in words. A message with no request left is answered with the
replies of its pieces; an information question that may be a request in disguise ("does anyone
have a stapler?") is answered and met with "Shall I bring you one?"; a third person's need
with no request wording ("Min needs scissors") is restated and asked before anything moves.

Then two rewrites make the rest readable by the frame parser: a thing named by its purpose
("something to cut this with") becomes the office's item type declared for that purpose, and
"another one" after a stated condition ("Zhang's stapler is broken") becomes that item.

The English words live in the package's ``data/english.yaml`` (``assistantx.core.english``); the
office's words (people, items, facilities, purposes) come from the office file. Pieces are
removed from the original text by their character spans, never re-joined, so what is left
parses as the person wrote it.

Each rule is a module of its own (``withdrawal``, ``note``, ``exclusion``, ``contrast``,
``purpose``, ``need_to_know``, ``wish``, ``thanks``, ``condition``, ``nothing_follows``,
``negation``, ``unsafe``,
``destructive``,
``placement``, ``elliptical``, ``fact``, ``facility_report``, ``own_doing``, ``doing_after``,
``own_need``, ``others_doing``, ``others_send_out``, ``question``, ``problem``, ``statement``,
``whereabouts``, ``kept``, ``variant``,
``service``, ``asked_doer``, ``outsider``), tried in the order of ``rules``; each reads the piece's
lexicon reading (``Piece.lexed``) and speech acts (``Piece.acts``, the ``speech_acts`` stage before
the screen), never its text again. ``request_screen`` runs in three steps the parser calls in turn:
``verdicts`` (the pieces judged: ``Spoken``), ``request`` (what is left, ``rewrites``: ``Request``),
and, after the readings and frames, ``decide`` (the message as a whole, ``answer``: ``Screened``);
``judge`` is the last stage.
"""

from assistantx.agents.symbolic.reading.screen.findings import UNANSWERED, Screened
from assistantx.agents.symbolic.reading.screen.request_screen import RequestScreen

__all__ = ["UNANSWERED", "RequestScreen", "Screened"]
