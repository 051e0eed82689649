//! Fuzz `inverse_bilinear_2d` against barytex-testkit's invariant `check_inverse_bilinear_2d`
//! (no panic, non-finite input is an error, inside preimages lie in `[0, 1]²` and map back to the
//! point).
//!
//! # Input layout
//!
//! Kept byte-simple so that `tests/tests/fuzz_regressions.rs` (main workspace, which cannot depend
//! on this crate) decodes a saved input identically with its own copy of [`Input::decode`]:
//!
//! | bytes   | meaning                                                                        |
//! |---------|--------------------------------------------------------------------------------|
//! | 0..40   | 10 little-endian `u32` f32 bit patterns: p.x p.y x.x x.y y.x y.y z.x z.y w.x w.y |
//! | 40      | mode byte                                                                      |
//! | 41..    | ignored                                                                        |
//!
//! The quad is `[x, y, z, w]` in `barytex_interp::bilinear`'s corner order. Missing bytes read as
//! zero, so every input is valid. Bit patterns go through `f32::from_bits`: NaNs, infinities,
//! subnormals and ±0 are all reachable.
//!
//! The mode byte `m` lets the fuzzer reach geometry that random bits almost never hit:
//! `kind = m & 7`, `k = (m >> 3) as i32 - 16` (ulps, −16..=15), `step` = `testkit::step_ulps`.
//!
//! | kind   | geometry                                                                          |
//! |--------|-----------------------------------------------------------------------------------|
//! | 0, 5–7 | raw                                                                               |
//! | 1      | `p = x`, then `p.x` stepped by `k` ulps (on / next to a corner)                   |
//! | 2      | `p = x + (y − x)·0.5`, then `p.y` stepped by `k` ulps (near edge `xy`)            |
//! | 3      | `z = y + w − x`, then `z.x` stepped by `k` ulps (near parallelogram)              |
//! | 4      | `p = bilinear(quad, α, β)` with `α = (raw p.x bits >> 8)·2⁻²⁴`, `β` likewise from `p.y`, then `p.x` stepped by `k` ulps (a point on the surface) |
//!
//! `Debug` prints the failing check as a Rust block that a regression test can paste; `cargo fuzz
//! fmt inverse_bilinear <artifact>` shows it for a crash file.
#![no_main]

use std::fmt;

use arbitrary::{Arbitrary, Unstructured};
use barytex_testkit::invariants::check_inverse_bilinear_2d;
use barytex_testkit::strategies::step_ulps;
use glam::Vec2;
use libfuzzer_sys::fuzz_target;

/// Number of bytes read: 10 words and the mode byte.
const LEN: usize = 10 * 4 + 1;

/// One fuzz input: raw words and mode, decoded exactly as documented above.
#[derive(Clone, Copy, PartialEq)]
struct Input {
    words: [u32; 10],
    mode: u8,
}

impl Input {
    fn decode(bytes: &[u8]) -> Self {
        let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
        let words =
            core::array::from_fn(|w| u32::from_le_bytes(core::array::from_fn(|k| byte(4 * w + k))));
        Self {
            words,
            mode: byte(40),
        }
    }

    /// `(p, [x, y, z, w])` after the mode is applied.
    fn geometry(&self) -> (Vec2, [Vec2; 4]) {
        let v = |i: usize| {
            Vec2::new(
                f32::from_bits(self.words[2 * i]),
                f32::from_bits(self.words[2 * i + 1]),
            )
        };
        let mut p = v(0);
        let mut quad = [v(1), v(2), v(3), v(4)];
        let [x, y, _, w] = quad;
        let k = i32::from(self.mode >> 3) - 16;
        match self.mode & 7 {
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
                let q = barytex_interp::bilinear(quad, unit(self.words[0]), unit(self.words[1]));
                p = Vec2::new(step_ulps(q.x, k), q.y);
            }
            _ => {}
        }
        (p, quad)
    }

    fn check(&self) -> Result<(), String> {
        let (p, quad) = self.geometry();
        check_inverse_bilinear_2d(p, quad)
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
        let (p, quad) = self.geometry();
        let words: Vec<String> = self.words.iter().map(|w| format!("{w:#010x}")).collect();
        writeln!(
            f,
            "// inverse_bilinear: words [{}], mode {:#04x}",
            words.join(", "),
            self.mode
        )?;
        writeln!(f, "{{")?;
        writeln!(f, "    let p = {}; // ({:?}, {:?})", Code(p), p.x, p.y)?;
        writeln!(f, "    let quad = [")?;
        for c in quad {
            writeln!(f, "        {}, // ({:?}, {:?})", Code(c), c.x, c.y)?;
        }
        writeln!(f, "    ];")?;
        writeln!(f, "    check_inverse_bilinear_2d(p, quad).unwrap();")?;
        write!(f, "}}")
    }
}

fuzz_target!(|input: Input| {
    if let Err(message) = input.check() {
        panic!("{message}\ninput:\n{input:?}");
    }
});
