//! Invariant checks of `orient3d` and the 3D convex hull, shared by property tests and the fuzz
//! target: each returns `Err(description)` rather than panicking.

use barytex_interp::{ConvexHull3d, HullError3d, Orientation, convex_hull_3d, orient3d};
use glam::Vec3;
use num_bigint::BigInt;
use num_traits::{Signed, Zero};

use crate::exact;

/// `orient3d(a, b, c, d)` is an error exactly for non-finite input, else the exact rational sign,
/// and it is antisymmetric (swapping `a` and `b` flips it, cycling `b, c, d` keeps it).
///
/// # Errors
/// The first violated property.
pub fn check_orient3d(a: Vec3, b: Vec3, c: Vec3, d: Vec3) -> Result<(), String> {
    let got = orient3d(a, b, c, d);
    if !(a.is_finite() && b.is_finite() && c.is_finite() && d.is_finite()) {
        return match got {
            Err(_) => Ok(()),
            Ok(o) => Err(format!(
                "orient3d({a:?}, {b:?}, {c:?}, {d:?}) = {o:?} for non-finite input"
            )),
        };
    }
    let want = exact::orient3d_sign(a, b, c, d);
    match got {
        Ok(o) if o.sign() == want => {}
        other => {
            return Err(format!(
                "orient3d({a:?}, {b:?}, {c:?}, {d:?}) = {other:?}, exact sign {want}"
            ));
        }
    }
    let swapped = orient3d(b, a, c, d).map(Orientation::sign).ok();
    let cycled = orient3d(a, c, d, b).map(Orientation::sign).ok();
    if swapped != Some(-want) || cycled != Some(want) {
        return Err(format!(
            "orient3d({a:?}, {b:?}, {c:?}, {d:?}) not antisymmetric: sign {want}, swapped {swapped:?}, cycled {cycled:?}"
        ));
    }
    Ok(())
}

/// Up to this many points, [`check_convex_hull_3d`] also compares the vertex set with the
/// brute-force exact reference [`reference_hull_vertices`] (`O(n⁴)` rational determinants).
pub const BRUTE_FORCE_MAX_POINTS: usize = 12;

/// The 3D hull invariants: non-finite input is rejected naming its first bad point; otherwise
/// the hull passes `ConvexHull3d::validate` (every point on the inner side of every facet,
/// closed, convex, Euler, strict corners), a second call gives the identical hull, and for at most
/// [`BRUTE_FORCE_MAX_POINTS`] points its vertex set equals [`reference_hull_vertices`].
///
/// # Errors
/// The first violated invariant.
pub fn check_convex_hull_3d(points: &[Vec3]) -> Result<(), String> {
    let got = convex_hull_3d(points);
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return match got {
            Err(HullError3d::NonFinite { index: i }) if i == index => Ok(()),
            other => Err(format!(
                "point {index} is not finite, but convex_hull_3d answered {other:?}"
            )),
        };
    }
    let hull = got.map_err(|e| format!("convex_hull_3d failed on finite input: {e}"))?;
    hull.validate(points)
        .map_err(|defect| format!("invalid hull {hull:?}: {defect}"))?;
    let again = convex_hull_3d(points).map_err(|e| e.to_string())?;
    if again != hull {
        return Err(format!("not deterministic: {hull:?} then {again:?}"));
    }
    if points.len() <= BRUTE_FORCE_MAX_POINTS {
        let mut got_vertices = hull.vertices().to_vec();
        got_vertices.sort_unstable();
        let want = reference_hull_vertices(points);
        if got_vertices != want {
            return Err(format!(
                "hull vertices {got_vertices:?}, brute-force reference {want:?} ({hull:?})"
            ));
        }
    }
    Ok(())
}

/// Integers, not rationals: the brute force scales every coordinate by `2¹⁴⁹` (the f32 grid),
/// so every determinant is an exact integer without any gcd normalisation.
type Z = BigInt;
type P3 = [Z; 3];

/// `x · 2¹⁴⁹`, exactly an integer for every finite f32.
fn scaled_integer(x: f32) -> Z {
    let bits = x.to_bits();
    let exponent = ((bits >> 23) & 0xff) as i32;
    let fraction = bits & 0x7f_ffff;
    let (mantissa, shift) = if exponent == 0 {
        (fraction, 0)
    } else {
        (fraction | 0x80_0000, exponent - 1)
    };
    let magnitude = Z::from(mantissa) << shift as usize;
    if bits >> 31 == 1 {
        -magnitude
    } else {
        magnitude
    }
}

