#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The truth simulator's sensor noise, fitted to the real logs' residuals.

For each logged sensor (m_depth, m_pitch, m_roll, m_heading) on the glides of
a real Slocum log (m_depth_state 1 or 2, deeper than 3 m, rows less than 10 s
apart): the residual of a local quadratic through +-R rows (the flight's own
motion taken out), its standard deviation (corrected for the fit's own
smoothing: the residual of white noise through a 2R+1-point quadratic keeps
1 - 3/(2R+1) of the variance, about) and its lag-1 autocorrelation (an AR(1)
model's phi), and the quantization step (the smallest non-zero change).
The numbers in src/sensors.cpp came from:
    python3 tools/science/truth/fit_noise.py tests/data/real/comet-2016-174-05.csv \
        tests/data/real/comet-2019-222-02-154.csv
"""
import math
import sys

R = 3


def read(path):
    header, rows = None, []
    for line in open(path):
        if line.startswith('#'):
            continue
        fields = line.rstrip('\n').split(',')
        if header is None:
            header = fields
            continue
        rows.append(fields)
    return header, rows


def column(header, rows, name):
    k = header.index(name)
    return [float(r[k]) if r[k] not in ('', 'nan', 'NaN') else math.nan for r in rows]


def quadratic_residual(t, x, i):
    ts = [t[j] - t[i] for j in range(i - R, i + R + 1)]
    xs = [x[j] for j in range(i - R, i + R + 1)]
    # least squares a + b s + c s^2 (normal equations, 3x3)
    s = [[sum(p ** (a + b) for p in ts) for b in range(3)] for a in range(3)]
    r = [sum(v * p ** a for p, v in zip(ts, xs)) for a in range(3)]
    det = lambda m: (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                     + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    d = det(s)
    if abs(d) < 1e-12:
        return math.nan
    a0 = det([[r[0], s[0][1], s[0][2]], [r[1], s[1][1], s[1][2]], [r[2], s[2][1], s[2][2]]]) / d
    return x[i] - a0


def main(paths):
    for path in paths:
        header, rows = read(path)
        t = column(header, rows, 'm_present_time')
        depth = column(header, rows, 'm_depth')
        state = column(header, rows, 'm_depth_state')
        print(path)
        for name in ('m_depth', 'm_pitch', 'm_roll', 'm_heading'):
            x = column(header, rows, name)
            if name == 'm_heading':  # unwrap
                for i in range(1, len(x)):
                    if math.isfinite(x[i]) and math.isfinite(x[i - 1]):
                        x[i] -= 2 * math.pi * round((x[i] - x[i - 1]) / (2 * math.pi))
            res = []
            for i in range(R, len(x) - R):
                window = range(i - R, i + R + 1)
                if not all(state[j] in (1.0, 2.0) and depth[j] > 3.0 and math.isfinite(x[j]) for j in window):
                    continue
                if t[i + R] - t[i - R] > 10.0 * 2 * R:
                    continue
                res.append((i, quadratic_residual(t, x, i)))
            values = [v for _, v in res if math.isfinite(v)]
            if len(values) < 20:
                continue
            mean = sum(values) / len(values)
            var = sum((v - mean) ** 2 for v in values) / len(values)
            pairs = [(a[1] - mean, b[1] - mean) for a, b in zip(res, res[1:]) if b[0] == a[0] + 1]
            lag1 = sum(p * q for p, q in pairs) / len(pairs) / var if pairs and var > 0 else math.nan
            steps = sorted(abs(x[i] - x[i - 1]) for i in range(1, len(x))
                           if math.isfinite(x[i]) and math.isfinite(x[i - 1]) and x[i] != x[i - 1])
            sigma = math.sqrt(var / (1.0 - 3.0 / (2 * R + 1)))
            print('  %-10s n %5d  sigma %.3g  lag-1 corr %+.2f  smallest step %.3g  (cycle median %.2f s)' % (
                name, len(values), sigma, lag1, steps[0] if steps else math.nan,
                sorted(b - a for a, b in zip(t, t[1:]))[len(t) // 2]))


if __name__ == '__main__':
    main(sys.argv[1:])
