"""The note under a DVA figure when a driven coordinate has kinks or jumps."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..motion import Motion

__all__ = ["kink_note"]


def kink_note(motion: Motion) -> str | None:
    """The explanation printed under the plot when a driven coordinate has kinks.

    Returns ``None`` when every signal is smooth over the run.
    """
    kinks = motion.kinks()
    if not kinks:
        return None
    where = "; ".join(
        f"{name} at t = "
        + ", ".join(f"{t:g}" for t in times[:5])
        + (", …" if times.size > 5 else "")
        + " s"
        for name, times in kinks.items()
    )
    if motion.method != "analytic":
        # Backward differences put the whole jump on one sample, central ones spread it
        # over two: the backward spike is twice as tall, as in Simulink's Derivative block.
        spread = (
            "on one sample, as Simulink's Derivative block shows it"
            if motion.method == "backward"
            else "over two samples, half as tall as Simulink's backward differences"
        )
        return (
            f"Kinks or jumps of the input ({where}): at a kink the velocity jumps by Δv, so "
            "the exact acceleration is an impulse and finite differences show a real spike "
            f"≈ Δv/dt ({spread}); where the value itself jumps (a sawtooth's drop) the "
            "velocity spikes too. Spikes grow as dt shrinks; method='analytic' gives the "
            "one-sided values."
        )
    return (
        f"Kinks or jumps of the input ({where}): there the exact acceleration is an impulse; "
        "the analytic curves show one-sided (right-hand) values and leave the impulses out. "
        "method='backward' (Simulink's Derivative block) or 'numeric' shows them as spikes."
    )
