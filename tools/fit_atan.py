"""Fit the odd polynomial for atan(u), |u| <= tan(pi/8), used by
crates/barytex-interp/src/slerp/trig.rs: atan(u) ~ u * P(u^2), P of degree DEG, by least squares
on relative error at Chebyshev nodes (close to minimax), then report the max relative error on a
dense grid. Run: python3 tools/fit_atan.py"""
import numpy as np

U_MAX = np.tan(np.pi / 8)
DEG = 5  # P(z) coefficients c0..c5, atan of degree 11
k = np.arange(4000)
u = U_MAX * np.cos((2 * k + 1) * np.pi / (2 * len(k)))
u = u[np.abs(u) > 1e-6]
z = u * u
target = np.arctan(u) / u
A = np.vstack([z**i for i in range(DEG + 1)]).T
coef, *_ = np.linalg.lstsq(A, target, rcond=None)
grid = np.linspace(1e-9, U_MAX, 200001)
approx = grid * np.polyval(coef[::-1], grid * grid)
rel = np.max(np.abs(approx - np.arctan(grid)) / np.arctan(grid))
for c in coef:
    print(f"    {c:.17e},")
print(f"max relative error {rel:.3e}")