fn sub(a: &P3, b: &P3) -> P3 {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

fn cross(a: &P3, b: &P3) -> P3 {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn dot(a: &P3, b: &P3) -> Z {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

fn is_zero(v: &P3) -> bool {
    v.iter().all(Zero::is_zero)
}

/// The strict corners of the hull of finite `points`, by brute force in exact integers, sorted;
/// of equal points the lowest index. Independent of `convex_hull_3d`: a triple spans a supporting
/// plane when every point is on one side of it, and a point is a strict corner when the
/// supporting planes through it have normals of rank 3. Coplanar inputs get an apex off their
/// plane (a strict corner of the pyramid that is not an input point); collinear ones are answered
/// by their lexicographic extremes. `O(n⁴)`: for small inputs only.
///
/// # Panics
/// On non-finite input.
#[must_use]
pub fn reference_hull_vertices(points: &[Vec3]) -> Vec<usize> {
    // Distinct points, each the lowest index of its value.
    let mut reps: Vec<usize> = Vec::new();
    for (i, p) in points.iter().enumerate() {
        if !reps.iter().any(|&r| points[r] == *p) {
            reps.push(i);
        }
    }
    let mut qs: Vec<P3> = reps
        .iter()
        .map(|&i| [points[i].x, points[i].y, points[i].z].map(scaled_integer))
        .collect();
    if reps.len() <= 2 {
        return reps;
    }
    // A non-collinear triple, if any.
    let mut triple = None;
    'search: for j in 1..qs.len() {
        for k in j + 1..qs.len() {
            let n = cross(&sub(&qs[j], &qs[0]), &sub(&qs[k], &qs[0]));
            if !is_zero(&n) {
                triple = Some((j, k, n));
                break 'search;
            }
        }
    }
    let Some((_, _, normal)) = triple else {
        // Collinear: the lexicographic extremes.
        let key = |i: usize| (points[i].x, points[i].y, points[i].z);
        let lo = reps.iter().copied().min_by(|&a, &b| {
            key(a)
                .partial_cmp(&key(b))
                .unwrap_or(std::cmp::Ordering::Equal)
        });
        let hi = reps.iter().copied().max_by(|&a, &b| {
            key(a)
                .partial_cmp(&key(b))
                .unwrap_or(std::cmp::Ordering::Equal)
        });
        let mut ends: Vec<usize> = lo.into_iter().chain(hi).collect();
        ends.sort_unstable();
        return ends;
    };
    let coplanar = qs.iter().all(|p| dot(&normal, &sub(p, &qs[0])).is_zero());
    let apex = coplanar.then(|| {
        // The centroid plus the normal, in integers: scaling every point by n makes the
        // centroid the (unscaled) sum.
        let apex: P3 =
            std::array::from_fn(|k| qs.iter().map(|p| p[k].clone()).sum::<Z>() + &normal[k]);
        let count = Z::from(qs.len());
        for p in &mut qs {
            for c in p.iter_mut() {
                *c *= &count;
            }
        }
        apex
    });
    let real = qs.len();
    qs.extend(apex);
    let n = qs.len();
    // Supporting planes: outward normals of triples with every point on one side.
    let mut supports: Vec<(usize, usize, usize, P3)> = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                let nrm = cross(&sub(&qs[j], &qs[i]), &sub(&qs[k], &qs[i]));
                if is_zero(&nrm) {
                    continue;
                }
                let sides: Vec<Z> = qs.iter().map(|p| dot(&nrm, &sub(p, &qs[i]))).collect();
                if sides.iter().all(|s| !s.is_positive()) {
                    supports.push((i, j, k, nrm));
                } else if sides.iter().all(|s| !s.is_negative()) {
                    supports.push((i, j, k, nrm.map(|c| -c)));
                }
            }
        }
    }
    let mut corners = Vec::new();
    for (p, &rep) in reps.iter().enumerate().take(real) {
        let normals: Vec<&P3> = supports
            .iter()
            .filter(|(i, j, k, _)| *i == p || *j == p || *k == p)
            .map(|(_, _, _, nrm)| nrm)
            .collect();
        let full_rank = normals.iter().enumerate().any(|(x, a)| {
            normals[x + 1..].iter().enumerate().any(|(y, b)| {
                let ab = cross(a, b);
                !is_zero(&ab) && normals[x + y + 2..].iter().any(|c| !dot(&ab, c).is_zero())
            })
        });
        if full_rank {
            corners.push(rep);
        }
    }
    corners.sort_unstable();
    corners
}

/// The indices sorted, for comparing hull vertex sets.
#[must_use]
pub fn sorted_vertices(hull: &ConvexHull3d) -> Vec<usize> {
    let mut v = hull.vertices().to_vec();
    v.sort_unstable();
    v
}
