"""A campaign: many independent trials run in parallel, streamed back as they end.

:func:`run_campaign` runs a list of :class:`TrialSpec` with a trial function
(default :func:`~tautwire.experiments.trial.run_trial`) on one of three
backends:

``serial``
    One trial after the other in this process (debugging, ``--only``).
``local``
    A pool of worker processes on this machine, started with ``spawn`` (no
    inherited threads or simulator state; safe on every platform). Each
    worker runs one trial at a time, so the parent always knows which trial
    a worker holds: a worker that dies (segfault, ``os._exit``, out of
    memory) costs exactly that trial, recorded as a failure with cause
    ``"crashed"``, and a new worker takes its place; so does one that runs
    past ``trial_timeout`` (cause ``"hung"``). As with any ``spawn``
    pool, a script that starts a campaign must guard its entry point with
    ``if __name__ == "__main__":``.

    Why not ``concurrent.futures.ProcessPoolExecutor``: when one worker dies
    the executor breaks as a whole (``BrokenProcessPool``) and every trial
    not yet returned is lost (``bench/campaign_pool.py``: of 20 trials, one
    killing its worker, the executor returned 2 results, this pool 20, the
    one recorded as crashed), and it cannot stop a hung call at all. Its
    overhead is the same (1.7 ms per trial on 2 workers, both). Why not
    pebble, whose ``ProcessPool`` has per-task timeouts and tells which task
    a dead worker held: it would be a new dependency (LGPL-3.0) that still
    leaves this module its own parts: workers born ignoring Ctrl-C so that
    an interrupted campaign returns what finished, a log file per worker
    with a header line per trial, a trial handed back if its worker dies
    before taking it, and the same callback for the serial and Ray backends.
``ray``
    Ray tasks on a local Ray instance or on a cluster (``address``, whose
    nodes need tautwire installed); Ray is the optional extra
    ``tautwire[ray]`` and is imported only here. A task whose worker dies is
    recorded with cause ``"crashed"``.

Every backend hands each result to a callback as soon as it arrives (a
progress bar, incremental saving). A trial that raises is a failure with
cause ``"error"``. A :class:`KeyboardInterrupt` (Ctrl-C, or raised by the
callback) stops the campaign and keeps the finished trials. The results come
back ordered by (letter, index), whatever order they finished in, so a
campaign's output depends on its specs only.
"""

from __future__ import annotations

import importlib
import logging
import multiprocessing
import os
import pickle
import signal
import sys
import threading
import time
import traceback
from collections import deque
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from multiprocessing.connection import Connection, wait
from multiprocessing.context import BaseContext
from multiprocessing.process import BaseProcess
from pathlib import Path
from typing import Any

from tautwire.errors import InvalidArgumentError, TautwireError
from tautwire.experiments.trial import LETTERS, TrialResult, TrialSpec, run_trial

#: A trial function: runs one trial, returns its result. For the ``local``
#: and ``ray`` backends it must be picklable (defined at module level).
TrialFunction = Callable[[TrialSpec], TrialResult]

#: Called once per finished trial, in the campaign's process.
ResultCallback = Callable[[TrialResult], None]

#: The backends :func:`run_campaign` offers.
BACKENDS: tuple[str, ...] = ("serial", "local", "ray")

#: Environment variables that cap the threads of numerical libraries; each
#: worker runs one trial on one core, so each is set to 1 unless the user set it.
THREAD_VARIABLES: tuple[str, ...] = (
    "OMP_NUM_THREADS",
    "OPENBLAS_NUM_THREADS",
    "MKL_NUM_THREADS",
    "VECLIB_MAXIMUM_THREADS",
    "NUMEXPR_NUM_THREADS",
)

#: Causes of a trial that ended without an outcome of its own, because of the
#: machinery around it rather than the primitive: its worker process died
#: (``"crashed"``), it ran past the pool's ``trial_timeout`` (``"hung"``), or
#: the trial function raised an internal error (``"error"``). A resumed
#: campaign runs such trials again (:func:`is_trial_outcome`).
INFRASTRUCTURE_CAUSES: frozenset[str] = frozenset({"crashed", "hung", "error"})

#: Seconds a stopping worker gets to exit before it is terminated.
_STOP_GRACE = 2.0


class CampaignError(TautwireError):
    """The campaign could not run at all (a backend is missing, workers cannot start)."""


