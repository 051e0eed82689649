//! Inverse bilinear interpolation: point → `(α, β)` (Buss 2003, ch. IV, inverting bilinear
//! interpolation).
//!
//! For a fixed `β` the point lies on the segment `s₁(β) s₂(β)` with `s₁ = (1−β)x + βw` and
//! `s₂ = (1−β)y + βz`; requiring `(s₁ − u) × (s₂ − u) = 0` gives `Aβ² + Bβ + C = 0` with
//! `A = (w − x) × (z − y)`, `B = (z − y) × (u − x) − (w − x) × (u − y)`,
//! `C = (u − x) × (u − y)`. (Denisjuk's restatement prints `A = (w − u) × (z − y)`; expanding the cross product
//! shows it is `w − x`.) The roots are taken cancellation-free as `q/A` and `C/q` with
//! `q = −½(B + sign(B)·√(B² − 4AC))`, so a parallelogram (`A = 0`) needs no threshold: its root is
//! `C/q = −C/B`. Then `α` is the projection of `u` onto `s₁s₂`.

use glam::{DVec2, DVec3, Vec2, Vec3};

use crate::InterpError;

/// The preimages `(α, β)` of a point under the bilinear map of a quad.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum InverseBilinear {
    /// Exactly one preimage in `[0, 1]²` — the usual answer for a point in a convex quad.
    Inside(Vec2),
    /// Two distinct preimages in `[0, 1]²`: the quad is non-convex or self-intersecting, so the
    /// map folds over (Buss 2003, Figure IV.13). The first has the smaller `β`.
    Folded(Vec2, Vec2),
    /// No preimage in `[0, 1]²`. Holds the real preimage nearest to the unit square (in the max
    /// norm), or `None` when the point has no real preimage at all.
    Outside(Option<Vec2>),
}

impl InverseBilinear {
    /// The preimage inside `[0, 1]²` (the first one for a folded quad), if any: `None` is a
    /// legitimate answer (the point lies outside the quad), not an error.
    ///
    /// ```
    /// use barytex_interp::inverse_bilinear_2d;
    /// use glam::Vec2;
    ///
    /// let square = [Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y];
    /// let centre = inverse_bilinear_2d(Vec2::splat(0.5), square)?;
    /// assert_eq!(centre.inside(), Some(Vec2::splat(0.5)));
    /// assert_eq!(inverse_bilinear_2d(Vec2::splat(2.0), square)?.inside(), None);
    /// # Ok::<(), barytex_interp::InterpError>(())
    /// ```
    #[must_use]
    pub fn inside(self) -> Option<Vec2> {
        match self {
            Self::Inside(ab) | Self::Folded(ab, _) => Some(ab),
            Self::Outside(_) => None,
        }
    }
}

/// How far outside `[0, 1]` a parameter may be computed and still count as inside: 2⁻²⁷, above
/// the error of a root from coefficients accurate to 2⁻³⁰ for a point on the boundary of a
/// well-shaped quad, and below the half-ulp (2⁻²⁵) that rounding the f32 result near 1 moves it
/// anyway. Next to a double root (a corner of a quad with a short edge) the error outgrows it:
/// `inverse_bilinear_2d` decides exact edge points exactly instead.
const INSIDE_SLACK: f64 = 1.0 / (1u64 << 27) as f64;

