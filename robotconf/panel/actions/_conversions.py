"""The same robot in another editor: the core's conversions, with where each coordinate went.

Each function returns the converted robot and ``order``: for each coordinate of the new
robot, the index of the old coordinate it continues (``None`` for a new one), so the
motion signals follow their joints (the same list a reordering of rows gives).

- DH rows → modules: the core's :func:`~robotconf.dh_to_modules`, row by row. The
  constant θ and α of a row become rotation modules held at their value, named
  ``"… (constant)"``; an unnamed row's constants are named after the row
  (``"DH row 2: α (constant)"``), since two modules may not share a name.
- modules → DH rows: the core's :func:`~robotconf.modules_to_dh`, with the modules named
  ``"… (constant)"`` passed as held (``constant=``), so converting back gives the rows.
- standard ⇄ modified DH: the core's :func:`~robotconf.convert_dh`, with the rows named
  ``"… (constant)"`` (the base or tool row an earlier conversion added) passed as held, so
  converting back gives the original table.
"""

from __future__ import annotations

from ...kinematics import DHLink, Link, Module, Robot, convert_dh, dh_to_modules, modules_to_dh

__all__ = ["to_modules", "to_dh", "to_convention", "CONSTANT_MARK"]

#: How the core names a module that holds a constant of a DH row.
CONSTANT_MARK = "(constant)"

Order = list[int | None]


def to_modules(robot: Robot) -> tuple[Robot, Order]:
    """``robot`` with every DH row written as modules (modules stay as they are).

    Examples
    --------
    >>> import numpy as np, robotconf as rc
    >>> arm = rc.Robot.from_dh([(0, 0, 1, np.pi / 2, "R"), (0, 0, 1, 0, "R")])
    >>> modules, order = to_modules(arm)
    >>> [module.kind for module in modules.modules], order
    (['Rz', 'Rx', 'Rz', 'fixed'], [0, None, 1, None])
    >>> np.allclose(modules.end_effector(), arm.end_effector())
    True
    """
    links: list[Module | DHLink] = []
    order: Order = []
    active = None
    for i, link in enumerate(robot.modules):
        if i == robot.active:
            active = len(links)
        if not isinstance(link, DHLink):
            links.append(link)  # type: ignore[arg-type]
            order.append(i)
            continue
        # The constants carry the row's name; an unnamed row lends its place instead.
        named = link if link.name is not None else link.with_name(f"DH row {i + 1}")
        joint_seen = False
        for module in dh_to_modules(named):
            is_joint = not joint_seen and module.name == named.name
            joint_seen = joint_seen or is_joint
            if is_joint and link.name is None:
                module = module.with_name(None)
            links.append(module)
            order.append(i if is_joint else None)
    converted = Robot(links, end_effector=robot.end_effector_point, active=active, name=robot.name)
    return converted, order


def _is_held(link: Link) -> bool:
    return (getattr(link, "name", None) or "").endswith(CONSTANT_MARK)


def held_modules(robot: Robot) -> list[int]:
    """Positions of the links that hold a constant (named ``"… (constant)"`` by the core).

    >>> import robotconf as rc
    >>> held_modules(rc.Robot([rc.Module("Rx", q=1.0, name="α (constant)"), rc.Module("Rz")]))
    [0]
    """
    return [i for i, link in enumerate(robot.modules) if _is_held(link)]


def to_dh(robot: Robot, convention: str) -> tuple[Robot, Order]:
    """``robot`` as a DH table in ``convention`` (the core says why when it cannot be).

    Raises
    ------
    InvalidInputError
        The core's message naming the module that breaks the DH pattern.

    Examples
    --------
    >>> import robotconf as rc
    >>> arm = rc.Robot([rc.Module("Rz", a=(0, 0, 20)), rc.Module("Rz", a=(30, 0, 0))])
    >>> rows, order = to_dh(arm, "modified")
    >>> [(link.d, link.a) for link in rows.modules], order
    ([(20.0, 0.0), (0.0, 30.0)], [0, 1])
    """
    held = held_modules(robot)
    converted = modules_to_dh(robot, convention, constant=held)
    sources = [
        i
        for i, link in enumerate(robot.modules[: robot.active])
        if isinstance(link, DHLink) or (link.is_joint and i not in held)
    ]
    order: Order = list(sources) if len(sources) == converted.n else [None] * converted.n
    return converted, order


def to_convention(robot: Robot, convention: str) -> tuple[Robot, Order]:
    """The same DH robot written in the other convention (the core's ``convert_dh``).

    A row the conversion adds (``"base (constant)"``, ``"tool (constant)"``) has no
    coordinate of the old robot; the joints keep theirs, in order.

    Raises
    ------
    InvalidInputError
        The core's message when the robot cannot be written so.

    Examples
    --------
    >>> import numpy as np, robotconf as rc
    >>> arm = rc.Robot.from_dh([(0, 0, 1, np.pi / 2, "R"), (0, 0, 2, np.pi / 2, "R")])
    >>> craig, order = to_convention(arm, "modified")
    >>> [link.name for link in craig.modules], order
    ([None, None, 'tool (constant)'], [0, 1, None])
    >>> to_convention(craig, "standard")[0] == arm  # the tool row is held: back to 2 rows
    True
    """
    held = held_modules(robot)
    converted = convert_dh(robot, convention, constant=held)
    joints = iter(i for i in range(robot.n) if i not in held)
    by_name = {robot.modules[i].name: i for i in held}  # a held row that stays a row
    order: Order = [
        by_name.get(link.name) if _is_held(link) else next(joints, None)  # type: ignore[attr-defined]
        for link in converted.modules
    ]
    return converted, order
