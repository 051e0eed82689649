"""Fit the three polynomials of the f32 SLERP's short-arc weight, used by
crates/barytex-interp/src/slerp/short_arc.rs:

    sin(s*theta)/sin(theta) = s * S(s^2 * A(y)) * B(y),   y = cos(theta) - 1 in [-1, 0],

with A(y) ~ theta^2 = (2 asin(sqrt(-y/2)))^2 and B(y) ~ theta/sin(theta), polynomials in y
(analytic on [-1, 0]; their nearest singularity is y = -2, i.e. theta = pi), and
S(z) ~ sin(sqrt(z))/sqrt(z) for z = (s*theta)^2 in [0, (pi/2)^2] (an even series, entire).
The identity is exact: sin(s*theta)/sin(theta) = s * sinc(s*theta) / sinc(theta).

Weighted least squares at Chebyshev nodes (A absolute, B and S relative), then the largest
error of each on a dense grid and of the whole weight over (s, y) in [0, 1] x [-1, 0], next to
that of Eberly's 16-factor series with its balanced last factor (tools/fit_eberly_mu.py), which
this replaces. Run: python3 tools/fit_slerp_weight.py [DEG_A DEG_B DEG_S] (default 10 10 4, the
degrees in use; A and B share one two-lane evaluation, so they cost the larger degree. Whole
weight error of other choices: 9 9 4: 1.9e-8, 8 9 4: 1.8e-8, 8 8 4: 8.5e-8, 9 10 5: 2.4e-9)."""
import sys

import numpy as np

DEG_A, DEG_B, DEG_S = (int(a) for a in sys.argv[1:4]) if len(sys.argv) > 3 else (10, 10, 4)


def chebyshev_nodes(lo, hi, n=4000):
    k = np.arange(n)
    return lo + (hi - lo) * (1 + np.cos((2 * k + 1) * np.pi / (2 * n))) / 2


def fit(x, f, deg, scale, c0):
    """Coefficients 0..=deg of a polynomial with the constant term fixed at c0 (the value at 0,
    so that the weight is exactly s at theta = 0), the rest by weighted least squares."""
    v = np.vstack([x**i for i in range(1, deg + 1)]).T / scale[:, None]
    c, *_ = np.linalg.lstsq(v, (f - c0) / scale, rcond=None)
    return np.concatenate([[c0], c])


def theta_of(y):
    # 2 asin(sqrt(-y/2)): well conditioned near y = 0, unlike acos(1 + y).
    return 2 * np.arcsin(np.sqrt(-y / 2))


def theta_over_sin(th):
    safe = np.where(th > 0, th, 1.0)
    return np.where(th > 0, safe / np.sin(safe), 1.0)


def sinc_sqrt(z):
    r = np.sqrt(np.where(z > 0, z, 1.0))
    return np.where(z > 0, np.sin(r) / r, 1.0)


def horner(c, x):
    return np.polyval(c[::-1], x)


y = chebyshev_nodes(-1.0, 0.0)
th = theta_of(y)
ca = fit(y, th**2, DEG_A, np.ones_like(y), 0.0)
cb = fit(y, theta_over_sin(th), DEG_B, theta_over_sin(th), 1.0)
z = chebyshev_nodes(0.0, (np.pi / 2) ** 2)
cs = fit(z, sinc_sqrt(z), DEG_S, sinc_sqrt(z), 1.0)

yg = np.linspace(-1.0, 0.0, 400001)
tg = theta_of(yg)
zg = np.linspace(0.0, (np.pi / 2) ** 2, 400001)
print(f"A: max abs error {np.max(np.abs(horner(ca, yg) - tg**2)):.2e}")
print(f"B: max rel error {np.max(np.abs(horner(cb, yg) / theta_over_sin(tg) - 1)):.2e}")
print(f"S: max rel error {np.max(np.abs(horner(cs, zg) / sinc_sqrt(zg) - 1)):.2e}")

# The whole weight against sin(s*theta)/sin(theta), and Eberly's series for comparison.
ys = np.linspace(-1.0, 0.0, 1001)[None, :]
ss = np.linspace(0.0, 1.0, 1001)[:, None]
ts = theta_of(ys)
exact = np.where(ts > 0, np.sin(ss * ts) / np.where(ts > 0, np.sin(ts), 1.0), ss)
ours = ss * horner(cs, ss * ss * horner(ca, ys)) * horner(cb, ys)
print(f"weight: max abs error {np.max(np.abs(ours - exact)):.2e}")
one_plus_mu = 1.916667572156612
f = np.ones_like(ours)
for i in range(16, 0, -1):
    u, v = 1 / (i * (2 * i + 1)), i / (2 * i + 1)
    if i == 16:
        u, v = u * one_plus_mu, v * one_plus_mu
    f = 1 + (u * ss * ss - v) * ys * f
print(f"Eberly, 16 factors: max abs error {np.max(np.abs(ss * f - exact)):.2e}")

for name, c in (("THETA2", ca), ("THETA_OVER_SIN", cb), ("SINC", cs)):
    print(f"const {name}: [f64; {len(c)}] = [")
    for v in c:
        print(f"    {float(v)!r},")
    print("];")
