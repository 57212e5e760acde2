"""The symbolic reader, as stages that pass forward (see ``parser``): screen → tokens →
lexicon → readings → frames. ``InstructionParser`` runs them against one office."""
