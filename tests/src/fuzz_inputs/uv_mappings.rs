//! Byte layout and checks of the `uv_mappings` fuzz target.
//!
//! Layout (f32 bit patterns): words 0–2 the point `p`, 3–5 the normal `n`, 6–8 vector `a`,
//! 9–11 vector `b`, 12–14 vector `c`, 15–16 scalars `s0`, `s1`, 17–22 a uv triangle; then the
//! mode byte at offset 92 (`kind`, `k` as in [`super::mode`]). The mappings built: `Planar::new(a,
//! b, c)`, `Planar::xz(s0)`, `BoxMapping::new(a, s0)`, `Cylindrical::new(s0, s1)` with and
//! without caps, `Spherical::new(s0, _)` in both projections, `Torus::new(s0, s1)`; the screen
//! derivatives are `a` and `b`. Kinds: 1 `p` on the y axis, x moved `k` ulps from 0 (poles,
//! axes); 2 `p` on the seam half-plane (`x` `k` ulps from 0, `z ≤ 0`); 3 `p` replaced per
//! mapping by its `point_at` of the triangle's first uv (on the surface); 4 the triangle's `u`
//! wrapped into `[0, 1)` (seam-repair geometry); others raw.

use std::fmt::Write as _;

use barytex_uv::mappings::{
    BoxMapping, CylinderCaps, Cylindrical, InverseUvMapping, Planar, SphereProjection, Spherical,
    Torus, UvMapping64,
};
use barytex_uv::seam::{repair_seam, repair_sphere_triangle};
use barytex_uv::{PositionMapping, SurfacePoint, UvMapping};
use glam::{Vec2, Vec3};

use super::{mode, word};
use barytex_testkit::strategies::step_ulps;

/// Bytes the `uv_mappings` target reads: 23 words and the mode byte.
pub const UV_MAPPINGS_LEN: usize = 23 * 4 + 1;

/// The decoded input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UvMappingsInput {
    /// The point.
    pub p: Vec3,
    /// The normal.
    pub n: Vec3,
    /// Parameter vectors (also the screen derivatives `a`, `b`).
    pub abc: [Vec3; 3],
    /// Scalar parameters.
    pub s: [f32; 2],
    /// The uv triangle.
    pub tri: [Vec2; 3],
    /// The mode kind.
    pub kind: u8,
}

/// `bytes` decoded (before the per-mapping `point_at` of kind 3).
#[must_use]
pub fn uv_mappings_input(bytes: &[u8]) -> UvMappingsInput {
    let f = |w: usize| f32::from_bits(word(bytes, w));
    let v3 = |w: usize| Vec3::new(f(w), f(w + 1), f(w + 2));
    let (kind, k) = mode(bytes, 92);
    let mut p = v3(0);
    let mut tri: [Vec2; 3] = core::array::from_fn(|i| Vec2::new(f(17 + 2 * i), f(18 + 2 * i)));
    match kind {
        1 => p = Vec3::new(step_ulps(0.0, k), p.y, 0.0),
        2 => p = Vec3::new(step_ulps(0.0, k), p.y, -p.z.abs()),
        4 => {
            for t in &mut tri {
                t.x = t.x.rem_euclid(1.0);
            }
        }
        _ => {}
    }
    UvMappingsInput {
        p,
        n: v3(3),
        abc: [v3(6), v3(9), v3(12)],
        s: [f(15), f(16)],
        tri,
        kind,
    }
}

/// A mapping as the checks see it.
trait Mapping: PositionMapping + UvMapping64 {
    fn inverse(&self) -> Option<&dyn InverseUvMapping>;
    /// Which of u, v are periodic (wrapped into `[0, 1)`), given the normal.
    fn periodic(&self, normal: Vec3) -> (bool, bool);
}

impl Mapping for Planar {
    fn inverse(&self) -> Option<&dyn InverseUvMapping> {
        Some(self)
    }
    fn periodic(&self, _: Vec3) -> (bool, bool) {
        (false, false)
    }
}

impl Mapping for BoxMapping {
    fn inverse(&self) -> Option<&dyn InverseUvMapping> {
        None
    }
    fn periodic(&self, _: Vec3) -> (bool, bool) {
        (false, false)
    }
}

impl Mapping for Cylindrical {
    fn inverse(&self) -> Option<&dyn InverseUvMapping> {
        Some(self)
    }
    fn periodic(&self, n: Vec3) -> (bool, bool) {
        (!self.on_cap(n), false)
    }
}

impl Mapping for Spherical {
    fn inverse(&self) -> Option<&dyn InverseUvMapping> {
        Some(self)
    }
    fn periodic(&self, _: Vec3) -> (bool, bool) {
        (true, false)
    }
}

impl Mapping for Torus {
    fn inverse(&self) -> Option<&dyn InverseUvMapping> {
        Some(self)
    }
    fn periodic(&self, _: Vec3) -> (bool, bool) {
        (true, true)
    }
}

