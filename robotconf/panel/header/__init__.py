"""The header row: undo and redo, the preset, the editing mode and the units, and the
modules → DH question."""

from ._header import MODE_OPTIONS, HeaderView, dh_entry_note, dh_refusal
from ._presets import NO_PRESET, PRESET_OPTIONS, preset_of

__all__ = [
    "HeaderView",
    "MODE_OPTIONS",
    "dh_entry_note",
    "dh_refusal",
    "preset_of",
    "NO_PRESET",
    "PRESET_OPTIONS",
]