/// Invert the bilinear map of the quad `[x, y, z, w]` (corner order as in
/// [`bilinear`](crate::bilinear)) at the point `p`.
///
/// Scale invariant and threshold-free: the quadratic's coefficients are computed from the f32
/// inputs with an exact sign and 2⁻³⁰ relative accuracy (an exact expansion sum of f32 × f32
/// products where plain f64 cancels), the rest in f64, where no f32 input or product overflows or
/// underflows; so a quad of size 1e-30, at offset 1e7 or with corners of wildly different
/// magnitudes behaves like a unit quad. A point exactly on the boundary is inside (decided
/// exactly, at any κ: where the roots miss the unit square, the point on an edge gets that edge's
/// parameters); inside results are clamped to `[0, 1]²`.
///
/// When `s₁(β) = s₂(β)` (an edge of the quad collapsed to a point) and `p` is that point, every
/// `α` maps to it and `α = 0` is returned. At the point where all rulings of a self-intersecting
/// quad cross, every `β` is a preimage: the answer is [`InverseBilinear::Folded`] with the
/// preimages at `β = 0` and `β = 1`.
///
/// # Errors
/// [`InterpError::NonFinite`] for NaN or infinite input; [`InterpError::DegenerateQuad`] exactly
/// when the four corners lie on one line (decided exactly).
///
/// # Accuracy
/// Inside convex quads: within `3e-7·(1 + κ)` in `(α, β)` of the exact preimage of the f32 input
/// point, where `κ` is the quad's condition number (diameter over the smallest distance from a
/// corner to the line of the diagonal it is not on). The bound depends on the shape only (the
/// result is bit-identical under power-of-two scaling), and is loose: measured at most 3.0e-8
/// on 20 000 quads squeezed to κ = 7.5e7 at offsets up to 1e3, and the plain `3e-7` is asserted on
/// the `convex_quad` sample (κ median 12.4, max 7.4e7). A point inside whose f32 rounding
/// leaves the quad gets its nearest preimage outside; a point exactly on an edge (corners
/// included) is `Inside` at any κ, where the roots alone missed the unit square from κ ≈ 9e3 on
/// (tests `inverse_bilinear_round_trip`, `inverse_bilinear_2d_within_its_condition_bound`,
/// `inverse_bilinear_scale_invariant`, `exact_edge_points_next_to_a_double_root_are_inside` and
/// the hard-case table).
///
/// ```
/// use barytex_interp::{inverse_bilinear_2d, InverseBilinear};
/// use glam::Vec2;
/// // Denisjuk, Example 10: (α, β) = (1/2, 1/4) maps to (17/8, 5/8).
/// let quad = [Vec2::new(0.0, 0.0), Vec2::new(4.0, 0.0), Vec2::new(5.0, 3.0), Vec2::new(0.0, 2.0)];
/// let ab = inverse_bilinear_2d(Vec2::new(17.0 / 8.0, 5.0 / 8.0), quad)?.inside().unwrap();
/// assert!((ab - Vec2::new(0.5, 0.25)).length() < 1e-7);
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
pub fn inverse_bilinear_2d(p: Vec2, quad: [Vec2; 4]) -> Result<InverseBilinear, InterpError> {
    if !p.is_finite() {
        return Err(InterpError::NonFinite { what: "point" });
    }
    if !quad.iter().all(|c| c.is_finite()) {
        return Err(InterpError::NonFinite { what: "quad" });
    }
    let [x, y, z, w] = quad;
    let det = crate::determinant::orient2d_det;
    if det(x, y, z) == 0.0 && det(x, z, w) == 0.0 && det(x, y, w) == 0.0 && det(y, z, w) == 0.0 {
        // All four corners on one line (exactly): the map collapses everywhere.
        return Err(InterpError::DegenerateQuad);
    }
    // The quadratic's coefficients from the f32 inputs directly, exact in sign and accurate to
    // 2⁻³⁰ relative: translating by `x` in f64 first would round when magnitudes differ by more
    // than 2²⁹, and can erase a small `A` (and with it a fold's second preimage).
    let cross = crate::determinant::cross_of_differences;
    let coefficients = [
        cross(w, x, z, y),
        crate::determinant::difference_of_crosses([z, y, p, x], [w, x, p, y]),
        cross(p, x, p, y),
    ];
    let origin = x.as_dvec2();
    match solve(
        p.as_dvec2() - origin,
        quad.map(|c| c.as_dvec2() - origin),
        coefficients,
        false,
    ) {
        // Next to a double root (a corner of a quad with a short edge, κ from about 9e3) the
        // roots' error outgrows `INSIDE_SLACK`: the corner w of one such quad came back at
        // α = −9.2e-9. A point exactly on one of the four edges (decided exactly) is inside, at
        // that edge's nearest point.
        Ok(InverseBilinear::Outside(nearest)) => Ok(exact_edge_point(p, quad)
            .map_or(InverseBilinear::Outside(nearest), InverseBilinear::Inside)),
        other => other,
    }
}

