"""Quaternion arithmetic: the plain-float fast path against NumPy; prints JSON.

    .venv/bin/python bench/quaternion.py

For each operation the control loop uses every period (Hamilton product,
conjugate, sign fix, square root, logarithm, rotating a vector), the median
time [us] of one call over 20,000 seeded random unit quaternions:

- ``floats_us``: the fast path on tuples of floats (``*_floats`` in
  :mod:`tautwire.model.quaternion`);
- ``numpy_us``: the same formula written on NumPy 4-vectors (as the module's
  array functions were before they were built on the fast path; defined
  here), which is what the code would run without the fast path;
- ``array_api_us``: the module's array function (fast path plus the
  conversion from and to an array), where there is one;

and ``ratio`` = numpy_us / floats_us. The task space calls these some 20
times a control period.
"""

from __future__ import annotations

import json
import os
import platform
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from tautwire.model import quaternion as q

N = 20_000


def _median_us(fn: Callable[[int], object], n: int = N) -> float:
    for i in range(500):
        fn(i % n)
    times = np.empty(n)
    clock = time.perf_counter
    for i in range(n):
        t0 = clock()
        fn(i)
        times[i] = clock() - t0
    return float(np.median(times) * 1e6)


Array = np.ndarray[Any, Any]


def _np_multiply(a: Array, b: Array) -> Array:
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return np.array(
        [
            w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
            w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
        ]
    )


def _np_conjugate(a: Array) -> Array:
    return np.array([a[0], -a[1], -a[2], -a[3]])


def _np_positive(a: Array) -> Array:
    out = a / np.linalg.norm(a)
    return -out if out[0] < 0.0 else out


def _np_sqrt(a: Array) -> Array:
    a = -a if a[0] < 0.0 else a
    c = np.sqrt(max(0.5 * (1.0 + a[0]), 0.0))
    return np.concatenate(([c], (0.5 / c) * a[1:]))


def _np_log(a: Array) -> Array:
    a = -a if a[0] < 0.0 else a
    s = np.linalg.norm(a[1:])
    if s < 1e-6:
        return (2.0 / a[0]) * a[1:]
    return (2.0 * np.arctan2(s, a[0]) / s) * a[1:]


def _np_rotate(a: Array, v: Array) -> Array:
    qv = np.concatenate(([0.0], v))
    return _np_multiply(_np_multiply(a, qv), _np_conjugate(a))[1:]


def main() -> None:
    rng = np.random.default_rng(0)
    arrays = rng.normal(size=(N, 4))
    arrays /= np.linalg.norm(arrays, axis=1)[:, None]
    others = np.roll(arrays, 1, axis=0)
    vectors = rng.normal(size=(N, 3))
    floats = [q.quat_floats(a) for a in arrays]
    other_floats = [q.quat_floats(a) for a in others]
    vector_floats = [q.vec_floats(v) for v in vectors]
    fl, fo, fv = floats, other_floats, vector_floats
    cases: dict[str, tuple[Callable[[int], object], ...]] = {
        "multiply": (
            lambda i: q.multiply_floats(fl[i], fo[i]),
            lambda i: _np_multiply(arrays[i], others[i]),
            lambda i: q.multiply(arrays[i], others[i]),
        ),
        "conjugate": (
            lambda i: q.conjugate_floats(fl[i]),
            lambda i: _np_conjugate(arrays[i]),
            lambda i: q.conjugate(arrays[i]),
        ),
        "positive": (
            lambda i: q.positive_floats(fl[i]),
            lambda i: _np_positive(arrays[i]),
        ),
        "sqrt": (
            lambda i: q.sqrt_floats(fl[i]),
            lambda i: _np_sqrt(arrays[i]),
            lambda i: q.quaternion_sqrt(arrays[i]),
        ),
        "log": (
            lambda i: q.log_floats(fl[i]),
            lambda i: _np_log(arrays[i]),
            lambda i: q.quaternion_log(arrays[i]),
        ),
        "rotate": (
            lambda i: q.rotate_floats(fl[i], fv[i]),
            lambda i: _np_rotate(arrays[i], vectors[i]),
        ),
    }
    report: dict[str, Any] = {"calls": N}
    for name, (fast, slow, *api) in cases.items():
        f, s = _median_us(fast), _median_us(slow)
        entry = {"floats_us": round(f, 3), "numpy_us": round(s, 3), "ratio": round(s / f, 1)}
        if api:
            entry["array_api_us"] = round(_median_us(api[0]), 3)
        report[name] = entry
    report["machine"] = {
        "cpu": platform.processor() or platform.machine(),
        "cores": os.cpu_count(),
        "python": platform.python_version(),
        "numpy": np.__version__,
        "platform": platform.platform(),
    }
    print(json.dumps(report, indent=2))


if __name__ == "__main__":
    main()
