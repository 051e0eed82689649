//! f64 references for the SLERP family, on slices so one implementation serves 2, 3 and 4
//! dimensions: the exact SLERP of the (normalized) inputs, the angle between directions, and
//! the error measures the tests and the report use.

/// `v` normalized in f64; `None` for zero or non-finite `v`.
#[must_use]
pub fn normalized(v: &[f64]) -> Option<Vec<f64>> {
    let len = dot(v, v).sqrt();
    (len.is_finite() && len > 0.0).then(|| v.iter().map(|x| x / len).collect())
}

/// Dot product.
#[must_use]
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Euclidean length.
#[must_use]
pub fn length(v: &[f64]) -> f64 {
    dot(v, v).sqrt()
}

/// The angle between the directions of `u` and `v` (radians), `2·atan2(|û − v̂|, |û + v̂|)`:
/// accurate at every angle. `None` when either is zero or not finite.
#[must_use]
pub fn angle(u: &[f64], v: &[f64]) -> Option<f64> {
    let (u, v) = (normalized(u)?, normalized(v)?);
    let d: Vec<f64> = u.iter().zip(&v).map(|(x, y)| x - y).collect();
    let s: Vec<f64> = u.iter().zip(&v).map(|(x, y)| x + y).collect();
    Some(2.0 * length(&d).atan2(length(&s)))
}

/// The SLERP of the directions of `a` and `b` at `t`, in f64, for any `t`; `perpendicular` is
/// used when they are exactly opposite. `None` when `a` or `b` is zero or not finite. Inputs
/// within `4·ε` of unit squared length are used as given (as barytex does), others normalized.
///
/// Computed in the arc's orthonormal frame with the perpendicular part of `b` taken from the
/// short one of `b ∓ a` (the same construction as barytex's f32 code, but in f64 from the f32
/// inputs, so its own error, ~1e-16, is far below the f32 errors it measures).
#[must_use]
pub fn slerp(a: &[f64], b: &[f64], t: f64, perpendicular: &[f64]) -> Option<Vec<f64>> {
    let (a, b) = (as_unit(a)?, as_unit(b)?);
    let c = dot(&a, &b);
    let near: Vec<f64> = if c >= 0.0 {
        b.iter().zip(&a).map(|(y, x)| y - x).collect()
    } else {
        b.iter().zip(&a).map(|(y, x)| y + x).collect()
    };
    let k = dot(&a, &near);
    let p: Vec<f64> = near.iter().zip(&a).map(|(n, x)| n - k * x).collect();
    let sin_theta = length(&p);
    let (e, theta) = if sin_theta == 0.0 {
        if c >= 0.0 {
            return Some(a);
        }
        (normalized(perpendicular)?, std::f64::consts::PI)
    } else {
        (
            p.iter().map(|x| x / sin_theta).collect(),
            sin_theta.atan2(c),
        )
    };
    let (st, ct) = (t * theta).sin_cos();
    Some(a.iter().zip(&e).map(|(x, y)| ct * x + st * y).collect())
}

/// `v` as given when its squared length is within `4·ε` (f64) of 1 — barytex's convention, so
/// a reference and the code under test see the same inputs — else [`normalized`].
fn as_unit(v: &[f64]) -> Option<Vec<f64>> {
    if (dot(v, v) - 1.0).abs() <= 4.0 * f64::EPSILON {
        Some(v.to_vec())
    } else {
        normalized(v)
    }
}

/// Angle error and `|length − 1|` of `result` against `reference` (a unit vector).
#[must_use]
pub fn errors(result: &[f64], reference: &[f64]) -> (f64, f64) {
    let angle = angle(result, reference).unwrap_or(f64::INFINITY);
    (angle, (length(result) - 1.0).abs())
}

/// A seeded random unit `Vec3` (uniform on the sphere).
pub fn unit_vec3(rng: &mut crate::seeded::XorShift) -> glam::Vec3 {
    loop {
        let v = rng.vec3_in(-1.0, 1.0);
        let len2 = v.length_squared();
        if (1e-4..=1.0).contains(&len2) {
            return v.normalize();
        }
    }
}

/// A seeded random unit quaternion (uniform over rotations).
pub fn unit_quat(rng: &mut crate::seeded::XorShift) -> glam::Quat {
    loop {
        let v = glam::Vec4::new(
            rng.f32_in(-1.0, 1.0),
            rng.f32_in(-1.0, 1.0),
            rng.f32_in(-1.0, 1.0),
            rng.f32_in(-1.0, 1.0),
        );
        let len2 = v.length_squared();
        if (1e-4..=1.0).contains(&len2) {
            return glam::Quat::from_vec4(v.normalize());
        }
    }
}

/// `n` seeded quaternion pairs whose 4D angle is spread evenly over `[0, max_angle]` (the short
/// path's range is `[0, π/2]`), each with a parameter `t` in `[0, 1]`.
pub fn quat_pairs(
    rng: &mut crate::seeded::XorShift,
    n: usize,
    max_angle: f32,
) -> Vec<(glam::Quat, glam::Quat, f32)> {
    (0..n)
        .map(|i| {
            let a = unit_quat(rng);
            let angle = max_angle * (i as f32 + rng.f32_in(0.0, 1.0)) / n as f32;
            // A rotation by 2φ moves the quaternion by the 4D angle φ.
            let b = a * glam::Quat::from_axis_angle(unit_vec3(rng), 2.0 * angle);
            (a, b.normalize(), rng.f32_in(0.0, 1.0))
        })
        .collect()
}

/// `n` seeded unit-vector pairs whose angle is spread evenly over `[0, max_angle]`, each with a
/// parameter `t` in `[0, 1]`.
pub fn vec3_pairs(
    rng: &mut crate::seeded::XorShift,
    n: usize,
    max_angle: f32,
) -> Vec<(glam::Vec3, glam::Vec3, f32)> {
    (0..n)
        .map(|i| {
            let a = unit_vec3(rng);
            let angle = max_angle * (i as f32 + rng.f32_in(0.0, 1.0)) / n as f32;
            let axis = a
                .cross(unit_vec3(rng))
                .normalize_or(a.any_orthonormal_vector());
            let b = glam::Quat::from_axis_angle(axis, angle) * a;
            (a, b.normalize(), rng.f32_in(0.0, 1.0))
        })
        .collect()
}