/// The `(α, β)` of `p` on the quad's boundary when it lies exactly on one of the four straight
/// edges ([`edges`]), the parameter along the edge
/// by projection in f64 (the differences of f32 values are exact there unless their magnitudes
/// differ by more than 2²⁹).
fn exact_edge_point(p: Vec2, quad: [Vec2; 4]) -> Option<Vec2> {
    edges(quad)
        .into_iter()
        .enumerate()
        .find_map(|(edge, (start, end))| {
            let within = |a: f32, b: f32, v: f32| a.min(b) <= v && v <= a.max(b);
            let on_edge = crate::determinant::orient2d_det(start, end, p) == 0.0
                && within(start.x, end.x, p.x)
                && within(start.y, end.y, p.y);
            if !on_edge {
                return None;
            }
            let d = end.as_dvec2() - start.as_dvec2();
            let den = d.length_squared();
            let t = if den == 0.0 {
                0.0
            } else {
                ((p.as_dvec2() - start.as_dvec2()).dot(d) / den).clamp(0.0, 1.0)
            };
            Some(edge_parameters(edge, t))
        })
        .map(DVec2::as_vec2)
}

/// The quad's four straight edges as `(start, end)`, numbered as [`edge_parameters`] reads
/// them: `α = 0` (x–w), `α = 1` (y–z), `β = 0` (x–y), `β = 1` (w–z).
fn edges<T: Copy>([x, y, z, w]: [T; 4]) -> [(T, T); 4] {
    [(x, w), (y, z), (x, y), (w, z)]
}

/// The `(α, β)` of the point a fraction `t` from the start to the end of edge `edge` of
/// [`edges`].
fn edge_parameters(edge: usize, t: f64) -> DVec2 {
    match edge {
        0 => DVec2::new(0.0, t),
        1 => DVec2::new(1.0, t),
        2 => DVec2::new(t, 0.0),
        _ => DVec2::new(t, 1.0),
    }
}

