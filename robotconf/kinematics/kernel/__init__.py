"""The numeric kernel: links as ``P·Screw(q)·Q`` composed over many samples in blocks.

Every kinematics number of a robot comes through here: a link's constant parts and its
screw (:class:`LinkGeometry`), and the vectorized composition of a chain of them over
``T`` samples without stacking 4×4 matrices.

One link
    :class:`LinkGeometry`
Chains over samples
    :func:`chain_poses`, :func:`chain_origins`, :func:`chain_point`,
    :func:`chain_point_pose`, :func:`link_matrices`, :func:`kernel_bytes`,
    :data:`BLOCK_SIZE`, :func:`cos_sin`

>>> import numpy as np
>>> links = [LinkGeometry(joint="R", axis=2, post_translation=np.array([1.0, 0, 0]))]
>>> chain_point(links, np.array([[np.pi / 2]]), np.zeros(3)).round(12) + 0.0
array([[0., 1., 0.]])
"""

from ._geometry import LinkGeometry
from ._kernel import (
    BLOCK_SIZE,
    chain_origins,
    chain_point,
    chain_point_pose,
    chain_poses,
    cos_sin,
    kernel_bytes,
    link_matrices,
)

__all__ = [
    "LinkGeometry",
    "BLOCK_SIZE",
    "cos_sin",
    "chain_poses",
    "chain_origins",
    "chain_point",
    "chain_point_pose",
    "link_matrices",
    "kernel_bytes",
]
