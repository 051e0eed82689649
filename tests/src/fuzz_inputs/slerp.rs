//! Byte layout and checks of the `slerp` fuzz target.
//!
//! Layout: words 0–3 quaternion `a` (x, y, z, w), words 4–7 quaternion `b`, word 8 the parameter
//! `t`, then the mode byte at offset 36 (`kind`, `k` as in [`super::mode`]). Kinds: 1 `b` is `a`
//! with its x moved `k` ulps (nearly equal); 2 `b` is `−a` so moved (nearly antipodal); 3 `t` is
//! 0 or 1 moved `k` ulps; 4 `a` and `b` normalized first (unit inputs: endpoint and length checks
//! apply); others raw.

use std::fmt::Write as _;

use barytex_interp::{
    InterpError, QuatInterpolation, QuatPath, SLERP_F32_LENGTH_BOUND, interpolate_normal, slerp,
    slerp_along, try_slerp_along,
};
use glam::{Quat, Vec4};

use super::{mode, word};
use barytex_testkit::strategies::step_ulps;

/// Bytes the `slerp` target reads: 9 words and the mode byte.
pub const SLERP_LEN: usize = 9 * 4 + 1;

/// `(a, b, t)` decoded from `bytes`.
#[must_use]
pub fn slerp_geometry(bytes: &[u8]) -> (Quat, Quat, f32) {
    let v = |i: usize| {
        Vec4::from_array(core::array::from_fn(|j| {
            f32::from_bits(word(bytes, 4 * i + j))
        }))
    };
    let (mut a, mut b, mut t) = (v(0), v(1), f32::from_bits(word(bytes, 8)));
    let (kind, k) = mode(bytes, 36);
    match kind {
        1 => b = Vec4::new(step_ulps(a.x, k), a.y, a.z, a.w),
        2 => b = -Vec4::new(step_ulps(a.x, k), a.y, a.z, a.w),
        3 => t = step_ulps(if k >= 0 { 0.0 } else { 1.0 }, k),
        4 => {
            a = a.try_normalize().unwrap_or(Vec4::W);
            b = b.try_normalize().unwrap_or(Vec4::X);
        }
        _ => {}
    }
    (Quat::from_vec4(a), Quat::from_vec4(b), t)
}

