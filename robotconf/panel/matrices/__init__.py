"""The Matrices tab: the derivation of the panel's robot, as text or LaTeX, numeric or
symbolic."""

from ._view import MatricesView, math_html, q_text, too_long_note

__all__ = ["MatricesView", "math_html", "q_text", "too_long_note"]
