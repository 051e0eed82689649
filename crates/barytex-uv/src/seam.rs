//! Seam repair: per-triangle texture coordinates that do not straddle the `u` wrap of a periodic
//! mapping (Figure V.4 of Buss, *3D Computer Graphics*, 2003), and pole handling for sphere
//! triangles.
//!
//! A periodic mapping ([`Cylindrical`](crate::mappings::Cylindrical),
//! [`Spherical`](crate::mappings::Spherical), [`Torus`](crate::mappings::Torus)) gives `u` in
//! `[0, 1)`. A triangle crossing the seam gets, say, `u = 0.9` and `u = 0.1`, and interpolating
//! between them sweeps back across 80 % of the texture instead of the 20 % the surface covers.
//! The fix shifts `u` by whole turns so the triangle's `u` range is the shortest arc of the
//! circle holding its vertices: `0.9 → 0.1` becomes `0.9 → 1.1` (with a repeating sampler,
//! `1.1` reads the texel of `0.1`).

use glam::Vec2;

/// `us` shifted by whole turns so they cover the shortest arc of the unit circle holding them,
/// the arc starting at the first vertex after the largest gap (which keeps its value). Leaves
/// the values alone if their range is already at most 1/2, or if any is non-finite.
fn unwrap_u(us: &mut [f32]) {
    if us.iter().any(|u| !u.is_finite()) || us.len() < 2 {
        return;
    }
    let (lo, hi) = us
        .iter()
        .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &u| {
            (lo.min(u), hi.max(u))
        });
    if f64::from(hi) - f64::from(lo) <= 0.5 {
        return;
    }
    // Span of the arc starting at each vertex, in f64 turns.
    let offset = |from: f32, to: f32| (f64::from(to) - f64::from(from)).rem_euclid(1.0);
    let span = |start: f32| us.iter().map(|&u| offset(start, u)).fold(0.0, f64::max);
    let mut best = us[0];
    for &u in us.iter() {
        if span(u) < span(best) {
            best = u;
        }
    }
    if span(best) >= f64::from(hi) - f64::from(lo) {
        return;
    }
    for u in us.iter_mut() {
        // A whole number of turns, so the shifted value is `u + k` rounded once.
        let k = (f64::from(best) + offset(best, *u) - f64::from(*u)).round();
        #[allow(clippy::cast_possible_truncation)]
        let shifted = (f64::from(*u) + k) as f32;
        *u = shifted;
    }
}

/// The triangle's texture coordinates with `u` shifted by whole turns (±1 for inputs in
/// `[0, 1)`) so that it does not straddle the `u = 0/1` seam: its `u` range becomes the shortest
/// arc holding the three values. `v` is never changed.
///
/// A triangle whose `u` range is already at most 1/2 is returned unchanged, as is one with a
/// non-finite `u`. The result spans at most 1/2 in `u` whenever the vertices fit in half a turn
/// (any triangle of a mesh fine enough to resolve the surface); otherwise it spans the
/// shortest arc (at most 2/3).
///
/// ```
/// use barytex_uv::seam::repair_seam;
/// use glam::Vec2;
///
/// // Buss (2003), Figure V.4: a patch whose s runs 0.9 → 0.1 must run 0.9 → 1.1.
/// let fixed = repair_seam([Vec2::new(0.9, 0.2), Vec2::new(0.1, 0.2), Vec2::new(0.9, 0.4)]);
/// assert_eq!(fixed, [Vec2::new(0.9, 0.2), Vec2::new(1.1, 0.2), Vec2::new(0.9, 0.4)]);
/// ```
#[must_use]
pub fn repair_seam(uvs: [Vec2; 3]) -> [Vec2; 3] {
    let mut us = uvs.map(|uv| uv.x);
    unwrap_u(&mut us);
    core::array::from_fn(|i| Vec2::new(us[i], uvs[i].y))
}

/// [`repair_seam`] for a triangle of a sphere (or any mapping with poles at `v = 0` and
/// `v = 1`): a vertex at a pole (`v ≤ 0` or `v ≥ 1`, exactly: the spherical mapping has no `u`
/// on the axis and returns `None` there, so whoever builds the mesh writes the pole row's `v`)
/// has no meaningful `u`, so the other
/// vertices are repaired among themselves and the pole vertex takes the mean of their `u`
/// (the pole's texel row is then sampled under the triangle rather than across the whole
/// texture). With two vertices at poles the third one's `u` is used; with three, or a
/// non-finite `v`, the triangle is only seam-repaired.
///
/// ```
/// use barytex_uv::seam::repair_sphere_triangle;
/// use glam::Vec2;
///
/// // A cap triangle across the seam: the pole vertex takes u = (0.95 + 1.05)/2.
/// let fixed = repair_sphere_triangle([Vec2::new(0.3, 0.0), Vec2::new(0.95, 0.1), Vec2::new(0.05, 0.1)]);
/// assert!((fixed[0].x - 1.0).abs() < 1e-6 && (fixed[2].x - 1.05).abs() < 1e-6);
/// ```
#[must_use]
pub fn repair_sphere_triangle(uvs: [Vec2; 3]) -> [Vec2; 3] {
    let at_pole = uvs.map(|uv| uv.y <= 0.0 || uv.y >= 1.0);
    let poles = at_pole.iter().filter(|&&p| p).count();
    if poles == 0 || poles == 3 || uvs.iter().any(|uv| !uv.y.is_finite()) {
        return repair_seam(uvs);
    }
    let mut us: Vec<f32> = (0..3).filter(|&i| !at_pole[i]).map(|i| uvs[i].x).collect();
    unwrap_u(&mut us);
    #[allow(clippy::cast_possible_truncation)]
    let mean = (us.iter().map(|&u| f64::from(u)).sum::<f64>() / us.len() as f64) as f32;
    let mut repaired = us.into_iter();
    core::array::from_fn(|i| {
        let u = if at_pole[i] {
            mean
        } else {
            repaired.next().unwrap_or(mean)
        };
        Vec2::new(u, uvs[i].y)
    })
}