@dataclass(frozen=True)
class CampaignResult:
    """What a campaign produced.

    Attributes:
        results: The finished trials, ordered by (letter, index).
        planned: How many trials were asked for.
        interrupted: Whether the campaign was stopped before all trials ended.
        backend: The backend that ran the trials.
        workers: How many trials ran at a time.
        wall_time: Wall time of the campaign [s].
    """

    results: tuple[TrialResult, ...]
    planned: int
    interrupted: bool
    backend: str
    workers: int
    wall_time: float

    @property
    def finished(self) -> int:
        """How many trials finished (successfully or not)."""
        return len(self.results)

    @property
    def failures(self) -> int:
        """How many of the finished trials failed."""
        return sum(1 for r in self.results if not r.success)


def result_order(result: TrialResult) -> tuple[int, str, int]:
    """Sort key of a result: the letter's row in :data:`LETTERS`, then the index."""
    row = LETTERS.index(result.letter) if result.letter in LETTERS else len(LETTERS)
    return row, result.letter, result.index


def _primitive_name(letter: str) -> str:
    """The primitive's canonical name, or ``""`` for a letter the catalogue lacks."""
    try:
        from tautwire.scenario.primitive_catalogue import find_primitive

        return find_primitive(letter).name
    except (TautwireError, ImportError):
        return ""


def is_trial_outcome(result: TrialResult) -> bool:
    """Whether ``result`` is the trial's own outcome, worth keeping on a resume.

    A success, or a failure the trial itself reported (``force_limit``,
    ``timeout``, ``diverged``, ``false_success``, ...), is; a failure of
    the infrastructure (:data:`INFRASTRUCTURE_CAUSES`) is not: the trial
    never got to its end.
    """
    return result.success or result.cause not in INFRASTRUCTURE_CAUSES


def failed_trial(spec: TrialSpec, cause: str, detail: str, wall_time: float = 0.0) -> TrialResult:
    """The result of a trial that ended without a result of its own.

    Args:
        spec: The trial.
        cause: ``"error"`` (the trial function raised) or ``"crashed"`` (its
            worker process died).
        detail: What happened, for a reader.
        wall_time: Wall time spent on the trial [s].
    """
    return TrialResult(
        spec.letter,
        _primitive_name(spec.letter),
        spec.index,
        spec.seed,
        {},
        "failure",
        cause,
        detail,
        0.0,
        0.0,
        wall_time,
    )


def _describe(exc: BaseException) -> str:
    """``Type: message at file:line`` of an exception, where it was raised."""
    frames = traceback.extract_tb(exc.__traceback__) if exc.__traceback__ else []
    where = f" at {frames[-1].filename.rsplit('/', 1)[-1]}:{frames[-1].lineno}" if frames else ""
    return f"{type(exc).__name__}: {exc}{where}"


def guarded_trial(trial: TrialFunction, spec: TrialSpec) -> TrialResult:
    """Run ``trial(spec)``; an exception or a wrong return becomes a failure with cause "error".

    ``KeyboardInterrupt`` and ``SystemExit`` pass through (the caller decides).
    """
    t0 = time.perf_counter()
    try:
        result = trial(spec)
    except Exception as exc:
        return failed_trial(
            spec, "error", f"the trial raised {_describe(exc)}", time.perf_counter() - t0
        )
    if not isinstance(result, TrialResult):
        return failed_trial(
            spec,
            "error",
            f"the trial function returned {type(result).__name__}, not TrialResult",
            time.perf_counter() - t0,
        )
    return result


def _check(
    specs: Sequence[TrialSpec], backend: str, workers: int, trial_timeout: float | None
) -> None:
    if backend not in BACKENDS:
        raise InvalidArgumentError(
            f"unknown backend {backend!r} (expected one of: {', '.join(BACKENDS)})"
        )
    if workers < 1:
        raise InvalidArgumentError(f"workers must be at least 1, got {workers}")
    if trial_timeout is not None and not trial_timeout > 0:
        raise InvalidArgumentError(f"trial_timeout must be positive, got {trial_timeout}")
    seen: set[tuple[str, int]] = set()
    for spec in specs:
        key = (spec.letter, spec.index)
        if key in seen:
            raise InvalidArgumentError(f"trial {spec.letter}:{spec.index} is listed twice")
        seen.add(key)


