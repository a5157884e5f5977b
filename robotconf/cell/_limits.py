"""Bounds of one cell query, checked before the work."""

__all__ = ["MAX_SAMPLES", "MAX_TARGETS", "MAX_VOXELS", "MAX_BASES"]

#: Configurations in one clearance or check call (a 100 s program at 1 kHz).
MAX_SAMPLES = 100_000

#: Targets of one reach call.
MAX_TARGETS = 10_000

#: Voxels of one reach map.
MAX_VOXELS = 100_000

#: Candidate bases times targets of one placement.
MAX_BASES = 20_000