fn mappings(input: &UvMappingsInput) -> Vec<(&'static str, Box<dyn Mapping>)> {
    let [a, b, c] = input.abc;
    let [s0, s1] = input.s;
    let mut out: Vec<(&'static str, Box<dyn Mapping>)> = Vec::new();
    if let Ok(m) = Planar::new(a, b, c) {
        out.push(("Planar::new", Box::new(m)));
    }
    if let Ok(m) = Planar::xz(s0) {
        out.push(("Planar::xz", Box::new(m)));
    }
    if let Ok(m) = BoxMapping::new(a, s0) {
        out.push(("BoxMapping", Box::new(m)));
    }
    if let Ok(m) = Cylindrical::new(s0, s1) {
        out.push(("Cylindrical", Box::new(m)));
        out.push((
            "Cylindrical caps",
            Box::new(m.with_caps(CylinderCaps::Planar)),
        ));
    }
    for projection in [
        SphereProjection::Equirectangular,
        SphereProjection::EqualArea,
    ] {
        if let Ok(m) = Spherical::new(s0, projection) {
            out.push(("Spherical", Box::new(m)));
        }
    }
    if let Ok(m) = Torus::new(s0, s1) {
        out.push(("Torus", Box::new(m)));
    }
    out
}

/// The mapping invariants at one point: `None` or finite; `None` for non-finite input; periodic
/// coordinates in `[0, 1)` (the sphere's v in `[0, 1]`); `map` is `None` or the chain rule.
fn check_mapping(
    name: &str,
    m: &dyn Mapping,
    p: Vec3,
    n: Vec3,
    d: [Vec3; 2],
) -> Result<(), String> {
    let j = m.uv_and_jacobian(p, n);
    if let Some(j) = j {
        if !(j.uv.is_finite() && j.du.is_finite() && j.dv.is_finite()) {
            return Err(format!("{name}: non-finite {j:?} at {p:?} {n:?}"));
        }
        let (pu, pv) = m.periodic(n);
        if pu && !(0.0..1.0).contains(&j.uv.x) {
            return Err(format!("{name}: u = {} not in [0, 1) at {p:?}", j.uv.x));
        }
        if pv && !(0.0..1.0).contains(&j.uv.y) {
            return Err(format!("{name}: v = {} not in [0, 1) at {p:?}", j.uv.y));
        }
        if name == "Spherical" && !(0.0..=1.0).contains(&j.uv.y) {
            return Err(format!("{name}: v = {} not in [0, 1] at {p:?}", j.uv.y));
        }
    }
    if !(p.is_finite() && n.is_finite()) && j.is_some() {
        return Err(format!("{name}: Some for non-finite input {p:?} {n:?}"));
    }
    let s = m.map(&SurfacePoint::with_derivatives(p, n, d[0], d[1]));
    if let Some(s) = s {
        let j = j.ok_or_else(|| format!("{name}: map Some but uv_and_jacobian None"))?;
        let chain = (
            Vec2::new(j.du.dot(d[0]), j.dv.dot(d[0])),
            Vec2::new(j.du.dot(d[1]), j.dv.dot(d[1])),
        );
        if s.uv != j.uv || (s.duvdx, s.duvdy) != chain {
            return Err(format!("{name}: map {s:?} is not the chain rule {chain:?}"));
        }
    }
    Ok(())
}

fn u_span(t: &[Vec2; 3]) -> f64 {
    let us = t.map(|p| f64::from(p.x));
    us.iter().copied().fold(f64::NEG_INFINITY, f64::max)
        - us.iter().copied().fold(f64::INFINITY, f64::min)
}

/// The shortest arc of the unit circle holding the three `u`, in turns.
fn circular_span(t: &[Vec2; 3]) -> f64 {
    let us = t.map(|p| f64::from(p.x));
    us.iter()
        .map(|&s| {
            us.iter()
                .map(|&u| (u - s).rem_euclid(1.0))
                .fold(0.0, f64::max)
        })
        .fold(f64::INFINITY, f64::min)
}

/// Seam-repair invariants: `v` bits kept; finite stays finite; for moderate `u` (|u| < 1024)
/// shifts are whole turns, the range never grows, and a triangle that fits in less than half a
/// turn spans at most half the texture.
fn check_seam(tri: [Vec2; 3]) -> Result<(), String> {
    for (name, fixed) in [
        ("repair_seam", repair_seam(tri)),
        ("repair_sphere_triangle", repair_sphere_triangle(tri)),
    ] {
        for i in 0..3 {
            if fixed[i].y.to_bits() != tri[i].y.to_bits() {
                return Err(format!("{name}: v changed {tri:?} → {fixed:?}"));
            }
        }
        let finite = tri.iter().all(|p| p.is_finite());
        if finite && !fixed.iter().all(|p| p.is_finite()) {
            return Err(format!("{name}: non-finite {tri:?} → {fixed:?}"));
        }
        let moderate = finite && tri.iter().all(|p| p.x.abs() < 1024.0);
        if !moderate || name != "repair_seam" {
            continue;
        }
        for i in 0..3 {
            let turns = f64::from(fixed[i].x) - f64::from(tri[i].x);
            if (turns - turns.round()).abs() > 1e-4 {
                return Err(format!(
                    "{name}: shift {turns} not whole {tri:?} → {fixed:?}"
                ));
            }
        }
        if u_span(&fixed) > u_span(&tri) + 1e-4 {
            return Err(format!("{name}: range grew {tri:?} → {fixed:?}"));
        }
        if circular_span(&tri) < 0.5 - 1e-3 && u_span(&fixed) > 0.5 {
            return Err(format!("{name}: spans more than half {tri:?} → {fixed:?}"));
        }
    }
    Ok(())
}

/// The invariants over every mapping buildable from the input and over seam repair.
///
/// # Errors
/// A description of the first violated invariant.
pub fn check_uv_mappings(bytes: &[u8]) -> Result<(), String> {
    let input = uv_mappings_input(bytes);
    let d = [input.abc[0], input.abc[1]];
    for (name, m) in mappings(&input) {
        let mut p = input.p;
        let on_surface = m.inverse().and_then(|inv| inv.point_at(input.tri[0]));
        if let (3, Some(q)) = (input.kind, on_surface) {
            if !q.is_finite() {
                return Err(format!("{name}: point_at gave {q:?}"));
            }
            p = q;
        }
        check_mapping(name, m.as_ref(), p, input.n, d)?;
    }
    check_seam(input.tri)
}

/// The input as a Rust block for a regression test.
#[must_use]
pub fn uv_mappings_code(bytes: &[u8]) -> String {
    let input = uv_mappings_input(bytes);
    let v3 = |v: Vec3| {
        let [x, y, z] = v
            .to_array()
            .map(|c| format!("f32::from_bits({:#010x})", c.to_bits()));
        format!("Vec3::new({x}, {y}, {z})")
    };
    let mut out = String::from("{\n");
    let _ = writeln!(out, "    // {input:?}");
    let _ = writeln!(out, "    let p = {};", v3(input.p));
    let _ = writeln!(out, "    let n = {};", v3(input.n));
    for (name, v) in ["a", "b", "c"].iter().zip(input.abc) {
        let _ = writeln!(out, "    let {name} = {};", v3(v));
    }
    let _ = writeln!(
        out,
        "    let (s0, s1) = (f32::from_bits({:#010x}), f32::from_bits({:#010x}));",
        input.s[0].to_bits(),
        input.s[1].to_bits()
    );
    out.push_str("    // build each mapping from (a, b, c, s0, s1) and evaluate at (p, n)\n}");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bytes(words: &[f32], mode: u8) -> Vec<u8> {
        let mut b: Vec<u8> = words
            .iter()
            .flat_map(|w| w.to_bits().to_le_bytes())
            .collect();
        b.resize(92, 0);
        b.push(mode);
        b
    }

    #[test]
    fn layout_and_checks() {
        let mut w = [0.0f32; 23];
        w[0..3].copy_from_slice(&[0.5, 0.25, 1.0]); // p
        w[3..6].copy_from_slice(&[0.0, 0.0, 1.0]); // n
        w[6..9].copy_from_slice(&[1.0, 0.0, 0.0]); // a
        w[9..12].copy_from_slice(&[0.0, 0.0, 1.0]); // b
        w[12..15].copy_from_slice(&[0.0, 1.0, 0.0]); // c
        w[15..17].copy_from_slice(&[1.0, 2.0]);
        w[17..23].copy_from_slice(&[0.9, 0.2, 0.1, 0.2, 0.1, 0.4]);
        let input = uv_mappings_input(&bytes(&w, 0));
        assert_eq!(input.p, Vec3::new(0.5, 0.25, 1.0));
        assert_eq!(input.s, [1.0, 2.0]);
        assert_eq!(input.tri[1], Vec2::new(0.1, 0.2));
        assert_eq!(mappings(&input).len(), 8);
        for kind in 0..8 {
            assert_eq!(check_uv_mappings(&bytes(&w, kind | (16 << 3))), Ok(()));
        }
        // Kind 1: p on the axis.
        assert_eq!(
            uv_mappings_input(&bytes(&w, 1 | (16 << 3))).p,
            Vec3::new(0.0, 0.25, 0.0)
        );
        assert_eq!(check_uv_mappings(&[]), Ok(()));
        assert!(uv_mappings_code(&bytes(&w, 0)).contains("0x3f000000"));
        // Figure V.4 passes the seam checks.
        assert!(
            check_seam([
                Vec2::new(0.9, 0.0),
                Vec2::new(0.1, 0.0),
                Vec2::new(0.9, 1.0)
            ])
            .is_ok()
        );
    }
}
