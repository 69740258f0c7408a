"""lmgc: a validation-first implementation of LMGC90. `lmgc.chipy` runs LMGC90's command.py scripts."""
