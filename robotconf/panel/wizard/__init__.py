"""The guided mode: the paper's questionnaire (Figure 12), drawn from the state's draft."""

from ._view import KIND_EXPLANATIONS, WizardView, formula, numeric

__all__ = ["WizardView", "KIND_EXPLANATIONS", "formula", "numeric"]