def run_campaign(
    specs: Sequence[TrialSpec],
    trial: TrialFunction = run_trial,
    *,
    backend: str = "local",
    workers: int = 2,
    address: str | None = None,
    on_result: ResultCallback | None = None,
    log_dir: str | Path | None = None,
    trial_timeout: float | None = None,
) -> CampaignResult:
    """Run every trial of ``specs``; stream each result to ``on_result`` as it ends.

    Args:
        specs: The trials; (letter, index) must be unique.
        trial: The trial function (module-level, for ``local`` and ``ray``).
        backend: ``"serial"``, ``"local"`` or ``"ray"``.
        workers: Trials at a time (``local``), or CPUs of the local Ray
            instance (``ray`` without ``address``); ``serial`` runs one.
        address: The Ray cluster to join (``ray`` only); None starts a local one.
        on_result: Called with each result as it arrives, in completion order.
            If it raises ``KeyboardInterrupt`` the campaign stops there,
            keeping that result.
        log_dir: ``local`` only: each worker writes its output (warnings of
            the simulator, anything a trial prints) to ``worker-N.log`` in
            this folder, under a header line per trial, instead of this
            process's terminal. None: the workers share this terminal.
        trial_timeout: ``local`` only: wall time [s] after which a trial
            that has not returned is stopped (its worker killed) and
            recorded as a failure with cause ``"hung"``; None waits forever.

    Returns:
        The finished trials ordered by (letter, index), and whether the
        campaign was interrupted (Ctrl-C): an interrupted campaign returns
        instead of raising, so its caller can save what finished.

    Raises:
        InvalidArgumentError: for an unknown backend, ``workers < 1`` or a
            trial listed twice.
        CampaignError: when the backend cannot run (Ray missing, the trial
            function cannot be sent to or loaded in a worker).
    """
    _check(specs, backend, workers, trial_timeout)
    logs = None if log_dir is None else Path(log_dir)
    results: list[TrialResult] = []

    def deliver(result: TrialResult) -> None:
        results.append(result)
        if on_result is not None:
            on_result(result)

    t0 = time.perf_counter()
    interrupted = False
    used = 1
    try:
        if backend == "serial":
            _run_serial(specs, trial, deliver)
        elif backend == "local":
            used = workers
            _run_local(specs, trial, min(workers, len(specs)), logs, trial_timeout, deliver)
        else:
            used = _run_ray(specs, trial, workers, address, deliver)
    except KeyboardInterrupt:
        interrupted = True
    return CampaignResult(
        tuple(sorted(results, key=result_order)),
        len(specs),
        interrupted,
        backend,
        used,
        time.perf_counter() - t0,
    )


def _run_serial(specs: Sequence[TrialSpec], trial: TrialFunction, deliver: ResultCallback) -> None:
    for spec in specs:
        deliver(guarded_trial(trial, spec))


# ---------------------------------------------------------------- local backend


def _redirect_output(path: Path) -> None:
    """Send this process's stdout and stderr (C libraries' too) to the file at ``path``."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_APPEND, 0o644)
    sys.stdout.flush()
    sys.stderr.flush()
    os.dup2(fd, 1)
    os.dup2(fd, 2)
    os.close(fd)


def _worker_main(conn: Connection, payload: bytes, log: Path | None) -> None:
    """A worker process: load the trial function, then run trials until told to stop.

    Messages to the parent: ``("ready", None)`` once, ``("result", TrialResult)``
    per trial, or ``("fatal", message)`` if the trial function cannot be loaded.
    With ``log``, the worker's output goes to that file, a header line per trial.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    if hasattr(signal, "pthread_sigmask"):  # born with it blocked (_sigint_ignored)
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
    for name in THREAD_VARIABLES:
        os.environ.setdefault(name, "1")
    if log is not None:
        _redirect_output(log)
    try:
        trial = pickle.loads(payload)
    except BaseException as exc:
        conn.send(("fatal", f"a worker could not load the trial function: {_describe(exc)}"))
        return
    conn.send(("ready", None))
    while True:
        try:
            spec = conn.recv()
        except (EOFError, OSError):
            return
        if spec is None:
            return
        if log is not None:
            print(
                f"=== trial {spec.letter}:{spec.index} seed {spec.seed}",
                file=sys.stderr,
                flush=True,
            )
        t0 = time.perf_counter()
        try:
            result = guarded_trial(trial, spec)
        except BaseException as exc:  # SystemExit, KeyboardInterrupt inside the trial
            result = failed_trial(
                spec, "error", f"the trial raised {_describe(exc)}", time.perf_counter() - t0
            )
        try:
            conn.send(("result", result))
        except Exception as exc:  # the result cannot be pickled
            conn.send(
                (
                    "result",
                    failed_trial(
                        spec, "error", f"the result could not be sent back: {_describe(exc)}"
                    ),
                )
            )


