#!/usr/bin/env python3
"""Writes fuzz/lmgc.dict: the keywords of every grammar catalogue (string literals of the
catalogue sources) and the layout words of LMGC90's files, in libFuzzer's dictionary format.
Run from the repository root after a catalogue changes: scripts/fuzz_dictionary.py"""
import pathlib
import re

root = pathlib.Path(__file__).resolve().parent.parent
sources = sorted(root.glob("grammar/*/catalogue.cpp")) + sorted(
    p for p in root.glob("grammar/*/*_catalogue.cpp") if p.name != "diagnostic_catalogue.cpp")
words = set()
for path in sources:
    for literal in re.findall(r'"((?:[^"\\]|\\.){2,40})"', path.read_text()):
        if "\\" in literal or "{" in literal or literal.strip() != literal and not literal.endswith(" "):
            continue
        words.add(literal)
# Layout words the parsers look for outside the catalogues.
words.update(["$bdyty", "$blmty", "$nodty", "$tacty", "$$$$$$", "$behav", "$seety", "$gravy", "$model", "$steps",
              "$icdan", "$dofty", "$models", "$gpv", "nodes", "model", "behav", "color", "numbr", "time=",
              "evolution", "D+00", "D-01", "E+00", "FOIS", "REPETE", "DEPUIS", "APPELLE", "RETOUR", "STEP",
              "END", "chipy.", "from pylmgc90 import chipy\n", "range(", "ExSolver(", "\n", "  ", ":", "="])
lines = ["# Keywords of lmgc's grammars for the fuzzers (scripts/fuzz_dictionary.py writes this file)."]
for k, word in enumerate(sorted(words)):
    escaped = "".join(c if 32 <= ord(c) < 127 and c not in '"\\' else "\\x%02X" % ord(c) for c in word)
    lines.append(f'w{k}="{escaped}"')
(root / "fuzz" / "lmgc.dict").write_text("\n".join(lines) + "\n")
print(f"fuzz/lmgc.dict: {len(words)} words")
