#!/usr/bin/env python3
"""Every speed bar of docs/report/peers.md measured in one sitting, each beside its peer or
same-result kernel, with the verdict per bar.

    python3 tools/speed_bars.py [--rounds R] [--frames N] [--skip-llvmpipe] [--skip-opencv]
                                [--markdown FILE]

It builds what it runs (`cargo bench -p barytex-benches --no-run` and `cargo build --release -p
barytex`: about 20 minutes from scratch on 2 cores, seconds when fresh), then, R rounds of each:

- the criterion benches, filtered to the bars' functions, `--output-format bencher`: lookups
  (`TextureSampler` ÷ the minimal kernel kept in the bench), the mip chain (linear light ÷
  fast_image_resize `Box`), quaternion SLERP (exact ÷ glam `Quat::slerp`, corrected nlerp over
  slices ÷ glam's nlerp), the remap (barytex's side of the OpenCV comparison), raster-only
  (euc ÷ barytex, clear + draw and `draw_cleared`, torus and random triangles);
- `tools/opencv_remap.py` (OpenCV `remap` INTER_LINEAR, 1 thread, in its pinned environment);
- then once `tools/llvmpipe_frame.py --rounds R --frames N` (the unlit frame beside Mesa's
  llvmpipe at 1 and 2 threads, and barytex's 2-thread scaling from the same frames).

Each ratio is the median of the rounds' ratios (each round's two sides measured back to back),
with the range when R > 1. Ratios move with the machine (2 shared cores: absolute times move by
a third between runs, ratios much less); docs/report/peers.md holds the history and the profiles.
Criterion's figures are its point estimates (the bencher format's), not medians.
"""

import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent

# (bench target, filter regex): the functions the bars compare, nothing else.
BENCHES = [
    ("lookup", r"^lookup_srgba8_repeat_[a-z_]+/(barytex_texture_sampler|minimal_kernel)$"),
    ("remap", r"^remap_2048_rgba8_bilinear/barytex_remap_bilinear_rgba8$"),
    ("mip", r"^mip_chain_4096_rgba8/(barytex_linear_light|fast_image_resize_box)$"),
    ("slerp", r"^quat_slerp/(barytex_slerp|glam_Quat_slerp|barytex_nlerp-corrected_slices"
              r"|glam_Quat_lerp_nlerp)$"),
    ("raster", r"^raster_only_1024_[a-z0-9_]+/(barytex_rgba8|barytex_rgba8_draw_cleared|euc_u32)$"),
]

LOOKUPS = ["nearest", "bilinear", "trilinear", "trilinear_varying"]
RASTER_SCENES = ["torus_6k", "random_10k"]
BENCHER = re.compile(r"^test (\S+) \.\.\. bench:\s+([\d,]+) ns/iter")
OPENCV_LINEAR = re.compile(r"^opencv remap linear: median ([\d.]+) ms")


def run(cmd, **kw):
    print("$ " + " ".join(str(c) for c in cmd), file=sys.stderr, flush=True)
    return subprocess.run(cmd, check=True, text=True, **kw)


def bench_executables():
    """Builds the benches and returns {target name: executable}."""
    out = run(["cargo", "bench", "-p", "barytex-benches", "--no-run", "--message-format=json"],
              cwd=ROOT, stdout=subprocess.PIPE).stdout
    found = {}
    for line in out.splitlines():
        try:
            msg = json.loads(line)
        except json.JSONDecodeError:
            continue
        target = msg.get("target", {})
        if msg.get("reason") == "compiler-artifact" and "bench" in target.get("kind", []) \
                and msg.get("executable"):
            found[target["name"]] = msg["executable"]
    return found


def criterion(executable, pattern):
    """{function id: ns per iteration} for the functions matching `pattern`."""
    out = run([executable, "--bench", pattern, "--output-format", "bencher"], cwd=ROOT,
              stdout=subprocess.PIPE, stderr=subprocess.DEVNULL).stdout
    times = {}
    for line in out.splitlines():
        m = BENCHER.match(line.strip())
        if m:
            times[m.group(1)] = float(m.group(2).replace(",", ""))
    return times


