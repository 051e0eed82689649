//! Fuzz `orient2d`, `locate_2d` and `barycentric_2d` against barytex-testkit's exact-rational
//! invariants (`check_orient2d`, `check_barycentric_2d`).
//!
//! # Input layout
//!
//! Kept byte-simple so that `tests/tests/fuzz_regressions.rs` (main workspace, which cannot depend
//! on this crate) decodes a saved input identically with its own copy of [`Input::decode`]:
//!
//! | bytes   | meaning                                                             |
//! |---------|---------------------------------------------------------------------|
//! | 0..32   | 8 little-endian `u32` f32 bit patterns: p.x p.y a.x a.y b.x b.y c.x c.y |
//! | 32      | mode byte                                                           |
//! | 33..    | ignored                                                             |
//!
//! Missing bytes read as zero, so every input is valid. Bit patterns go through `f32::from_bits`:
//! NaNs, infinities, subnormals and ±0 are all reachable.
//!
//! The mode byte `m` lets the fuzzer reach degenerate geometry that random bits almost never hit:
//! `kind = m & 7`, `k = (m >> 3) as i32 - 16` (ulps, −16..=15), `step` = `testkit::step_ulps`.
//!
//! | kind   | geometry                                                              |
//! |--------|-----------------------------------------------------------------------|
//! | 0, 5–7 | raw                                                                   |
//! | 1      | `p = a`, then `p.x` stepped by `k` ulps (on / next to a vertex)       |
//! | 2      | `p = a + (b − a)·0.5`, then `p.y` stepped by `k` ulps (near edge `c`) |
//! | 3      | `c = a + (b − a)·0.5`, then `c.y` stepped by `k` ulps (sliver)        |
//! | 4      | `b = a` with both coordinates stepped by `k` ulps (tiny edge)         |
//!
//! # Checks
//!
//! `check_orient2d` on the triangle `(a, b, c)` and on the three sub-triangles `(b, c, p)`,
//! `(c, a, p)`, `(a, b, p)` whose signs `barycentric_2d` classifies with; then
//! `check_barycentric_2d(p, [a, b, c])`. Any `Err` panics with its message.
//!
//! `Debug` prints the failing checks as a Rust block that a regression test can paste; `cargo fuzz
//! fmt orient_barycentric <artifact>` shows it for a crash file.
#![no_main]

use std::fmt;

use arbitrary::{Arbitrary, Unstructured};
use barytex_testkit::invariants::{check_barycentric_2d, check_orient2d};
use barytex_testkit::strategies::step_ulps;
use glam::Vec2;
use libfuzzer_sys::fuzz_target;

/// Number of bytes read: 8 words and the mode byte.
const LEN: usize = 8 * 4 + 1;

/// One fuzz input: raw words and mode, decoded exactly as documented above.
#[derive(Clone, Copy, PartialEq)]
struct Input {
    words: [u32; 8],
    mode: u8,
}

impl Input {
    fn decode(bytes: &[u8]) -> Self {
        let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
        let words =
            core::array::from_fn(|w| u32::from_le_bytes(core::array::from_fn(|k| byte(4 * w + k))));
        Self {
            words,
            mode: byte(32),
        }
    }

    /// `(p, [a, b, c])` after the mode is applied.
    fn geometry(&self) -> (Vec2, [Vec2; 3]) {
        let v = |i: usize| {
            Vec2::new(
                f32::from_bits(self.words[2 * i]),
                f32::from_bits(self.words[2 * i + 1]),
            )
        };
        let (mut p, a, mut b, mut c) = (v(0), v(1), v(2), v(3));
        let k = i32::from(self.mode >> 3) - 16;
        match self.mode & 7 {
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

    fn check(&self) -> Result<(), String> {
        let (p, [a, b, c]) = self.geometry();
        for (q, r, s) in [(a, b, c), (b, c, p), (c, a, p), (a, b, p)] {
            check_orient2d(q, r, s)?;
        }
        check_barycentric_2d(p, [a, b, c])
    }
}

impl<'a> Arbitrary<'a> for Input {
    fn arbitrary(u: &mut Unstructured<'a>) -> arbitrary::Result<Self> {
        let bytes = u.bytes(LEN.min(u.len()))?;
        Ok(Self::decode(bytes))
    }

    fn arbitrary_take_rest(u: Unstructured<'a>) -> arbitrary::Result<Self> {
        Ok(Self::decode(u.take_rest()))
    }

    fn size_hint(_depth: usize) -> (usize, Option<usize>) {
        (0, Some(LEN))
    }
}

/// `Vec2::new(f32::from_bits(0x…), f32::from_bits(0x…))`.
struct Code(Vec2);

impl fmt::Display for Code {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "Vec2::new(f32::from_bits({:#010x}), f32::from_bits({:#010x}))",
            self.0.x.to_bits(),
            self.0.y.to_bits()
        )
    }
}

impl fmt::Debug for Input {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (p, [a, b, c]) = self.geometry();
        let words: Vec<String> = self.words.iter().map(|w| format!("{w:#010x}")).collect();
        writeln!(
            f,
            "// orient_barycentric: words [{}], mode {:#04x}",
            words.join(", "),
            self.mode
        )?;
        writeln!(f, "{{")?;
        for (name, v) in [("p", p), ("a", a), ("b", b), ("c", c)] {
            writeln!(f, "    let {name} = {}; // ({:?}, {:?})", Code(v), v.x, v.y)?;
        }
        writeln!(
            f,
            "    for (q, r, s) in [(a, b, c), (b, c, p), (c, a, p), (a, b, p)] {{"
        )?;
        writeln!(f, "        check_orient2d(q, r, s).unwrap();")?;
        writeln!(f, "    }}")?;
        writeln!(f, "    check_barycentric_2d(p, [a, b, c]).unwrap();")?;
        write!(f, "}}")
    }
}

fuzz_target!(|input: Input| {
    if let Err(message) = input.check() {
        panic!("{message}\ninput:\n{input:?}");
    }
});