/// Invert the bilinear map of a quad in 3D, planar or not.
///
/// The corners and the point are projected onto a plane where the quad is convex, then solved as
/// [`inverse_bilinear_2d`]. For a planar quad (or a nearly planar one) that plane is the one
/// spanned by the diagonals; when that projection is not convex, or is convex with a smaller
/// smallest turn, Buss's choice is used: the plane perpendicular to the line joining the
/// midpoints of the diagonals, on which the projection of a non-planar quad is always convex
/// (Denisjuk, Corollary 12), so the inverse is exact for every point on the bilinear surface. A
/// point off the surface gets the preimage of its projection; a point within `2⁻²⁴·|p|` (the
/// f32 rounding of a point on the surface) of an edge is on that edge, so inside.
///
/// # Errors
/// As [`inverse_bilinear_2d`]; [`InterpError::DegenerateQuad`] also when both diagonals are
/// parallel and the quad is planar.
///
/// # Accuracy
/// For a point on the bilinear surface (given as its f32 rounding `p`, edges included) of a quad
/// from planar to saddle-shaped, the answer includes a preimage in `[0, 1]²` that maps back
/// within `1e-6·diameter + 2⁻²⁴·|p|` of the point (the second term is the point's own rounding,
/// which no preimage can undo: it matters only far from the origin) and, on well-shaped quads (a
/// convex quad with one corner lifted by up to its size, any rotation, scales 2⁻⁶⁰ … 2⁶⁰), lies
/// within `2e-5` of the true `(α, β)` (measured: 2.4e-8·diameter and 6.0e-8). A planar convex
/// quad of condition number `κ` (as in [`inverse_bilinear_2d`], of the quad in its plane), at
/// any offset: within `3e-7·(1 + κ)·(1 + |p|/diameter)` of the true `(α, β)` (the rounding of
/// `p`, relative to `|p|`, amplified by the shape; measured at most 0.09 of that on 900 000
/// `convex_quad` draws, κ up to 7e7, edges included). Not the 2D bound: the projection's
/// coefficients are plain f64, without the exact signs of [`inverse_bilinear_2d`] (tests
/// `inverse_bilinear_3d_round_trip_non_planar`, `inverse_bilinear_3d_planar`,
/// `inverse_bilinear_3d_from_planar_to_saddle_at_any_scale`,
/// `rounded_edge_point_of_a_planar_sliver_in_3d_is_inside` and
/// `saddle_point_next_to_a_nearly_folded_corner_of_the_diagonal_projection`).
///
/// ```
/// use barytex_interp::{bilinear, inverse_bilinear_3d, InverseBilinear};
/// use glam::{Vec2, Vec3};
///
/// // A saddle: the corner z is lifted out of the plane of the other three.
/// let quad = [Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 1.0), Vec3::Y];
/// let p = bilinear(quad, 0.25, 0.75); // (α, β) = (¼, ¾)
/// let InverseBilinear::Inside(ab) = inverse_bilinear_3d(p, quad)? else { panic!() };
/// assert!((ab - Vec2::new(0.25, 0.75)).abs().max_element() < 1e-6);
/// // A point past the edge α = 1 has no preimage in the unit square.
/// let outside = inverse_bilinear_3d(Vec3::new(1.5, 0.5, 0.0), quad)?;
/// assert_eq!(outside.inside(), None);
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
pub fn inverse_bilinear_3d(p: Vec3, quad: [Vec3; 4]) -> Result<InverseBilinear, InterpError> {
    if !p.is_finite() {
        return Err(InterpError::NonFinite { what: "point" });
    }
    if !quad.iter().all(|c| c.is_finite()) {
        return Err(InterpError::NonFinite { what: "quad" });
    }
    let origin = quad[0].as_dvec3();
    // How far the f32 rounding of a point on the surface may be from it: half an ulp per
    // component, at most 2⁻²⁴ of its magnitude (2⁻¹⁵⁰ for a subnormal). The 2⁻⁴⁸ term covers
    // that the bound is stated for the exact point, and the f64 rounding of the translation and
    // of the distance to an edge (a few units of 2⁻⁵³ of the coordinates).
    let magnitude = p.as_dvec3().length();
    let corners = quad
        .iter()
        .map(|c| c.as_dvec3().length())
        .fold(0.0, f64::max);
    let rounding =
        F32_HALF_ULP * magnitude + EVALUATION * (magnitude + corners) + SUBNORMAL_HALF_ULP;
    let p = p.as_dvec3() - origin;
    let q = quad.map(|c| c.as_dvec3() - origin);
    match solve_3d(p, q) {
        // The f32 rounding of a point on an edge may fall just outside the quad: on a sliver that
        // is far beyond `INSIDE_SLACK` in the parameters (α = −7e-6 on one of κ ≈ 500). It is on
        // the edge within that rounding, so it is inside, at the edge's nearest point.
        Ok(InverseBilinear::Outside(nearest)) => Ok(nearest_edge_point(p, q, rounding)
            .map_or(InverseBilinear::Outside(nearest), InverseBilinear::Inside)),
        other => other,
    }
}

/// 2⁻²⁴: half an f32 ulp relative to the value (normal range).
const F32_HALF_ULP: f64 = 1.0 / (1u64 << 24) as f64;
/// Half the smallest f32 subnormal (2⁻¹⁵⁰), times √3 rounded up to 2: three components.
const SUBNORMAL_HALF_ULP: f64 = f32::from_bits(1) as f64;
/// 2⁻⁴⁸, relative to the coordinates: the f64 evaluation of a distance (and 2⁻²⁴ of 2⁻²⁴).
const EVALUATION: f64 = 1.0 / (1u64 << 48) as f64;

/// The `(α, β)` of the point on the quad's boundary nearest to `p`, if it is within `tolerance`.
/// The edges of a bilinear surface are straight segments ([`edges`]).
fn nearest_edge_point(p: DVec3, quad: [DVec3; 4], tolerance: f64) -> Option<Vec2> {
    let mut best: Option<(f64, DVec2)> = None;
    for (edge, (start, end)) in edges(quad).into_iter().enumerate() {
        let d = end - start;
        let den = d.length_squared();
        let t = if den == 0.0 {
            0.0
        } else {
            ((p - start).dot(d) / den).clamp(0.0, 1.0)
        };
        let distance = (start + d * t - p).length();
        if distance <= tolerance && best.is_none_or(|(b, _)| distance < b) {
            best = Some((distance, edge_parameters(edge, t)));
        }
    }
    best.map(|(_, ab)| ab.as_vec2())
}