def opencv_linear_ms():
    out = run([sys.executable, str(HERE / "opencv_remap.py")], cwd=ROOT,
              stdout=subprocess.PIPE).stdout
    for line in out.splitlines():
        m = OPENCV_LINEAR.match(line.strip())
        if m:
            return float(m.group(1))
    raise SystemExit("tools/opencv_remap.py printed no INTER_LINEAR median")


def ratio_rows(rounds):
    """[(bar name, [ratio per round], comparison, bar)] from the rounds' criterion (and OpenCV)
    figures."""
    def per_round(f):
        out = []
        for r in rounds:
            try:
                out.append(f(r))
            except KeyError:
                pass
        return out

    rows = []
    # A round without OpenCV (skipped, or its environment could not be made) has no remap ratio.
    rows.append(("bilinear remap 2048² RGBA8, 1 thread: barytex ÷ OpenCV `remap` INTER_LINEAR",
                 per_round(lambda r: r["remap_2048_rgba8_bilinear/barytex_remap_bilinear_rgba8"]
                           / 1e6 / r["opencv_ms"]), "<=", 1.0))
    for name in LOOKUPS:
        g = f"lookup_srgba8_repeat_{name}"
        rows.append((f"lookups, {name}: `TextureSampler` ÷ minimal kernel",
                     per_round(lambda r: r[f"{g}/barytex_texture_sampler"] / r[f"{g}/minimal_kernel"]),
                     "<=", 1.0))
    g = "mip_chain_4096_rgba8"
    rows.append(("mip chain 4096² linear light ÷ fast_image_resize `Box`",
                 per_round(lambda r: r[f"{g}/barytex_linear_light"] / r[f"{g}/fast_image_resize_box"]),
                 "<=", 1.0))
    g = "quat_slerp"
    rows.append(("exact quaternion slerp ÷ glam `Quat::slerp`",
                 per_round(lambda r: r[f"{g}/barytex_slerp"] / r[f"{g}/glam_Quat_slerp"]), "<=", 1.0))
    rows.append(("corrected nlerp (slices) ÷ glam nlerp",
                 per_round(lambda r: r[f"{g}/barytex_nlerp-corrected_slices"] / r[f"{g}/glam_Quat_lerp_nlerp"]),
                 "<=", 1.5))
    for scene in RASTER_SCENES:
        g = f"raster_only_1024_{scene}"
        rows.append((f"raster-only {scene}, 1 thread: euc ÷ barytex (clear + draw)",
                     per_round(lambda r: r[f"{g}/euc_u32"] / r[f"{g}/barytex_rgba8"]), ">=", 4.0))
        rows.append((f"raster-only {scene}, 1 thread: euc ÷ barytex (`draw_cleared`)",
                     per_round(lambda r: r[f"{g}/euc_u32"] / r[f"{g}/barytex_rgba8_draw_cleared"]),
                     ">=", 4.0))
    return rows


def llvmpipe_rows(report):
    rows = []
    by = {(r["scene"], r["threads"]): r for r in report["rows"]}
    for (scene, threads), r in sorted(by.items()):
        lo, hi = r["ratio_range"]
        rows.append((f"unlit trilinear frame {scene}, {threads} thread(s): barytex ÷ llvmpipe",
                     [r["ratio"]], "<=", 1.0, (lo, hi)))
    for scene in sorted({s for s, _ in by}):
        if (scene, 1) in by and (scene, 2) in by:
            rows.append((f"barytex 2 threads vs 1, {scene} unlit frame (frame at 1 ÷ at 2)",
                         [by[scene, 1]["bx"] / by[scene, 2]["bx"]], ">=", 1.8, None))
    return rows


def unmeasured_frame_rows():
    """The frame and scaling bars of the llvmpipe tool's default scenes, not measured."""
    rows = []
    for scene in ("Avocado", "Suzanne"):
        for threads in (1, 2):
            rows.append((f"unlit trilinear frame {scene}, {threads} thread(s): barytex ÷ llvmpipe",
                         [], "<=", 1.0))
        rows.append((f"barytex 2 threads vs 1, {scene} unlit frame (frame at 1 ÷ at 2)", [], ">=", 1.8))
    return rows


def verdict(values, op, bar):
    if not values:
        return "not measured"
    m = statistics.median(values)
    return "met" if (m <= bar if op == "<=" else m >= bar) else "**not met**"


