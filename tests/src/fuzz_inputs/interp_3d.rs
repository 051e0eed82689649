//! Byte layout and checks of the `interp_3d` fuzz target: `barycentric_3d` and
//! `inverse_bilinear_3d` on arbitrary f32 bits.
//!
//! Layout: 15 little-endian words as f32 bit patterns — the point `p` (words 0–2) and the corners
//! `a, b, c, d` (words 3–14) — then the mode byte (byte 60). The triangle is `[a, b, c]`, the quad
//! `[a, b, c, d]`. Kind `m & 7`: 1 = the corners on a small integer grid (the low byte of each
//! word as an `i8`, times `2^(k)` with `k = (m >> 3) − 16`) and `p` on the bilinear surface at
//! `(α, β) = ((1 + b₀ mod 15)/16, (1 + b₄ mod 15)/16)` (`bᵢ` the input bytes), rounded to f32;
//! others raw.
//!
//! Invariants, as the functions document them:
//! - `barycentric_3d`: `NonFinite` exactly for NaN/∞ input; `DegenerateTriangle` exactly for
//!   collinear vertices (decided with exact rationals); otherwise no NaN weight, and at any
//!   distance from the triangle each weight within `1 ulp + 2⁻⁴⁶·κ` of the exact weight of the
//!   projected point (its `# Accuracy`; an infinity is accepted where the exact weight rounds to
//!   it, and `±f32::MAX` falls under the bound where a computed weight beyond f32's range may
//!   have a finite exact value: `crash-487e…`, exact 3.8e37, was an infinity). The weights then sum to 1 within the sum of those bounds. (The input
//!   `fuzz/regressions/interp_3d/crash-54d6…`, a point 1e13 from a triangle of size 1e-17, broke
//!   the bound before the weights were computed from one long vector and one edge.)
//! - `inverse_bilinear_3d`: `NonFinite` exactly for NaN/∞ input, no other error than
//!   `DegenerateQuad` for finite input; no NaN in any reported preimage; inside preimages in
//!   `[0, 1]²`. For kind 1 with four non-coplanar corners (decided exactly) the point is exactly on
//!   the surface (grid corners and sixteenths need no rounding): the answer must be a preimage in `[0, 1]²` that maps back within `1e-6` of the
//!   quad's diameter (the criterion of `tests/bilinear.rs::inverse_bilinear_3d_round_trip_non_planar`
//!   in barytex-interp).

use std::fmt::Write as _;

use barytex_interp::{InterpError, InverseBilinear, barycentric_3d, inverse_bilinear_3d};
use barytex_testkit::exact::{self, qf};
use barytex_testkit::ulp::ulp_f32;
use glam::{DVec3, Vec3};

use super::{mode, word};

/// Bytes the target reads: 15 words and the mode byte.
pub const INTERP_3D_LEN: usize = 15 * 4 + 1;

/// A decoded `interp_3d` input: `(p, [a, b, c, d], on_surface)`.
#[must_use]
pub fn interp_3d_geometry(bytes: &[u8]) -> (Vec3, [Vec3; 4], bool) {
    let f = |w: usize| f32::from_bits(word(bytes, w));
    let v = |i: usize| Vec3::new(f(3 * i), f(3 * i + 1), f(3 * i + 2));
    let (kind, k) = mode(bytes, 60);
    if kind == 1 {
        let scale = 2f32.powi(k);
        let grid = |w: usize| f32::from(word(bytes, w) as u8 as i8) * scale;
        let corner = |i: usize| Vec3::new(grid(3 * i + 3), grid(3 * i + 4), grid(3 * i + 5));
        let quad = [corner(0), corner(1), corner(2), corner(3)];
        let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
        let alpha = f64::from(1 + byte(0) % 15) / 16.0;
        let beta = f64::from(1 + byte(4) % 15) / 16.0;
        let p = bilinear_3d_f64(quad.map(Vec3::as_dvec3), alpha, beta).as_vec3();
        return (p, quad, true);
    }
    (v(0), [v(1), v(2), v(3), v(4)], false)
}

fn bilinear_3d_f64([x, y, z, w]: [DVec3; 4], a: f64, b: f64) -> DVec3 {
    x * ((1.0 - a) * (1.0 - b)) + y * (a * (1.0 - b)) + z * (a * b) + w * ((1.0 - a) * b)
}

/// κ of a 3D barycentric query: `max(|p|, |a|, |b|, |c|) · max edge / |2·area|` (in f64).
fn kappa(p: Vec3, [a, b, c]: [Vec3; 3]) -> f64 {
    let (p, a, b, c) = (p.as_dvec3(), a.as_dvec3(), b.as_dvec3(), c.as_dvec3());
    let m = [p, a, b, c].iter().map(|v| v.length()).fold(0.0, f64::max);
    let e = (b - a).length().max((c - b).length()).max((a - c).length());
    m * e / (b - a).cross(c - a).length()
}

