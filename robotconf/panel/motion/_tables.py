"""A motion's DVA table and statistics as readable HTML: units in the headers, numbers
right-aligned in equal-width digits, the header kept in sight while the rows scroll.

The numbers are the core's (:attr:`Motion.table <robotconf.Motion.table>`,
:meth:`Motion.stats <robotconf.Motion.stats>`); the only change is the angle unit:
angular velocities are shown in deg/s in degree mode (the core's rad/s times 180/π).
Float noise (``7.77e-15`` where the exact value is 0) shows as 0, as in the Matrices tab:
a number is noise when it is below 1e-12 of the largest magnitude of its quantity (all
its axes and points) or of the robot's size, so a coordinate that is 0 throughout (the
paper's y) reads 0 too.
"""

from __future__ import annotations

import html
from typing import TYPE_CHECKING

import numpy as np

from ..state import Units

ANGLE_UNIT = "rad"

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["dva_table_html", "stats_table_html", "TABLE_CLASS"]

#: Class of every result table (the style below is scoped to it).
TABLE_CLASS = "robotconf-result"
#: Below this fraction of a column's largest magnitude a number is float noise.
_NOISE = 1e-12
#: The tables' look. Line height: an HTML widget gives its content the 28 px of a
#: control row, which would space the rows out. Digits: tabular, so columns of numbers
#: line up. The header sticks to the top of the scrolling box. The widget's content box
#: may shrink below the table's width (a flex item would not), so a wide table scrolls
#: sideways in its own box and never widens the panel.
_STYLE = f"""<style>
.{TABLE_CLASS} {{max-height: 360px; overflow: auto; border: 1px solid #ddd;
  font-size: 11px; line-height: 1.35; max-width: 100%;}}
.{TABLE_CLASS} table {{border-collapse: collapse; font-variant-numeric: tabular-nums;}}
.{TABLE_CLASS} th, .{TABLE_CLASS} td {{padding: 2px 4px; white-space: nowrap;}}
.{TABLE_CLASS} td {{text-align: right;
  font-family: var(--jp-code-font-family, monospace), monospace;}}
.{TABLE_CLASS} th {{text-align: center; font-weight: 600;
  background: var(--jp-layout-color1, #f5f5f5);}}
.{TABLE_CLASS} th.row {{text-align: left; white-space: normal; min-width: 5em;}}
.{TABLE_CLASS} thead {{position: sticky; top: 0; z-index: 1;}}
.{TABLE_CLASS} tbody tr:nth-child(even) td {{background: var(--jp-layout-color2, #fafafa);}}
.{TABLE_CLASS} .group {{border-left: 1px solid #ccc;}}
.{TABLE_CLASS} th.quantity {{white-space: normal;}}
.{TABLE_CLASS} th.wrap {{white-space: normal;}}
.{TABLE_CLASS} th.point {{border-top: 1px solid #ccc;}}
.widget-html-content:has(> .{TABLE_CLASS}) {{min-width: 0;}}
</style>"""


#: Start of every result table: its style, the scrolling box, the table (classed like
#: pandas' own HTML, which tests and the app's pages look for).
_OPEN = f"{_STYLE}<div class='{TABLE_CLASS}'><table class='dataframe'>"


def _heading(quantity: str, units: Units) -> str:
    """``"angular velocity [deg/s]"`` for a quantity of the core's table."""
    return f"{quantity.replace('_', ' ')} [{html.escape(units.quantity(quantity))}]"


def _cleaned(values: np.ndarray, groups: np.ndarray, size: float) -> np.ndarray:
    """``values`` with float noise as 0: below ``_NOISE`` times the largest magnitude of
    the same quantity (``groups`` names each column's, or each row's for statistics,
    along the last axis) or times the robot's ``size``.

    >>> _cleaned(np.array([[70.0, 7.77e-15]]), np.array(["position", "position"]), 90.0)
    array([[70.,  0.]])
    """
    with np.errstate(invalid="ignore"):
        magnitude = np.abs(values)
        out = values.copy()
        for group in dict.fromkeys(groups.tolist()):
            chosen = groups == group
            largest = max(float(np.nanmax(magnitude[..., chosen], initial=0.0)), size)
            part = out[..., chosen]
            part[magnitude[..., chosen] < _NOISE * largest] = 0.0
            out[..., chosen] = part
    return out


def _number(value: float) -> str:
    return f"{value:.6g}"


def _shown(frame: pd.DataFrame, units: Units, quantity_level: int) -> np.ndarray:
    """The frame's numbers in the panel's units: angular velocities scaled."""
    values = frame.to_numpy(dtype=float, copy=True)
    quantities = frame.columns.get_level_values(quantity_level)
    scale = units.scale(ANGLE_UNIT)
    if scale != 1.0:
        values[:, np.asarray(quantities == "angular_velocity")] *= scale
    return values