def table(rows):
    lines = ["| bar | ratio (median of rounds, range) | bar | verdict |", "|---|---|---|---|"]
    for row in rows:
        name, values, op, bar = row[:4]
        spread = row[4] if len(row) > 4 else (min(values), max(values)) if len(values) > 1 else None
        text = f"{statistics.median(values):.2f}×" if values else "—"
        if spread and spread[1] > spread[0]:
            text += f" ({spread[0]:.2f}–{spread[1]:.2f})"
        sign = "≤" if op == "<=" else "≥"
        lines.append(f"| {name} | {text} | {sign} {bar:g}× | {verdict(values, op, bar)} |")
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rounds", type=int, default=1,
                    help="criterion and OpenCV rounds, and llvmpipe rounds (default %(default)s)")
    ap.add_argument("--frames", type=int, default=10, help="llvmpipe tool's frames (default %(default)s)")
    ap.add_argument("--skip-llvmpipe", action="store_true", help="no frame comparison (no Mesa here)")
    ap.add_argument("--skip-opencv", action="store_true", help="no OpenCV remap (no PyPI here)")
    ap.add_argument("--markdown", help="also write the table and the commands to this file")
    args = ap.parse_args()
    if args.rounds < 1 or args.frames < 1:
        ap.error("--rounds and --frames must be at least 1")

    started = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    load_before = os.getloadavg()[0]
    executables = bench_executables()
    missing = [b for b, _ in BENCHES if b not in executables]
    if missing:
        raise SystemExit(f"cargo built no bench executable for {missing}")
    if not args.skip_llvmpipe:
        run(["cargo", "build", "--release", "-p", "barytex"], cwd=ROOT)

    rounds = []
    opencv = not args.skip_opencv
    for k in range(args.rounds):
        print(f"round {k + 1}/{args.rounds}", file=sys.stderr, flush=True)
        figures = {}
        for target, pattern in BENCHES:
            figures.update(criterion(executables[target], pattern))
        if opencv:
            try:
                figures["opencv_ms"] = opencv_linear_ms()
            except (subprocess.CalledProcessError, OSError, SystemExit) as e:
                print(f"OpenCV remap not measured: {e}", file=sys.stderr)
                opencv = False
        rounds.append(figures)
    rows = ratio_rows(rounds)

    frames_measured = False
    if not args.skip_llvmpipe:
        with tempfile.TemporaryDirectory() as tmp:
            report = Path(tmp) / "llvmpipe.json"
            try:
                run([sys.executable, str(HERE / "llvmpipe_frame.py"), "--frames", str(args.frames),
                     "--rounds", str(args.rounds), "--json", str(report)], cwd=ROOT)
                rows += llvmpipe_rows(json.loads(report.read_text()))
                frames_measured = True
            except (subprocess.CalledProcessError, OSError, ValueError) as e:
                # No Mesa or no fixtures here: the other bars still stand.
                print(f"llvmpipe frames not measured: {e}", file=sys.stderr)

    if not frames_measured:
        rows += unmeasured_frame_rows()
    load = os.getloadavg()
    lines = table(rows)
    header = (f"Speed bars, {started} to {time.strftime('%H:%M UTC', time.gmtime())}, {args.rounds} "
              f"round(s), load average {load_before:.1f} before and {load[0]:.1f} at the end on "
              f"{os.cpu_count()} CPUs "
              f"(`python3 tools/speed_bars.py {' '.join(sys.argv[1:])}`)".replace(" `)", "`)"))
    print()
    print(header)
    print()
    print("\n".join(lines))
    met = sum(1 for row in rows if verdict(row[1], row[2], row[3]) == "met")
    print(f"\n{met} of {len(rows)} bars met")
    print("\nround 1's figures (criterion ns/iter; OpenCV ms):")
    for k, v in sorted(rounds[0].items()):
        print(f"  {k}: {v:,.0f}" if v > 100 else f"  {k}: {v:.2f}")
    if args.markdown:
        Path(args.markdown).write_text(header + "\n\n" + "\n".join(lines) + f"\n\n{met} of {len(rows)} bars met\n")
        print(f"wrote {args.markdown}")


if __name__ == "__main__":
    main()
