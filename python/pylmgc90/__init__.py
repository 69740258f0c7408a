"""Forwarding package: `from pylmgc90 import chipy` inside lmgc-run gives lmgc's chipy.

lmgc-run puts this folder first on sys.path; it is never installed where Python finds it by
itself, so that a real LMGC90 stays what `import pylmgc90` means everywhere else.
"""