@contextmanager
def _sigint_ignored() -> Iterator[None]:
    """Hold SIGINT back while a child starts, so that it is born ignoring Ctrl-C.

    Blocked, not ignored: the child inherits the blocked mask and ignores the
    signal itself before it unblocks it (:func:`_worker_main`), while a
    Ctrl-C that reaches the parent meanwhile stays pending and is delivered
    when the start is over. Ignoring it lost it: a spawn takes up to a second
    on a loaded machine, and a Ctrl-C in that time left the campaign running
    to its end. Where signals cannot be blocked (not the main thread, no
    ``pthread_sigmask``), SIGINT is ignored for the start as before, or left
    alone outside the main thread.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    if hasattr(signal, "pthread_sigmask"):
        signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
        try:
            yield
        finally:
            signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


@dataclass
class _Worker:
    """A worker process, its end of the pipe and the trial it holds."""

    process: BaseProcess
    conn: Connection
    ready: bool = False
    spec: TrialSpec | None = None
    started: float = 0.0


def _start_worker(
    context: BaseContext, payload: bytes, number: int, log_dir: Path | None
) -> _Worker:
    parent_end, child_end = context.Pipe()
    log = None if log_dir is None else log_dir / f"worker-{number}.log"
    process = context.Process(  # type: ignore[attr-defined]
        target=_worker_main,
        args=(child_end, payload, log),
        name=f"tautwire-trial-worker-{number}",
        daemon=True,
    )
    with _sigint_ignored():
        process.start()
    child_end.close()
    return _Worker(process, parent_end)


def _exit_text(process: BaseProcess) -> str:
    """How a dead process ended, e.g. ``"exit code 3"`` or ``"signal SIGSEGV"``."""
    process.join(timeout=_STOP_GRACE)
    code = process.exitcode
    if code is None:
        return "unknown exit"
    if code < 0:
        try:
            return f"signal {signal.Signals(-code).name}"
        except ValueError:
            return f"signal {-code}"
    return f"exit code {code}"


def _stop_workers(pool: list[_Worker]) -> None:
    """Stop every worker: idle ones are asked to exit, busy ones are terminated."""
    for worker in pool:
        if worker.process.is_alive():
            if worker.spec is None:
                try:
                    worker.conn.send(None)
                except OSError:
                    worker.process.terminate()
            else:
                worker.process.terminate()
    deadline = time.monotonic() + _STOP_GRACE
    for worker in pool:
        worker.process.join(timeout=max(0.0, deadline - time.monotonic()))
        if worker.process.is_alive():
            worker.process.kill()
            worker.process.join(timeout=_STOP_GRACE)
        worker.conn.close()


def _run_local(
    specs: Sequence[TrialSpec],
    trial: TrialFunction,
    workers: int,
    log_dir: Path | None,
    trial_timeout: float | None,
    deliver: ResultCallback,
) -> None:
    if not specs:
        return
    try:
        payload = pickle.dumps(trial)
    except Exception as exc:
        raise CampaignError(
            f"the trial function cannot be sent to worker processes ({_describe(exc)}); "
            "define it at module level"
        ) from exc
    context = multiprocessing.get_context("spawn")
    queue = deque(specs)
    started = 0
    pool: list[_Worker] = []
    try:
        for _ in range(workers):
            pool.append(_start_worker(context, payload, started, log_dir))
            started += 1
        while queue or any(w.spec is not None for w in pool):
            for worker in pool:
                if worker.ready and worker.spec is None and queue:
                    nxt = queue.popleft()
                    try:
                        worker.conn.send(nxt)
                    except OSError:  # the worker just died: the next wait sees it
                        queue.appendleft(nxt)
                        continue
                    worker.spec, worker.started = nxt, time.perf_counter()
            waitables: list[Any] = [w.conn for w in pool] + [w.process.sentinel for w in pool]
            ready = wait(waitables, timeout=_wait_timeout(pool, trial_timeout))
            for slot, worker in enumerate(pool):
                if worker.conn not in ready and worker.process.sentinel not in ready:
                    continue
                message = _receive(worker)
                if message is not None:
                    kind, value = message
                    if kind == "fatal":
                        raise CampaignError(str(value))
                    if kind == "ready":
                        worker.ready = True
                    elif kind == "result" and worker.spec is not None:
                        worker.spec = None
                        deliver(value)
                    continue
                # The worker died: its trial (if any) is the one that killed it.
                held, how = worker.spec, _exit_text(worker.process)
                worker.spec = None
                worker.conn.close()
                if not worker.ready:
                    raise CampaignError(
                        f"a worker process died while starting ({how}); "
                        "is the trial function importable in a fresh interpreter?"
                    )
                pool[slot] = _start_worker(context, payload, started, log_dir)
                started += 1
                if held is not None:
                    deliver(
                        failed_trial(
                            held,
                            "crashed",
                            f"the worker process died ({how}) while running this trial",
                            time.perf_counter() - worker.started,
                        )
                    )
            for slot, worker in enumerate(pool):
                if _overdue(worker, trial_timeout):
                    assert worker.spec is not None and trial_timeout is not None
                    overdue = worker.spec
                    worker.process.kill()
                    worker.process.join(timeout=_STOP_GRACE)
                    worker.conn.close()
                    pool[slot] = _start_worker(context, payload, started, log_dir)
                    started += 1
                    deliver(
                        failed_trial(
                            overdue,
                            "hung",
                            f"no result after {trial_timeout:g} s of wall time; "
                            "its worker process was killed",
                            time.perf_counter() - worker.started,
                        )
                    )
    finally:
        _stop_workers(pool)


def _overdue(worker: _Worker, trial_timeout: float | None) -> bool:
    """Whether the worker has held its trial for longer than ``trial_timeout`` [s]."""
    return (
        trial_timeout is not None
        and worker.spec is not None
        and time.perf_counter() - worker.started > trial_timeout
    )


def _wait_timeout(pool: list[_Worker], trial_timeout: float | None) -> float | None:
    """How long [s] to wait for messages before the next trial becomes overdue."""
    if trial_timeout is None:
        return None
    now = time.perf_counter()
    left = [trial_timeout - (now - w.started) for w in pool if w.spec is not None]
    return max(0.0, min(left)) + 0.01 if left else None


def _receive(worker: _Worker) -> tuple[str, Any] | None:
    """The worker's next message, or None if the worker is dead."""
    try:
        if worker.conn.poll():
            kind, value = worker.conn.recv()
            return str(kind), value
    except (EOFError, OSError):
        return None
    return None if not worker.process.is_alive() else ("idle", None)