/// [`inverse_bilinear_3d`] for the translated point and corners, before the boundary check.
fn solve_3d(p: DVec3, q: [DVec3; 4]) -> Result<InverseBilinear, InterpError> {
    let diagonal_normal = (q[2] - q[0]).cross(q[3] - q[1]);
    let midpoint_normal = (q[1] + q[3] - q[0] - q[2]) * 0.5;
    let project = |normal: DVec3| {
        let frame = Frame::perpendicular_to(normal)?;
        Some((frame.project(p), q.map(|c| frame.project(c))))
    };
    let solve_in = |(u, projected): (DVec2, [DVec2; 4])| {
        solve(
            u,
            projected,
            coefficients(u, projected),
            is_flat_f64(projected),
        )
    };
    let diagonal = project(diagonal_normal);
    let midpoint = project(midpoint_normal);
    // Of the two planes, the one where the projection is convex with the larger smallest turn
    // (both projections are orthogonal, so their turns compare): the diagonals' plane for a
    // planar or nearly planar quad (it is the quad's own plane; Buss's plane there squashes the
    // quad towards a line), Buss's plane when the diagonals' projection folds or nearly folds at
    // a corner (a saddle whose diagonal projection turns 0.17 at one corner and 8 … 32 at the
    // others lost 3e-6 in β next to that corner). A planar quad that folds in both is answered
    // in its own plane, like `inverse_bilinear_2d` would.
    let margin = |projection: Option<(DVec2, [DVec2; 4])>| {
        projection.and_then(|(_, projected)| convexity_margin(projected))
    };
    match (margin(diagonal), margin(midpoint), diagonal, midpoint) {
        (Some(d), Some(m), _, Some(buss)) if m > d => solve_in(buss),
        (Some(_), _, Some(own), _) | (None, None, Some(own), _) => solve_in(own),
        (None, Some(_), _, Some(buss)) => solve_in(buss),
        _ => Err(InterpError::DegenerateQuad),
    }
}

/// An orthonormal basis of the plane perpendicular to a normal.
struct Frame {
    t1: DVec3,
    t2: DVec3,
}

impl Frame {
    fn perpendicular_to(normal: DVec3) -> Option<Self> {
        let n = normal.try_normalize()?;
        let (t1, t2) = n.any_orthonormal_pair();
        Some(Self { t1, t2 })
    }

    fn project(&self, v: DVec3) -> DVec2 {
        DVec2::new(v.dot(self.t1), v.dot(self.t2))
    }
}

/// The smallest turn of a strictly convex quad (`None` when it is not strictly convex).
fn convexity_margin(q: [DVec2; 4]) -> Option<f64> {
    let turns: [f64; 4] =
        core::array::from_fn(|i| (q[(i + 1) % 4] - q[i]).perp_dot(q[(i + 2) % 4] - q[(i + 1) % 4]));
    let convex = turns.iter().all(|&t| t > 0.0) || turns.iter().all(|&t| t < 0.0);
    convex.then(|| turns.iter().fold(f64::INFINITY, |m, t| m.min(t.abs())))
}

/// The coefficients `[A, B, C]` of the quadratic in β, in plain f64 (for the projected 3D quad).
fn coefficients(u: DVec2, [x, y, z, w]: [DVec2; 4]) -> [f64; 3] {
    [
        (w - x).perp_dot(z - y),
        (z - y).perp_dot(u - x) - (w - x).perp_dot(u - y),
        (u - x).perp_dot(u - y),
    ]
}

/// Whether the (projected) quad's corners are on one line, in plain f64.
fn is_flat_f64([x, y, z, w]: [DVec2; 4]) -> bool {
    [(x, y, z), (x, z, w), (x, y, w), (y, z, w)]
        .iter()
        .all(|&(a, b, c)| (b - a).perp_dot(c - a) == 0.0)
}

