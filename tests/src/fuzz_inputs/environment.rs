//! Byte layout and checks of the `environment` fuzz target.
//!
//! Layout: words 0–2 a direction `d` (x, y, z), words 3–4 a texture coordinate `uv`, words 5–7 a
//! second vector `w` (the view vector of the reflection, the eye of the mapping), then the mode
//! byte at offset 32 (`kind`, `k` as in [`super::mode`]). Kinds: 1 `d` normalized first; 2 `d`
//! near a cube corner (`(x, x + k ulps, x − k ulps)`, ties between axes); 3 `d` within `k` ulps
//! of the sphere map's singular direction `(0, 0, −1)`; 4 `u` on the seam (0 for `k ≥ 0`, 1
//! otherwise, moved `k` ulps); 5 `uv` uniform in `[0, 1)²` from the top 24 bits of words 3 and 4;
//! 6 `d` uniform in `[−1, 1)³` likewise from words 0–2; others raw.

use std::fmt::Write as _;

use barytex_uv::PositionMapping;
use barytex_uv::environment::{
    CUBE_ROUND_TRIP_BOUND, CubeFace, EQUIRECT_ROUND_TRIP_BOUND, EnvironmentMap, EnvironmentMapping,
    Lookup, OCTAHEDRAL_ROUND_TRIP_BOUND, SPHERE_MAP_ROUND_TRIP_BOUND, cube_direction, cube_face_uv,
    equirect_direction, equirect_uv, octahedral_decode, octahedral_encode, reflect,
    reflect_normalized, sphere_map_direction, sphere_map_uv,
};
use glam::{Vec2, Vec3};

use super::{mode, word};
use barytex_testkit::strategies::step_ulps;

/// Bytes the `environment` target reads: 8 words and the mode byte.
pub const ENVIRONMENT_LEN: usize = 8 * 4 + 1;

/// `(d, uv, w)` decoded from `bytes`.
#[must_use]
pub fn environment_geometry(bytes: &[u8]) -> (Vec3, Vec2, Vec3) {
    let f = |i: usize| f32::from_bits(word(bytes, i));
    let unit = |i: usize| (word(bytes, i) >> 8) as f32 * (1.0 / 16_777_216.0);
    let mut d = Vec3::new(f(0), f(1), f(2));
    let mut uv = Vec2::new(f(3), f(4));
    let w = Vec3::new(f(5), f(6), f(7));
    let (kind, k) = mode(bytes, 32);
    match kind {
        1 => d = d.try_normalize().unwrap_or(Vec3::Z),
        2 => d = Vec3::new(d.x, step_ulps(d.x, k), step_ulps(d.x, -k)),
        3 => d = Vec3::new(step_ulps(0.0, k), step_ulps(0.0, k / 2), -1.0),
        4 => uv.x = step_ulps(if k >= 0 { 0.0 } else { 1.0 }, k),
        5 => uv = Vec2::new(unit(3), unit(4)),
        6 => d = 2.0 * Vec3::new(unit(0), unit(1), unit(2)) - 1.0,
        _ => {}
    }
    (d, uv, w)
}

fn angle(a: Vec3, b: Vec3) -> f64 {
    let (a, b) = (a.as_dvec3(), b.as_dvec3());
    a.cross(b).length().atan2(a.dot(b))
}

fn in_unit_square(uv: Vec2) -> bool {
    uv.is_finite() && uv.cmpge(Vec2::ZERO).all() && uv.cmple(Vec2::ONE).all()
}

fn is_unit(d: Vec3) -> bool {
    d.is_finite() && (d.length() - 1.0).abs() <= 1e-6
}

/// Brute force cube face: the last axis of largest magnitude (z over y over x, Vulkan's tie
/// rule) with its sign.
fn argmax_face(d: Vec3) -> Option<CubeFace> {
    let a = d.abs().to_array();
    let max = a.iter().copied().fold(0.0f32, f32::max);
    if max == 0.0 || !d.is_finite() {
        return None;
    }
    let axis = (0..3).rev().find(|&i| a[i] == max)?;
    CubeFace::from_layer(2 * axis as u32 + u32::from(d[axis] < 0.0))
}

