"""The symbolic reader, as stages that pass forward (see ``parser``): tokens → lexicon →
screen (the speech acts of each piece) → readings → frames → operations and unknown items →
the screen's judgement. ``InstructionParser`` runs them against one office."""
