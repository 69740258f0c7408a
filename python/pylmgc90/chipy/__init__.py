"""`pylmgc90.chipy` inside lmgc-run: lmgc's chipy module under LMGC90's name."""
import sys

import lmgc.chipy as _chipy

# One module object under both names, so that attributes a script sets on one are seen on the other.
sys.modules[__name__] = _chipy