/// The solver proper, in f64, with the quad translated so that `x` is near the origin, the
/// quadratic's coefficients `[A, B, C]` given, and whether the quad is flat decided by the caller
/// (exactly for f32 input).
fn solve(
    u: DVec2,
    [x, y, z, w]: [DVec2; 4],
    [a, b, c]: [f64; 3],
    flat: bool,
) -> Result<InverseBilinear, InterpError> {
    let quad = [x, y, z, w];
    let size = quad
        .iter()
        .map(|corner| (*corner - x).abs().max_element())
        .fold(0.0, f64::max);
    let mut roots = if a == 0.0 && b == 0.0 {
        if c != 0.0 {
            return Ok(InverseBilinear::Outside(None));
        }
        // Every β solves the equation: either the quad is flat (all corners on one line) or `u`
        // is the point where all rulings of a self-intersecting quad cross; then the rulings at
        // β = 0 and β = 1 stand for the whole family.
        if flat {
            return Err(InterpError::DegenerateQuad);
        }
        [0.0, 1.0]
    } else {
        let disc = b * b - 4.0 * a * c;
        if disc < 0.0 || !disc.is_finite() {
            return Ok(InverseBilinear::Outside(None));
        }
        let sign_b = if b < 0.0 { -1.0 } else { 1.0 };
        let q = -0.5 * (b + sign_b * crate::math::sqrt(disc));
        [q / a, c / q]
    };
    if roots[1] < roots[0] {
        roots.swap(0, 1);
    }
    let mut inside: [Option<DVec2>; 2] = [None; 2];
    let mut nearest: Option<(f64, DVec2)> = None;
    for (slot, &beta) in roots.iter().enumerate() {
        if !beta.is_finite() || (slot == 1 && roots[0] == beta) {
            continue;
        }
        let segment = ruling(quad, beta);
        let ab = DVec2::new(alpha_on(u, segment), beta);
        // A root of the quadratic is a preimage only if it maps back to `u`: where
        // `s₁(β) = s₂(β)` the equation `(s₁ − u) × (s₂ − u) = 0` holds for every `u`, and on
        // nearly flat quads rounding can produce such spurious roots.
        if !maps_to(segment, ab, u, size) {
            continue;
        }
        let distance = distance_outside_unit_square(ab);
        if distance <= INSIDE_SLACK {
            inside[slot] = Some(ab.clamp(DVec2::ZERO, DVec2::ONE));
        } else if nearest.is_none_or(|(d, _)| distance < d) {
            nearest = Some((distance, ab));
        }
    }
    let f32_pair = |v: DVec2| v.as_vec2();
    Ok(match inside {
        [Some(first), Some(second)] if f32_pair(first) != f32_pair(second) => {
            InverseBilinear::Folded(f32_pair(first), f32_pair(second))
        }
        [Some(only), _] => InverseBilinear::Inside(f32_pair(only)),
        [None, Some(only)] => InverseBilinear::Inside(f32_pair(only)),
        [None, None] => InverseBilinear::Outside(nearest.map(|(_, ab)| f32_pair(ab))),
    })
}

/// The ruling of the quad at `β`: the segment `s₁(β) s₂(β)` with `s₁ = (1−β)x + βw` and
/// `s₂ = (1−β)y + βz`.
fn ruling([x, y, z, w]: [DVec2; 4], beta: f64) -> (DVec2, DVec2) {
    (x + (w - x) * beta, y + (z - y) * beta)
}

/// How far, relative to the quad's size, a candidate may map from `u`: 2⁻²⁶, a quarter of what
/// rounding the answer to f32 moves it, and far above f64 rounding of well-posed roots.
const RESIDUAL_TOLERANCE: f64 = 1.0 / (1u64 << 26) as f64;

/// Whether `(α, β)`, with `(s1, s2)` the ruling at β, maps back to `u`, relative to the quad's
/// size (and to `|(α, β)|` for preimages far outside the unit square).
fn maps_to((s1, s2): (DVec2, DVec2), ab: DVec2, u: DVec2, size: f64) -> bool {
    let back = s1 + (s2 - s1) * ab.x;
    let scale = size * (1.0 + ab.abs().max_element());
    (back - u).abs().max_element() <= RESIDUAL_TOLERANCE * scale
}

/// α by projecting `u` onto the ruling `s₁ s₂`; 0 when it collapses to a point.
fn alpha_on(u: DVec2, (s1, s2): (DVec2, DVec2)) -> f64 {
    let d = s2 - s1;
    let den = d.length_squared();
    if den == 0.0 {
        0.0
    } else {
        (u - s1).dot(d) / den
    }
}

fn distance_outside_unit_square(ab: DVec2) -> f64 {
    let below = (-ab).max(DVec2::ZERO);
    let above = (ab - DVec2::ONE).max(DVec2::ZERO);
    below.max(above).max_element()
}
