"""Run one hostile input and judge its outcome: a clear refusal naming the field, or a
correct result, within a time and memory budget.

Cheap cases run in the test process. Risky ones (those that once hung, overflowed or ran
out of memory) run in a forked child with an address-space limit and a hard timeout, so a
regression fails its test instead of hanging or killing the suite.

The time a case reports is the CPU time of the work (the child's, for a risky case): the
budget is about the computation, and on a machine shared with other jobs the wall clock
also counts the waiting. The hard timeout is on CPU time too, with a wall-clock guard
``WALL_FACTOR`` times longer for a machine that is busy elsewhere.
"""

from __future__ import annotations

import multiprocessing
import resource
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import robotconf as rc

#: Extra address space a risky child may take beyond what the test process already maps.
CHILD_MEMORY = 1536 * 1024**2
#: How much longer than its CPU budget a risky case may take by the wall clock.
WALL_FACTOR = 10.0


@dataclass(frozen=True)
class Refused:
    """The input must end in an ``rc.InvalidInputError`` whose field contains ``field``."""

    field: str = ""
    message: str = ""


@dataclass(frozen=True)
class Returns:
    """The call must return; ``check(result)`` must hold (real numbers, not just "no error")."""

    check: Callable[[Any], bool]
    what: str = "the expected result"


@dataclass(frozen=True)
class Judged:
    """Either a refusal whose field contains ``field`` or a result for which ``check`` holds
    (an answer the checker may refuse to parse or grade as wrong)."""

    field: str
    check: Callable[[Any], bool]
    what: str = "the expected result"


@dataclass(frozen=True)
class Case:
    """One hostile input at one entry point."""

    entry: str
    name: str
    call: Callable[[], Any]
    expect: Refused | Returns | Judged
    risky: bool = False
    seconds: float = 20.0
    setup: Callable[[], None] | None = field(default=None, compare=False)

    @property
    def id(self) -> str:
        return f"{self.entry}: {self.name}"


def _one_line(message: str) -> bool:
    """One line of text, or a typing slip's line with a caret line under it."""
    lines = message.strip().split("\n")
    return len(lines) == 1 or (len(lines) == 2 and lines[1].strip() == "^")


def _outcome(case: Case) -> tuple[str, str, str, bool]:
    """``(kind, type name, text, ok)`` for one run in this process."""
    if case.setup is not None:
        case.setup()
    try:
        result = case.call()
    except rc.InvalidInputError as err:
        expect = case.expect
        message = expect.message if isinstance(expect, Refused) else ""
        ok = (
            isinstance(expect, (Refused, Judged))
            and expect.field in err.field
            and message in str(err)
            and _one_line(str(err))
        )
        return "refused", type(err).__name__, f"[{err.field}] {err}", ok
    except BaseException as err:  # noqa: BLE001 - every other exception is a finding
        text = "".join(traceback.format_exception_only(type(err), err)).strip()
        return "raised", type(err).__name__, text[:2000], False
    finally:
        rc.set_memory_budget(None)
    expect = case.expect
    if isinstance(expect, (Returns, Judged)):
        try:
            ok = bool(expect.check(result))
        except Exception as err:  # noqa: BLE001
            return "returned", type(result).__name__, f"check failed: {err!r}", False
        return "returned", type(result).__name__, expect.what, ok
    return "returned", type(result).__name__, repr(result)[:300], False


def _mapped_bytes() -> int:
    with open("/proc/self/statm", encoding="ascii") as statm:
        pages = int(statm.read().split()[0])
    return pages * resource.getpagesize()


def _child(case: Case, conn: Any) -> None:
    limit = _mapped_bytes() + CHILD_MEMORY
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    # A hard stop on CPU time (SIGXCPU ends the child) a little past the budget.
    cpu = int(time.process_time() + case.seconds) + 2
    resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu))
    start = time.process_time()
    outcome = _outcome(case)
    conn.send((*outcome, time.process_time() - start))
    conn.close()


def run_case(case: Case) -> tuple[str, str, str, bool, float]:
    """Run ``case`` and return ``(kind, type name, text, ok, CPU seconds)``."""
    if not case.risky:
        start = time.process_time()
        kind, name, text, ok = _outcome(case)
        return kind, name, text, ok, time.process_time() - start
    context = multiprocessing.get_context("fork")
    receive, send = context.Pipe(duplex=False)
    process = context.Process(target=_child, args=(case, send), daemon=True)
    process.start()
    send.close()
    seconds = float("inf")
    if receive.poll(case.seconds * WALL_FACTOR):
        try:
            kind, name, text, ok, seconds = receive.recv()
        except EOFError:
            kind, name, text, ok = "died", "EOFError", f"exit code {process.exitcode}", False
    else:
        wall = case.seconds * WALL_FACTOR
        kind, name, text, ok = "timeout", "", f"no answer within {wall:g} s of wall clock", False
    process.kill()
    process.join(5)
    if ok and seconds > case.seconds:
        kind, ok = "timeout", False
        text = f"took {seconds:.2f} s of CPU time; budget {case.seconds} s"
    return kind, name, text, ok, seconds