def dva_table_html(frame: pd.DataFrame, units: Units, size: float = 0.0) -> str:
    """HTML of (some columns of) :attr:`Motion.table <robotconf.Motion.table>`.

    Parameters
    ----------
    frame : pandas.DataFrame
        Rows of the core's table, its ``(point, quantity, axis)`` columns for one point
        or for all.
    units : Units
        The panel's units: names the length unit, converts angular velocities.
    size : float
        The robot's size (length units): a number below 1e-12 of it is noise.

    Returns
    -------
    str
        A scrolling ``<div>`` holding the table; point names are escaped.

    Examples
    --------
    >>> import robotconf as rc
    >>> motion = rc.simulate(rc.preset("paper"), {}, t_end=0.5, dt=0.5)
    >>> text = dva_table_html(motion.table.loc[:, ["EE"]], Units("mm"))
    >>> "position [mm]" in text, "angular velocity [deg/s]" in text, "<td>70</td>" in text
    (True, True, True)
    """
    columns = frame.columns
    points = list(dict.fromkeys(columns.get_level_values(0)))
    quantities = np.asarray(columns.get_level_values(1))
    values = _cleaned(_shown(frame, units, 1), quantities, size)
    rows = [
        "<tr><th></th>"
        + "".join(
            f"<th class='group' colspan='{(columns.get_level_values(0) == p).sum()}'>"
            f"{html.escape(str(p))}</th>"
            for p in points
        )
        + "</tr>"
    ]
    points_and_quantities = zip(
        columns.get_level_values(0), columns.get_level_values(1), strict=True
    )
    pairs = list(dict.fromkeys(points_and_quantities))
    rows.append(
        "<tr><th class='row'>t [s]</th>"
        + "".join(
            f"<th class='group quantity' colspan='3'>{_heading(quantity, units)}</th>"
            for _, quantity in pairs
        )
        + "</tr>"
    )
    rows.append(
        "<tr><th></th>"
        + "".join(
            f"<th{' class=group' if i % 3 == 0 else ''}>{html.escape(str(axis))}</th>"
            for i, axis in enumerate(columns.get_level_values(2))
        )
        + "</tr>"
    )
    body = "".join(
        f"<tr><td>{_number(t)}</td>" + "".join(f"<td>{_number(v)}</td>" for v in row) + "</tr>"
        for t, row in zip(frame.index, values, strict=True)
    )
    return f"{_OPEN}<thead>{''.join(rows)}</thead><tbody>{body}</tbody></table></div>"


def stats_table_html(stats: pd.DataFrame, units: Units, size: float = 0.0) -> str:
    """HTML of (some rows of) :meth:`Motion.stats <robotconf.Motion.stats>`.

    One row per (point, quantity, axis), the rows of each point under its name when
    there are several; the unit of each row's numbers is in its quantity's heading
    (times in seconds).

    Examples
    --------
    >>> import robotconf as rc
    >>> motion = rc.simulate(rc.preset("paper"), {}, t_end=0.5, dt=0.5)
    >>> text = stats_table_html(motion.stats().loc[["EE"]], Units("cm"))
    >>> "velocity [cm/s]" in text, "t_max [s]" in text
    (True, True)
    """
    index = stats.index
    values = _shown(stats.T, units, 1).T
    times = np.asarray([name.startswith("t_") for name in stats.columns])
    quantities = np.asarray(index.get_level_values(1))
    values[:, ~times] = _cleaned(values[:, ~times].T, quantities, size).T
    points = list(index.get_level_values(0))
    several = len(set(points)) > 1
    heads = [f"{name} [s]" if name.startswith("t_") else name for name in stats.columns]
    # The core's column names; a header may wrap after "_" (peak_to_peak) to save width.
    header = "<th class='row'>quantity</th><th>axis</th>" + "".join(
        f"<th class='wrap'>{html.escape(head).replace('_to_', '_<wbr>to_<wbr>')}</th>"
        for head in heads
    )
    pairs = list(zip(points, index.get_level_values(1), strict=True))
    body = []
    for i, (point, quantity, axis) in enumerate(index):
        cells = ""
        if several and (i == 0 or points[i - 1] != point):
            # Each point heads its rows across the table: no column spent on it.
            body.append(
                f"<tr><th class='row point' colspan='{2 + len(heads)}'>"
                f"{html.escape(str(point))}</th></tr>"
            )
        if i == 0 or pairs[i - 1] != pairs[i]:
            span = pairs.count(pairs[i])
            cells += f"<th class='row' rowspan='{span}'>{_heading(quantity, units)}</th>"
        cells += f"<th>{html.escape(str(axis))}</th>"
        cells += "".join(f"<td>{_number(v)}</td>" for v in values[i])
        body.append(f"<tr>{cells}</tr>")
    return f"{_OPEN}<thead><tr>{header}</tr></thead><tbody>{''.join(body)}</tbody></table></div>"