# ------------------------------------------------------------------ ray backend


def _ray_module() -> Any:
    """The ``ray`` module, or a :class:`CampaignError` naming the extra to install.

    Imported dynamically (and typed ``Any``) so that neither the package nor
    its type checking needs Ray.
    """
    try:
        return importlib.import_module("ray")
    except ImportError as exc:
        raise CampaignError(
            "the ray backend needs Ray, an optional extra: pip install 'tautwire[ray]'"
        ) from exc


def _run_ray(
    specs: Sequence[TrialSpec],
    trial: TrialFunction,
    workers: int,
    address: str | None,
    deliver: ResultCallback,
) -> int:
    """Run the trials as Ray tasks; return the number of CPUs Ray runs them on."""
    ray = _ray_module()
    # Ray sets OMP_NUM_THREADS to a task's num_cpus (1) in its workers itself.
    own = not ray.is_initialized()
    if own:
        if address is None:
            ray.init(num_cpus=workers, include_dashboard=False, logging_level=logging.ERROR)
        else:
            ray.init(address=address, logging_level=logging.ERROR)
    try:
        cpus = int(ray.cluster_resources().get("CPU", workers) or workers)
        remote = ray.remote(num_cpus=1, max_retries=0)(guarded_trial)
        trial_ref = ray.put(trial)
        specs_of = {remote.remote(trial_ref, spec): spec for spec in specs}
        pending = list(specs_of)
        try:
            while pending:
                done, pending = ray.wait(pending, num_returns=1)
                for ref in done:
                    spec = specs_of[ref]
                    try:
                        result = ray.get(ref)
                    except ray.exceptions.RayError as exc:
                        raised = isinstance(exc, ray.exceptions.RayTaskError)
                        first = (str(exc).strip().splitlines() or [""])[0]
                        result = failed_trial(
                            spec,
                            "error" if raised else "crashed",
                            f"the Ray task failed: {type(exc).__name__}: {first}",
                        )
                    deliver(result)
        finally:
            for ref in pending:
                ray.cancel(ref, force=True)
        return cpus
    finally:
        if own:
            ray.shutdown()