/// The forward maps on `d`: `Some` exactly for finite nonzero `d` (the sphere map also refuses
/// its singular direction), results in `[0, 1]²`, the cube face that of a brute-force argmax,
/// and the round trip through the inverse within each map's stated angle.
fn check_direction(d: Vec3) -> Result<(), String> {
    let valid = d.is_finite() && d != Vec3::ZERO;
    let trip = |name: &str, back: Option<Vec3>, bound: f64| -> Result<(), String> {
        let back = back.ok_or_else(|| format!("{name}: inverse None for {d:?}"))?;
        if !is_unit(back) || angle(back, d) > bound {
            return Err(format!(
                "{name}: {d:?} came back as {back:?}, {} rad (bound {bound:e})",
                angle(back, d)
            ));
        }
        Ok(())
    };
    let cube = cube_face_uv(d);
    if cube.map(|(f, _)| f) != argmax_face(d) {
        return Err(format!(
            "cube face of {d:?}: {cube:?}, argmax {:?}",
            argmax_face(d)
        ));
    }
    if let Some((face, st)) = cube {
        if !in_unit_square(st) {
            return Err(format!("cube_face_uv({d:?}) = {st:?}"));
        }
        trip(
            "cube",
            cube_direction(face, st),
            f64::from(CUBE_ROUND_TRIP_BOUND),
        )?;
    }
    let forward = [
        ("equirect", equirect_uv(d)),
        ("octahedral", octahedral_encode(d)),
    ];
    for (name, uv) in forward {
        if uv.is_some() != valid || !uv.is_none_or(in_unit_square) {
            return Err(format!("{name}({d:?}) = {uv:?}"));
        }
    }
    if let Some(uv) = equirect_uv(d) {
        trip(
            "equirect",
            equirect_direction(uv),
            f64::from(EQUIRECT_ROUND_TRIP_BOUND),
        )?;
    }
    if let Some(uv) = octahedral_encode(d) {
        trip(
            "octahedral",
            octahedral_decode(uv),
            f64::from(OCTAHEDRAL_ROUND_TRIP_BOUND),
        )?;
    }
    let st = sphere_map_uv(d);
    let from_neg_z = if valid { angle(d, Vec3::NEG_Z) } else { 0.0 };
    match st {
        Some(st) => {
            if !valid || !in_unit_square(st) || (st - 0.5).length() > 0.5 + 1e-7 {
                return Err(format!("sphere_map_uv({d:?}) = {st:?}"));
            }
            if from_neg_z >= 1e-6 {
                let cos_half = (angle(d, Vec3::Z) / 2.0).cos();
                let bound = f64::from(SPHERE_MAP_ROUND_TRIP_BOUND) / cos_half;
                trip("sphere map", sphere_map_direction(st), bound)?;
            }
        }
        None if valid && from_neg_z >= 1e-3 => {
            return Err(format!(
                "sphere_map_uv({d:?}) None, {from_neg_z} rad from −z"
            ));
        }
        None => {}
    }
    for map in EnvironmentMap::ALL {
        if let Some(j) = map.uv_and_direction_jacobian(d) {
            if !valid || !in_unit_square(j.uv) || !j.du.is_finite() || !j.dv.is_finite() {
                return Err(format!("{} jacobian at {d:?}: {j:?}", map.name()));
            }
            if Some(j.uv) != map.uv(d) {
                return Err(format!("{} jacobian uv differs at {d:?}", map.name()));
            }
        }
    }
    Ok(())
}

/// The inverse maps on `uv`: unit directions or `None` (non-finite `uv` always `None`), and the
/// round trip uv → direction → uv away from seams, poles, folds and the rim.
fn check_uv(uv: Vec2) -> Result<(), String> {
    let finite = uv.is_finite();
    let inner = finite && uv.cmpge(Vec2::splat(0.001)).all() && uv.cmple(Vec2::splat(0.999)).all();
    let back = |name: &str, d: Option<Vec3>, forward: &dyn Fn(Vec3) -> Option<Vec2>, tol: f32| {
        if !finite && d.is_some() || !d.is_none_or(is_unit) {
            return Err(format!("{name}({uv:?}) = {d:?}"));
        }
        match d.map(|d| (d, forward(d))) {
            Some((d, Some(again))) if (again - uv).abs().max_element() > tol => Err(format!(
                "{name}: {uv:?} → {d:?} → {again:?} (tolerance {tol:e})"
            )),
            Some((d, None)) => Err(format!("{name}: {uv:?} → {d:?} → None")),
            _ => Ok(()),
        }
    };
    for face in CubeFace::ALL {
        let d = cube_direction(face, uv);
        if !finite && d.is_some() || !d.is_none_or(is_unit) {
            return Err(format!("cube_direction({face:?}, {uv:?}) = {d:?}"));
        }
        if inner {
            let forward = |d: Vec3| cube_face_uv(d).and_then(|(f, st)| (f == face).then_some(st));
            back("cube_direction", d, &forward, 4e-7)?;
        }
    }
    let equirect = equirect_direction(uv);
    if inner {
        back("equirect_direction", equirect, &equirect_uv, 2e-6)?;
    } else if !finite && equirect.is_some() || !equirect.is_none_or(is_unit) {
        return Err(format!("equirect_direction({uv:?}) = {equirect:?}"));
    }
    let octahedral = octahedral_decode(uv);
    if octahedral.is_some() != finite {
        return Err(format!("octahedral_decode({uv:?}) = {octahedral:?}"));
    }
    let p = 2.0 * uv - 1.0;
    if inner && (p.x.abs() + p.y.abs() - 1.0).abs() > 1e-3 {
        back("octahedral_decode", octahedral, &octahedral_encode, 1e-6)?;
    } else if !octahedral.is_none_or(is_unit) {
        return Err(format!("octahedral_decode({uv:?}) = {octahedral:?}"));
    }
    let sphere = sphere_map_direction(uv);
    if finite && p.length() < 0.998 {
        back("sphere_map_direction", sphere, &sphere_map_uv, 1e-6)?;
    } else if !finite && sphere.is_some() || !sphere.is_none_or(is_unit) {
        return Err(format!("sphere_map_direction({uv:?}) = {sphere:?}"));
    }
    Ok(())
}

