//! Replays every saved fuzz input of `fuzz/regressions/<target>/` through the same invariant
//! checks as the fuzz target, so a crash found once stays fixed without needing `cargo fuzz`.
//!
//! The main workspace cannot depend on the fuzz crate (it has its own workspace and needs
//! libFuzzer), so the byte layout of each target is decoded here by a copy of the target's
//! `Input::decode` and `Input::geometry`. The layouts are documented at the top of
//! `fuzz/fuzz_targets/<target>.rs`; keep both copies in step (the `layout_*` tests below pin the
//! decoding of a hand-written input).
//!
//! Every file of the directory except `README.md` is an input. A missing or empty directory fails
//! the test, so a renamed target or a lost seed is noticed.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use barytex_testkit::invariants::{
    check_barycentric_2d, check_inverse_bilinear_2d, check_orient2d,
};
use barytex_testkit::strategies::step_ulps;
use glam::Vec2;

/// The little-endian `u32` word `w` of `bytes`, missing bytes reading as zero.
fn word(bytes: &[u8], w: usize) -> u32 {
    let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
    u32::from_le_bytes(core::array::from_fn(|k| byte(4 * w + k)))
}

/// Point `i` of `bytes`: words `2i` and `2i + 1` as f32 bit patterns.
fn point(bytes: &[u8], i: usize) -> Vec2 {
    Vec2::new(
        f32::from_bits(word(bytes, 2 * i)),
        f32::from_bits(word(bytes, 2 * i + 1)),
    )
}

/// The mode byte at `offset` split into `(kind, k)`: `kind = m & 7`, `k = (m >> 3) − 16`.
fn mode(bytes: &[u8], offset: usize) -> (u8, i32) {
    let m = bytes.get(offset).copied().unwrap_or(0);
    (m & 7, i32::from(m >> 3) - 16)
}

/// `fuzz_targets/orient_barycentric.rs`: 8 words p a b c, mode byte at 32. Returns `(p, tri)`.
fn orient_barycentric_geometry(bytes: &[u8]) -> (Vec2, [Vec2; 3]) {
    let (mut p, a, mut b, mut c) = (
        point(bytes, 0),
        point(bytes, 1),
        point(bytes, 2),
        point(bytes, 3),
    );
    let (kind, k) = mode(bytes, 32);
    match kind {
        1 => p = Vec2::new(step_ulps(a.x, k), a.y),
        2 => {
            let m = a + (b - a) * 0.5;
            p = Vec2::new(m.x, step_ulps(m.y, k));
        }
        3 => {
            let m = a + (b - a) * 0.5;
            c = Vec2::new(m.x, step_ulps(m.y, k));
        }
        4 => b = Vec2::new(step_ulps(a.x, k), step_ulps(a.y, k)),
        _ => {}
    }
    (p, [a, b, c])
}

fn check_orient_barycentric(bytes: &[u8]) -> Result<(), String> {
    let (p, [a, b, c]) = orient_barycentric_geometry(bytes);
    for (q, r, s) in [(a, b, c), (b, c, p), (c, a, p), (a, b, p)] {
        check_orient2d(q, r, s)?;
    }
    check_barycentric_2d(p, [a, b, c])
}

/// `fuzz_targets/inverse_bilinear.rs`: 10 words p x y z w, mode byte at 40. Returns `(p, quad)`.
fn inverse_bilinear_geometry(bytes: &[u8]) -> (Vec2, [Vec2; 4]) {
    let mut p = point(bytes, 0);
    let mut quad = [
        point(bytes, 1),
        point(bytes, 2),
        point(bytes, 3),
        point(bytes, 4),
    ];
    let [x, y, _, w] = quad;
    let (kind, k) = mode(bytes, 40);
    match kind {
        1 => p = Vec2::new(step_ulps(x.x, k), x.y),
        2 => {
            let m = x + (y - x) * 0.5;
            p = Vec2::new(m.x, step_ulps(m.y, k));
        }
        3 => {
            let z = y + w - x;
            quad[2] = Vec2::new(step_ulps(z.x, k), z.y);
        }
        4 => {
            let unit = |bits: u32| (bits >> 8) as f32 * (1.0 / 16_777_216.0);
            let q = barytex_interp::bilinear(quad, unit(word(bytes, 0)), unit(word(bytes, 1)));
            p = Vec2::new(step_ulps(q.x, k), q.y);
        }
        _ => {}
    }
    (p, quad)
}

