"""Fit sin(r)/r and cos(r) as polynomials in r^2 for |r| <= pi/2, used by
crates/barytex-interp/src/slerp/trig.rs (sin(phi) = cos(phi - pi/2), cos(phi) = -sin(phi - pi/2)
for phi in [0, pi]): least squares at Chebyshev nodes, max abs error on a dense grid.
Run: python3 tools/fit_sin_cos.py"""
import numpy as np

R = np.pi / 2
k = np.arange(3000)
r = R * np.cos((2 * k + 1) * np.pi / (2 * len(k)))
r = r[np.abs(r) > 1e-6]
z = r * r
N_SIN, N_COS = 6, 6
cs, *_ = np.linalg.lstsq(np.vstack([z**i for i in range(N_SIN)]).T, np.sin(r) / r, rcond=None)
cc, *_ = np.linalg.lstsq(np.vstack([z**i for i in range(N_COS)]).T, np.cos(r), rcond=None)
g = np.linspace(-R, R, 400001)
es = np.max(np.abs(g * np.polyval(cs[::-1], g * g) - np.sin(g)))
ec = np.max(np.abs(np.polyval(cc[::-1], g * g) - np.cos(g)))
print("SIN", [f"{c:.17e}" for c in cs], f"max abs error {es:.2e}")
print("COS", [f"{c:.17e}" for c in cc], f"max abs error {ec:.2e}")