/// The invariants: every member of the family gives a finite result on any input; valid
/// inputs give unit-length exact SLERP results (within 4× the stated bound: non-unit inputs are
/// normalized first) with exact endpoints for unit inputs; invalid inputs give zero / an error naming the first bad input.
///
/// # Errors
/// A description of the first violated invariant.
pub fn check_slerp(bytes: &[u8]) -> Result<(), String> {
    let (a, b, t) = slerp_geometry(bytes);
    for path in [QuatPath::Shortest, QuatPath::AsGiven] {
        let q = slerp_along(a, b, t, path);
        if !q.is_finite() {
            return Err(format!("slerp_along({a:?}, {b:?}, {t}, {path:?}) = {q:?}"));
        }
        let valid = Vec4::from(a).length_squared() > 0.0
            && Vec4::from(b).length_squared() > 0.0
            && a.is_finite()
            && b.is_finite()
            && t.is_finite();
        let checked = try_slerp_along(a, b, t, path);
        match checked {
            Ok(r) => {
                if r != q {
                    return Err(format!(
                        "try_slerp_along {r:?} differs from slerp_along {q:?}"
                    ));
                }
                if (Vec4::from(r).length() - 1.0).abs() > 4.0 * SLERP_F32_LENGTH_BOUND {
                    return Err(format!("|slerp_along({a:?}, {b:?}, {t})| = {}", r.length()));
                }
            }
            Err(e) if q != Quat::from_xyzw(0.0, 0.0, 0.0, 0.0) => {
                return Err(format!(
                    "{e:?} from try_slerp_along but slerp_along gave {q:?}"
                ));
            }
            Err(e) if valid && Vec4::from(a).is_finite() => {
                // Valid by finiteness but rejected: only a zero vector after all (subnormal
                // components whose squares underflow are still nonzero, and must work).
                return Err(format!("valid input rejected ({e:?}): {a:?} {b:?} {t}"));
            }
            Err(e) => {
                // The error names the first bad input, in the order t, a, b.
                let want = if !t.is_finite() {
                    InterpError::NonFinite { what: "t" }
                } else if !a.is_finite() {
                    InterpError::NonFinite { what: "a" }
                } else if Vec4::from(a) == Vec4::ZERO {
                    InterpError::ZeroLength { what: "a" }
                } else if !b.is_finite() {
                    InterpError::NonFinite { what: "b" }
                } else {
                    InterpError::ZeroLength { what: "b" }
                };
                if e != want {
                    return Err(format!("try_slerp_along gave {e:?}, want {want:?}"));
                }
            }
        }
        // The library's unit test: the squared length in f64 (exact products) within 4ε of 1.
        // Asserted a hair inside the tolerance, so that the summation order of the f64 squared
        // length cannot flip a case on the boundary. (The f32 squared length rounds: for
        // w = 1 + 2⁻²² it is exactly 1 + 4ε while the true value is above — the regression
        // `crash-6bc9085fd7932acdc85e42efe74329f94601cb32`.)
        let near_unit = |q: Quat| {
            let squared: f64 = q
                .to_array()
                .iter()
                .map(|&c| f64::from(c) * f64::from(c))
                .sum();
            (squared - 1.0).abs() <= 4.0 * f64::from(f32::EPSILON) * (1.0 - 1e-9)
        };
        let unit = near_unit(a) && near_unit(b);
        if unit && checked.is_ok() {
            let end = if path == QuatPath::Shortest && a.dot(b) < 0.0 {
                -b
            } else {
                b
            };
            if slerp_along(a, b, 0.0, path) != a || slerp_along(a, b, 1.0, path) != end {
                return Err(format!("endpoints not exact for {a:?} {b:?} {path:?}"));
            }
        }
    }
    for method in QuatInterpolation::ALL {
        let r = method.interpolate(a, b, t);
        if !r.is_finite() {
            return Err(format!("{} gave {r:?}", method.name()));
        }
    }
    let (u, v) = (Vec4::from(a).truncate(), Vec4::from(b).truncate());
    let s = slerp(u, v, t);
    if !s.is_finite() {
        return Err(format!("slerp({u:?}, {v:?}, {t}) = {s:?}"));
    }
    for method in [
        barytex_interp::NormalInterpolation::Renormalize,
        barytex_interp::NormalInterpolation::Slerp,
    ] {
        if !interpolate_normal(u, v, t, method).is_finite() {
            return Err(format!(
                "interpolate_normal({u:?}, {v:?}, {t}, {method:?}) not finite"
            ));
        }
    }
    Ok(())
}

fn quat_code(q: Quat) -> String {
    let [x, y, z, w] = q
        .to_array()
        .map(|c| format!("f32::from_bits({:#010x})", c.to_bits()));
    format!("Quat::from_xyzw({x}, {y}, {z}, {w})")
}

/// The input as a Rust block for a regression test.
#[must_use]
pub fn slerp_code(bytes: &[u8]) -> String {
    let (a, b, t) = slerp_geometry(bytes);
    let mut out = String::from("{\n");
    let _ = writeln!(out, "    let a = {};", quat_code(a));
    let _ = writeln!(out, "    let b = {};", quat_code(b));
    let _ = writeln!(out, "    let t = f32::from_bits({:#010x});", t.to_bits());
    out.push_str("    for path in [QuatPath::Shortest, QuatPath::AsGiven] {\n");
    out.push_str("        assert!(slerp_along(a, b, t, path).is_finite());\n    }\n}");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layout_and_printing() {
        let mut bytes = vec![0u8; SLERP_LEN];
        bytes[12..16].copy_from_slice(&1.0f32.to_bits().to_le_bytes()); // a = identity
        bytes[16..20].copy_from_slice(&1.0f32.to_bits().to_le_bytes()); // b = x
        bytes[32..36].copy_from_slice(&0.5f32.to_bits().to_le_bytes());
        let (a, b, t) = slerp_geometry(&bytes);
        assert_eq!(
            (a, b, t),
            (Quat::IDENTITY, Quat::from_xyzw(1.0, 0.0, 0.0, 0.0), 0.5)
        );
        assert_eq!(check_slerp(&bytes), Ok(()));
        assert!(slerp_code(&bytes).contains("0x3f000000"));
        // Kind 2 with k = 0: exactly antipodal.
        bytes[36] = 2 | (16 << 3);
        let (a, b, _) = slerp_geometry(&bytes);
        assert_eq!(Vec4::from(b), -Vec4::from(a));
        assert_eq!(check_slerp(&bytes), Ok(()));
    }
}