fn check_inverse_bilinear(bytes: &[u8]) -> Result<(), String> {
    let (p, quad) = inverse_bilinear_geometry(bytes);
    check_inverse_bilinear_2d(p, quad)
}

fn regressions_dir(target: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../fuzz/regressions")
        .join(target)
}

/// Runs `check` on every input file of the target's directory; fails listing every violation.
fn replay(target: &str, check: fn(&[u8]) -> Result<(), String>) {
    let dir = regressions_dir(target);
    let entries =
        std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()));
    let mut files: Vec<PathBuf> = entries
        .map(|entry| entry.expect("directory entry").path())
        .filter(|path| path.is_file() && path.file_name().is_some_and(|n| n != "README.md"))
        .collect();
    files.sort();
    assert!(
        !files.is_empty(),
        "no fuzz inputs in {}: every target keeps at least one seed",
        dir.display()
    );
    let mut failures = String::new();
    for file in &files {
        let bytes = std::fs::read(file).expect("readable input");
        if let Err(message) = check(&bytes) {
            let name = file.file_name().unwrap_or_default().to_string_lossy();
            let _ = writeln!(failures, "fuzz/regressions/{target}/{name}: {message}");
        }
    }
    assert!(
        failures.is_empty(),
        "{target}: invariants violated by saved inputs (of {} replayed):\n{failures}",
        files.len()
    );
    println!("{target}: {} inputs replayed", files.len());
}

#[test]
fn orient_barycentric_regressions() {
    replay("orient_barycentric", check_orient_barycentric);
}

#[test]
fn inverse_bilinear_regressions() {
    replay("inverse_bilinear", check_inverse_bilinear);
}

fn le_words(words: &[u32], mode: Option<u8>) -> Vec<u8> {
    let mut bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
    bytes.extend(mode);
    bytes
}

#[test]
fn layout_orient_barycentric() {
    let bits = |x: f32| x.to_bits();
    let words = [1.0, 0.0, 0.0, 0.0, 2.0, 3.0, 3.0, 1.0].map(bits);
    let (p, tri) = orient_barycentric_geometry(&le_words(&words, None));
    assert_eq!(p, Vec2::new(1.0, 0.0));
    assert_eq!(tri, [Vec2::ZERO, Vec2::new(2.0, 3.0), Vec2::new(3.0, 1.0)]);
    // Short input: missing bytes read as zero.
    assert_eq!(
        orient_barycentric_geometry(&[]),
        (Vec2::ZERO, [Vec2::ZERO; 3])
    );
    // Mode 3 with k = +1: c is the midpoint of ab, one ulp up in y.
    let (_, [_, _, c]) = orient_barycentric_geometry(&le_words(&words, Some((17 << 3) | 3)));
    assert_eq!(c, Vec2::new(1.0, 1.5f32.next_up()));
}

#[test]
fn layout_inverse_bilinear() {
    let bits = |x: f32| x.to_bits();
    let words = [0.5, 0.25, 0.0, 0.0, 4.0, 0.0, 5.0, 3.0, 0.0, 2.0].map(bits);
    let quad = [
        Vec2::ZERO,
        Vec2::new(4.0, 0.0),
        Vec2::new(5.0, 3.0),
        Vec2::new(0.0, 2.0),
    ];
    assert_eq!(
        inverse_bilinear_geometry(&le_words(&words, None)),
        (Vec2::new(0.5, 0.25), quad)
    );
    // Mode 1 with k = −1: p is corner x, one ulp down in x.
    let (p, _) = inverse_bilinear_geometry(&le_words(&words, Some((15 << 3) | 1)));
    assert_eq!(p, Vec2::new(-f32::from_bits(1), 0.0));
}
