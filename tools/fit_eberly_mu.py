"""Fit the error-balancing factor (1 + mu_n) of Eberly's polynomial SLERP, n = 1..16.

Eberly ("A Fast and Accurate Algorithm for Computing SLERP", JGT 2011; revised 2018) writes
f(t, x) = sin(t*theta) / sin(theta), x = cos(theta) in [0, 1], as the power series
f = sum_i a_i(t) (x - 1)^i with a_0 = t, a_i = (u_i t^2 - v_i) a_{i-1}, u_i = 1/(i(2i+1)),
v_i = i/(2i+1). "n terms" counts the factors i = 1..n as Eberly's code does (a_0 .. a_n are
summed); scaling the last u, v by (1 + mu) balances the error over the domain. This script picks mu minimising the maximum of
|f_n - f| over a dense (t, x) grid in [0, 1]^2 (golden-section search on the convex-looking
max-error curve), and prints the table that `crates/barytex-interp/src/slerp/eberly.rs` embeds,
with the coefficient error each achieves. Run: python3 tools/fit_eberly_mu.py
"""
import numpy as np

T = np.linspace(0.0, 1.0, 401)[:, None]
X = np.linspace(0.0, 1.0, 801)[None, :]
THETA = np.arccos(X)
with np.errstate(invalid="ignore", divide="ignore"):
    EXACT = np.where(X < 1.0, np.sin(T * THETA) / np.sin(THETA), T * np.ones_like(X))


def approx(n, mu):
    y = X - 1.0
    acc = np.ones_like(T * X)
    for i in range(n, 0, -1):
        u, v = 1.0 / (i * (2 * i + 1)), i / (2 * i + 1)
        if i == n:
            u, v = u * (1 + mu), v * (1 + mu)
        acc = 1.0 + (u * T * T - v) * y * acc
    return T * acc


def max_err(n, mu):
    return float(np.max(np.abs(approx(n, mu) - EXACT)))


for n in range(1, 17):
    lo, hi = 0.0, 3.0
    g = (np.sqrt(5) - 1) / 2
    for _ in range(80):
        a, b = hi - g * (hi - lo), lo + g * (hi - lo)
        if max_err(n, a) < max_err(n, b):
            hi = b
        else:
            lo = a
    mu = (lo + hi) / 2
    print(f"n={n:2} one_plus_mu={1 + mu:.15f} err={max_err(n, mu):.3e} (plain truncation {max_err(n, 0.0):.3e})")