/// The invariants: `check_direction` on `d` (and on its reflection about `w`), `check_uv` on
/// `uv`, `reflect_normalized` unit or `None` exactly for an invalid input, and the
/// [`EnvironmentMapping`]s total (`Some` only with finite uv in `[0, 1]²` and finite
/// gradients).
///
/// # Errors
/// A description of the first violated invariant.
pub fn check_environment(bytes: &[u8]) -> Result<(), String> {
    let (d, uv, w) = environment_geometry(bytes);
    check_direction(d)?;
    check_uv(uv)?;
    let valid = |v: Vec3| v.is_finite() && v != Vec3::ZERO;
    let r = reflect_normalized(d, w);
    match r {
        Some(r) if !(valid(d) && valid(w) && is_unit(r)) => {
            return Err(format!("reflect_normalized({d:?}, {w:?}) = {r:?}"));
        }
        Some(r) => check_direction(r)?,
        None if valid(d) && valid(w) => {
            return Err(format!("reflect_normalized({d:?}, {w:?}) = None"));
        }
        None => {}
    }
    // The raw reflection may be anything, but never a panic; its maps are checked like d.
    let raw = reflect(d, w);
    if raw.is_finite() {
        check_direction(raw)?;
    }
    for map in EnvironmentMap::ALL {
        for lookup in [
            Lookup::Normal,
            Lookup::Reflect { eye: w },
            Lookup::Direction,
        ] {
            let mapping = EnvironmentMapping { map, lookup };
            let position = uv.extend(0.0);
            if let Some(j) = mapping.uv_and_jacobian(position, d)
                && (!in_unit_square(j.uv) || !j.du.is_finite() || !j.dv.is_finite())
            {
                return Err(format!("{mapping:?} at {position:?}, normal {d:?}: {j:?}"));
            }
        }
    }
    Ok(())
}

fn vec3_code(v: Vec3) -> String {
    let [x, y, z] = v
        .to_array()
        .map(|c| format!("f32::from_bits({:#010x})", c.to_bits()));
    format!("Vec3::new({x}, {y}, {z})")
}

/// The input as a Rust block for a regression test.
#[must_use]
pub fn environment_code(bytes: &[u8]) -> String {
    let (d, uv, w) = environment_geometry(bytes);
    let mut out = String::from("{\n");
    let _ = writeln!(out, "    let d = {}; // {d:?}", vec3_code(d));
    let _ = writeln!(
        out,
        "    let uv = Vec2::new(f32::from_bits({:#010x}), f32::from_bits({:#010x})); // {uv:?}",
        uv.x.to_bits(),
        uv.y.to_bits()
    );
    let _ = writeln!(out, "    let w = {}; // {w:?}", vec3_code(w));
    out.push_str(
        "    let _ = (cube_face_uv(d), equirect_uv(d), sphere_map_uv(d), octahedral_encode(d));\n",
    );
    out.push_str(
        "    let _ = (equirect_direction(uv), sphere_map_direction(uv), octahedral_decode(uv));\n",
    );
    out.push_str("    let _ = reflect_normalized(d, w);\n}");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bytes(words: &[f32], mode: u8) -> Vec<u8> {
        let mut out: Vec<u8> = words
            .iter()
            .flat_map(|x| x.to_bits().to_le_bytes())
            .collect();
        out.resize(32, 0);
        out.push(mode);
        out
    }

    #[test]
    fn layout_and_printing() {
        let input = bytes(&[1.0, 2.0, 3.0, 0.25, 0.75, 0.0, 1.0, 0.0], 0);
        assert_eq!(
            environment_geometry(&input),
            (Vec3::new(1.0, 2.0, 3.0), Vec2::new(0.25, 0.75), Vec3::Y)
        );
        assert_eq!(check_environment(&input), Ok(()));
        assert!(environment_code(&input).contains("0x3e800000"));
        // Kind 3 with k = 0: exactly the singular direction.
        let singular = bytes(&[], 3 | (16 << 3));
        assert_eq!(environment_geometry(&singular).0, Vec3::NEG_Z);
        assert_eq!(check_environment(&singular), Ok(()));
        // Short input: all zero, every map refuses, nothing fails.
        assert_eq!(check_environment(&[]), Ok(()));
        // Kind 2, k = 0: a corner, z wins.
        let corner = bytes(&[-1.0], 2 | (16 << 3));
        assert_eq!(environment_geometry(&corner).0, Vec3::splat(-1.0));
        assert_eq!(check_environment(&corner), Ok(()));
    }
}
