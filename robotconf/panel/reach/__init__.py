"""The Reach tab: a target the robot follows by inverse kinematics, and its closed-form
branches."""

from ._view import TOLERANCE, ReachView, status_text

__all__ = ["ReachView", "TOLERANCE", "status_text"]
