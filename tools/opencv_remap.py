#!/usr/bin/env python3
"""OpenCV's remap (INTER_LINEAR, and NEAREST, CUBIC) on the warp of benches/benches/remap.rs,
single-threaded, timed beside `cargo bench -p barytex-benches --bench remap`, with its error
against an exact f64 bilinear on the same coordinates.

Run: python3 tools/opencv_remap.py

On first use it creates a virtual environment with the pinned versions of
tools/opencv/requirements.txt (OpenCV's headless wheel and numpy) under
~/.cache/barytex/opencv-venv and re-runs itself there, so the OpenCV side is the same build on
every machine.
"""
import time
from pathlib import Path

from pinned_venv import ensure_venv

HERE = Path(__file__).resolve().parent
VENV = Path.home() / ".cache" / "barytex" / "opencv-venv"


ensure_venv(VENV, __file__, ["-r", str(HERE / "opencv" / "requirements.txt")],
            "opencv-python-headless, numpy")

import cv2  # noqa: E402  (after the environment is in place)
import numpy as np  # noqa: E402

SIDE = 2048


def source():
    y, x = np.mgrid[0:SIDE, 0:SIDE].astype(np.int64)
    img = np.zeros((SIDE, SIDE, 4), np.uint8)
    img[..., 0] = (x * 255 // SIDE).astype(np.uint8)
    img[..., 1] = (y * 255 // SIDE).astype(np.uint8)
    img[..., 2] = ((x ^ y) & 0xFF).astype(np.uint8)
    img[..., 3] = 255
    return img


def warp():
    """Pixel-space maps (OpenCV convention: pixel centres at integers), the same warp as the
    Rust bench's texture coordinates: u·n − ½ = x + dx."""
    y, x = np.mgrid[0:SIDE, 0:SIDE].astype(np.float32)
    n = np.float32(SIDE)
    dx = 20.0 * np.sin(np.float32(2 * np.pi) * 3.0 * y / n)
    dy = 20.0 * np.cos(np.float32(2 * np.pi) * 2.0 * x / n)
    return (x + dx).astype(np.float32), (y + dy).astype(np.float32)


def exact_bilinear(img, mx, my):
    x = mx.astype(np.float64)
    y = my.astype(np.float64)
    x0, y0 = np.floor(x), np.floor(y)
    fx, fy = (x - x0)[..., None], (y - y0)[..., None]
    x0, y0 = x0.astype(np.int64), y0.astype(np.int64)
    c = lambda i, j: img[np.clip(j, 0, SIDE - 1), np.clip(i, 0, SIDE - 1)].astype(np.float64)
    top = c(x0, y0) * (1 - fx) + c(x0 + 1, y0) * fx
    bottom = c(x0, y0 + 1) * (1 - fx) + c(x0 + 1, y0 + 1) * fx
    return top * (1 - fy) + bottom * fy


def main():
    cv2.setNumThreads(1)
    print(f"OpenCV {cv2.__version__}, numpy {np.__version__}")
    img, (mx, my) = source(), warp()
    rows = slice(0, SIDE, 7)
    want = exact_bilinear(img, mx[rows], my[rows])
    for name, flag in [("nearest", cv2.INTER_NEAREST), ("linear", cv2.INTER_LINEAR), ("cubic", cv2.INTER_CUBIC)]:
        out = cv2.remap(img, mx, my, flag, borderMode=cv2.BORDER_REPLICATE)
        times = []
        for _ in range(11):
            t = time.perf_counter()
            cv2.remap(img, mx, my, flag, borderMode=cv2.BORDER_REPLICATE)
            times.append(time.perf_counter() - t)
        median = sorted(times)[len(times) // 2]
        err = np.abs(out[rows].astype(np.float64) - want).max() if flag == cv2.INTER_LINEAR else float("nan")
        print(f"opencv remap {name}: median {median * 1e3:.2f} ms = {median / SIDE / SIDE * 1e9:.2f} ns/pixel, "
              f"max error vs exact bilinear {err:.3f} steps")


if __name__ == "__main__":
    main()
