# SPDX-License-Identifier: Apache-2.0
"""The varied parameters of campaign run i, from (campaign seed, i) alone.

Every number comes from a counter-based generator: splitmix64's mixer of
(seed, run, parameter-name hash, draw), in 64-bit integer arithmetic that is
the same in every Python on every machine, so a run's parameters do not
depend on which shard or host draws them, nor on the other runs. Uniform
values use only integer and IEEE arithmetic; normal ones Box-Muller
(sqrt, log, cos of the C library, as sil/include/glider/sil/portable_random.hpp).
Python's own random and numpy's generators are not used: their streams are
not a documented, stable function of (seed, i)."""

import math

MASK = (1 << 64) - 1
GOLDEN = 0x9E3779B97F4A7C15
TWO_TO_MINUS_53 = 1.0 / 9007199254740992.0
MAX_REDRAWS = 1000  # bounded rejection for truncated normals


class SpecError(Exception):
    pass


def mix64(z):
    """splitmix64's finaliser: a bijection of 64-bit words with full avalanche."""
    z = (z + GOLDEN) & MASK
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return z ^ (z >> 31)


def name_stream(name):
    """FNV-1a 64 of a parameter name: adding a parameter leaves the others' draws alone."""
    h = 0xCBF29CE484222325
    for byte in name.encode("utf-8"):
        h = ((h ^ byte) * 0x100000001B3) & MASK
    return h


def word(seed, run, stream, draw):
    return mix64(mix64(mix64(mix64(seed) ^ run) ^ stream) ^ draw)


def uniform01(seed, run, stream, draw):
    return (word(seed, run, stream, draw) >> 11) * TWO_TO_MINUS_53


def run_seed(seed, run):
    """The SIL's noise seed of run `run` (glider-sil --seed), < 2^63."""
    return word(seed, run, name_stream("sil.seed"), 0) >> 1


def _number(spec, key, name):
    value = spec.get(key)
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SpecError(f"[vary] {name}: {key} = {value!r}: must be a finite number")
    return float(value)


def check_spec(name, spec):
    """Refuses a parameter description that cannot be sampled; returns its kind."""
    if not isinstance(spec, dict):
        return "fixed"
    kinds = [k for k in ("distribution", "grid", "list", "choice") if k in spec]
    if len(kinds) != 1:
        raise SpecError(f"[vary] {name} = {spec!r}: give one of distribution = \"uniform\"|\"normal\", "
                        "grid = [...], list = [...], choice = [...]")
    kind = kinds[0]
    if kind in ("grid", "list", "choice"):
        values = spec[kind]
        if not isinstance(values, list) or not values:
            raise SpecError(f"[vary] {name}: {kind} must be a non-empty list")
        extra = set(spec) - {kind}
    elif spec["distribution"] == "uniform":
        lo, hi = _number(spec, "min", name), _number(spec, "max", name)
        if not lo < hi:
            raise SpecError(f"[vary] {name}: uniform needs min < max (got {lo}, {hi})")
        extra = set(spec) - {"distribution", "min", "max"}
        kind = "uniform"
    elif spec["distribution"] == "normal":
        _number(spec, "mean", name)
        if not _number(spec, "sigma", name) > 0.0:
            raise SpecError(f"[vary] {name}: normal needs sigma > 0")
        lo = _number(spec, "min", name) if "min" in spec else -math.inf
        hi = _number(spec, "max", name) if "max" in spec else math.inf
        if not lo < hi:
            raise SpecError(f"[vary] {name}: normal needs min < max")
        extra = set(spec) - {"distribution", "mean", "sigma", "min", "max"}
        kind = "normal"
    else:
        raise SpecError(f"[vary] {name}: distribution = {spec['distribution']!r}: allowed uniform, normal")
    if extra:
        raise SpecError(f"[vary] {name}: unknown key(s) {', '.join(sorted(extra))}")
    return kind


def grid_size(vary):
    size = 1
    for spec in vary.values():
        if isinstance(spec, dict) and "grid" in spec:
            size *= len(spec["grid"])
    return size


def parameters(vary, seed, run):
    """{name: value} of run `run`. Grid parameters take the cell run mod
    (product of grid sizes), the last one in the file varying fastest; list
    parameters take element run mod len; the rest are drawn."""
    out = {}
    cell = run % grid_size(vary)
    strides = {}
    stride = 1
    for name in reversed(list(vary)):
        spec = vary[name]
        if isinstance(spec, dict) and "grid" in spec:
            strides[name] = stride
            stride *= len(spec["grid"])
    for name, spec in vary.items():
        kind = check_spec(name, spec)
        stream = name_stream(name)
        if kind == "fixed":
            out[name] = spec
        elif kind == "grid":
            out[name] = spec["grid"][(cell // strides[name]) % len(spec["grid"])]
        elif kind == "list":
            out[name] = spec["list"][run % len(spec["list"])]
        elif kind == "choice":
            out[name] = spec["choice"][word(seed, run, stream, 0) % len(spec["choice"])]
        elif kind == "uniform":
            u = uniform01(seed, run, stream, 0)
            out[name] = spec["min"] + (spec["max"] - spec["min"]) * u
        else:
            out[name] = _truncated_normal(spec, seed, run, stream, name)
    return out


def _truncated_normal(spec, seed, run, stream, name):
    lo, hi = spec.get("min", -math.inf), spec.get("max", math.inf)
    for attempt in range(MAX_REDRAWS):
        u1 = ((word(seed, run, stream, 2 * attempt) >> 11) + 0.5) * TWO_TO_MINUS_53  # (0, 1): log finite
        u2 = uniform01(seed, run, stream, 2 * attempt + 1)
        value = spec["mean"] + spec["sigma"] * math.sqrt(-2.0 * math.log(u1)) * math.cos(2.0 * math.pi * u2)
        if lo <= value <= hi:
            return value
    raise SpecError(f"[vary] {name}: no draw inside [{lo}, {hi}] in {MAX_REDRAWS} tries (bounds far from mean?)")