/// `barycentric_3d`'s invariants (see the module documentation).
///
/// # Errors
/// The violated invariant.
pub fn check_barycentric_3d(p: Vec3, tri: [Vec3; 3]) -> Result<(), String> {
    let got = barycentric_3d(p, tri);
    if !(p.is_finite() && tri.iter().all(|v| v.is_finite())) {
        return match got {
            Err(InterpError::NonFinite { .. }) => Ok(()),
            other => Err(format!("non-finite {p:?} {tri:?} gave {other:?}")),
        };
    }
    let Some(want) = exact::barycentric_3d(p, tri) else {
        return match got {
            Err(InterpError::DegenerateTriangle) => Ok(()),
            other => Err(format!("collinear {tri:?} gave {other:?}")),
        };
    };
    let b = got.map_err(|e| format!("barycentric_3d({p:?}, {tri:?}) failed: {e}"))?;
    if let Some(g) = b.weights.iter().find(|g| g.is_nan()) {
        return Err(format!(
            "a NaN weight {g} of {p:?} in {tri:?}: {:?}",
            b.weights
        ));
    }
    let k = kappa(p, tri);
    for (i, (g, w)) in b.weights.iter().zip(&want).enumerate() {
        let w64 = exact::to_f64(w);
        if g.is_infinite() && *g == w64 as f32 {
            // The exact weight is beyond f32: its infinity is the rounded value.
            continue;
        }
        if g.is_infinite() && w64.abs() > f64::from(f32::MAX) {
            // The exact weight is beyond f32 but the computed one overflowed the other way:
            // allowed only when the error bound (before the rounding to f32) spans both signs,
            // i.e. the weight is so ill-conditioned that its sign is within the rounding.
            let bound = k * 2f64.powi(-49);
            if w64.abs() <= bound {
                continue;
            }
        }
        if !g.is_finite() {
            return Err(format!(
                "weight {i} of {p:?} in {tri:?} is {g}, exact {w64:e}"
            ));
        }
        let err = exact::abs_diff(&qf(*g), w);
        let bound = ulp_f32(w64) + k * 2f64.powi(-46);
        if err > bound {
            return Err(format!(
                "weight {i} of {p:?} in {tri:?}: {g} vs exact {w64:e}, error {err:e} > bound {bound:e} (κ {k:e})"
            ));
        }
    }
    Ok(())
}

/// `inverse_bilinear_3d`'s invariants (see the module documentation).
///
/// # Errors
/// The violated invariant.
pub fn check_inverse_bilinear_3d(p: Vec3, quad: [Vec3; 4], on_surface: bool) -> Result<(), String> {
    let got = inverse_bilinear_3d(p, quad);
    if !(p.is_finite() && quad.iter().all(|v| v.is_finite())) {
        return match got {
            Err(InterpError::NonFinite { .. }) => Ok(()),
            other => Err(format!("non-finite {p:?} {quad:?} gave {other:?}")),
        };
    }
    // On the surface of a non-planar quad, the answer is a preimage (Denisjuk, Corollary 12).
    let [a, b, c, d] = quad;
    let strict = on_surface && exact::orient3d_sign(a, b, c, d) != 0;
    let result = match got {
        Ok(result) => result,
        Err(InterpError::DegenerateQuad) if !strict => return Ok(()),
        Err(e) => return Err(format!("inverse_bilinear_3d({p:?}, {quad:?}) failed: {e}")),
    };
    let inside = |ab: glam::Vec2| (0.0..=1.0).contains(&ab.x) && (0.0..=1.0).contains(&ab.y);
    let preimages = match result {
        InverseBilinear::Inside(ab) => vec![ab],
        InverseBilinear::Folded(a, b) => vec![a, b],
        InverseBilinear::Outside(Some(ab)) if ab.is_nan() => {
            return Err(format!("outside preimage {ab:?} of {p:?} in {quad:?}"));
        }
        InverseBilinear::Outside(_) if strict => {
            return Err(format!("{result:?} for {p:?} on the surface of {quad:?}"));
        }
        InverseBilinear::Outside(_) => vec![],
    };
    if let Some(ab) = preimages.iter().find(|ab| !inside(**ab)) {
        return Err(format!(
            "{result:?}: preimage {ab:?} outside [0,1]² for {p:?} in {quad:?}"
        ));
    }
    if strict {
        let q = quad.map(Vec3::as_dvec3);
        let diameter = q
            .iter()
            .flat_map(|x| q.iter().map(move |y| (*x - *y).length()))
            .fold(0.0, f64::max);
        for ab in preimages {
            let back = bilinear_3d_f64(q, f64::from(ab.x), f64::from(ab.y));
            let residual = (back - p.as_dvec3()).length();
            if residual > 1e-6 * diameter {
                return Err(format!(
                    "{result:?} for {p:?} in {quad:?}: maps back to {back:?}, residual {residual:e} (diameter {diameter:e})"
                ));
            }
        }
    }
    Ok(())
}

/// The `interp_3d` invariants: [`check_barycentric_3d`] on `(p, [a, b, c])`, then
/// [`check_inverse_bilinear_3d`] on `(p, [a, b, c, d])`.
///
/// # Errors
/// The first violated invariant.
pub fn check_interp_3d(bytes: &[u8]) -> Result<(), String> {
    let (p, [a, b, c, d], on_surface) = interp_3d_geometry(bytes);
    check_barycentric_3d(p, [a, b, c])?;
    check_inverse_bilinear_3d(p, [a, b, c, d], on_surface)
}

fn code(v: Vec3) -> String {
    format!(
        "Vec3::new(f32::from_bits({:#010x}), f32::from_bits({:#010x}), f32::from_bits({:#010x}))",
        v.x.to_bits(),
        v.y.to_bits(),
        v.z.to_bits()
    )
}

/// A failing input as a Rust block for a regression test.
#[must_use]
pub fn interp_3d_code(bytes: &[u8]) -> String {
    let (p, quad, on_surface) = interp_3d_geometry(bytes);
    let mut out = format!("{{\n    let p = {}; // {p:?}\n    let quad = [\n", code(p));
    for v in quad {
        let _ = writeln!(out, "        {}, // {v:?}", code(v));
    }
    out.push_str("    ];\n    check_barycentric_3d(p, [quad[0], quad[1], quad[2]]).unwrap();\n");
    let _ = writeln!(
        out,
        "    check_inverse_bilinear_3d(p, quad, {on_surface}).unwrap();\n}}"
    );
    out
}
