//! As-rigid-as-possible refinement (L. Liu, L. Zhang, Y. Xu, C. Gotsman, S. J. Gortler, "A
//! local/global approach to mesh parameterization", *Computer Graphics Forum* 27(5), 2008).
//!
//! The energy `Σ_T A_T ‖J_T − R_T‖²_F` (§3, eq. 3, with the "ARAP" choice of `R_T`: the rotation
//! closest to the triangle's Jacobian `J_T`) is lowered by alternating a local step (each `R_T`
//! from the current `J_T`, in closed form for 2×2) and a global step (a Poisson solve with the
//! cotangent stiffness matrix, one vertex pinned).
//!
//! A global step can fold triangles. Every candidate is therefore checked exactly
//! ([`crate::is_positively_oriented`]); a step that would add a flip or raise the energy is
//! halved towards the current iterate (up to [`BACKTRACKS`] times) and otherwise rejected, which
//! ends the refinement. The result never has more flips than the start — from a flip-free start
//! (LSCM, or a mean-value embedding) it stays flip-free.

use glam::{DVec2, DVec3};

use crate::UnwrapError;
use crate::check::count_flips;
use crate::geometry::{doubled_area_2d, flatten};
use crate::sparse::{CsrMatrix, SolveControl, Triplets, solve_spd, try_factor};
use crate::topology::NONE;

/// Halvings of a rejected step before giving up.
pub const BACKTRACKS: u32 = 8;

/// The relative residual of each global step's solve.
const ARAP_TOLERANCE: f64 = 1e-8;

/// The relative energy decrease below which the iterations stop early.
const STALL: f64 = 1e-4;

/// How an ARAP refinement went.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ArapReport {
    /// Accepted iterations.
    pub iterations: u32,
    /// The ARAP energy `Σ A ‖J − R‖²` before (after rescaling the start to the surface's area).
    pub energy_before: f64,
    /// The energy after.
    pub energy_after: f64,
    /// Flipped (or degenerate) triangles before, decided exactly.
    pub flips_before: usize,
    /// Flipped triangles after: never more than before.
    pub flips_after: usize,
}

/// Per-triangle data: area and the gradients of the three hat functions in the flat frame.
struct Element {
    area: f64,
    grad: [DVec2; 3],
}

fn element(p: [DVec3; 3]) -> Option<Element> {
    let q = flatten(p);
    let dt = doubled_area_2d(q);
    if !(dt > 0.0 && dt.is_finite()) {
        return None;
    }
    let m = glam::DMat2::from_cols(q[1] - q[0], q[2] - q[0])
        .inverse()
        .transpose();
    let (g1, g2) = (m.x_axis, m.y_axis);
    Some(Element {
        area: 0.5 * dt,
        grad: [-g1 - g2, g1, g2],
    })
}

/// The rotation closest to the Jacobian with gradient rows `gu`, `gv`, as its rows.
fn closest_rotation(gu: DVec2, gv: DVec2) -> (DVec2, DVec2) {
    let theta = (gv.x - gu.y).atan2(gu.x + gv.y);
    let (s, c) = theta.sin_cos();
    (DVec2::new(c, -s), DVec2::new(s, c))
}

fn gradients(e: &Element, t: &[u32; 3], uvs: &[DVec2]) -> (DVec2, DVec2) {
    let mut gu = DVec2::ZERO;
    let mut gv = DVec2::ZERO;
    for k in 0..3 {
        let uv = uvs[t[k] as usize];
        gu += uv.x * e.grad[k];
        gv += uv.y * e.grad[k];
    }
    (gu, gv)
}

fn energy(elements: &[(usize, Element)], triangles: &[[u32; 3]], uvs: &[DVec2]) -> f64 {
    elements
        .iter()
        .map(|(t, e)| {
            let (gu, gv) = gradients(e, &triangles[*t], uvs);
            let (ru, rv) = closest_rotation(gu, gv);
            e.area * ((gu - ru).length_squared() + (gv - rv).length_squared())
        })
        .sum()
}

/// Refines `uvs` (a parameterization of `triangles` over `positions`) by at most
/// `max_iterations` ARAP local/global steps, never adding a flip. The start is first scaled so
/// its uv area equals the surface's (ARAP's minimum is near that scale).
///
/// ```
/// use barytex_unwrap::{arap_refine, lscm};
/// use glam::DVec3;
///
/// // A bent strip: LSCM, then ARAP.
/// let p: Vec<DVec3> = (0..10)
///     .flat_map(|i| {
///         let x = i as f64 / 3.0;
///         [DVec3::new(x, 0.0, x * x / 4.0), DVec3::new(x, 1.0, x * x / 4.0)]
///     })
///     .collect();
/// let t: Vec<[u32; 3]> = (0..9u32)
///     .flat_map(|i| [[2 * i, 2 * i + 2, 2 * i + 3], [2 * i, 2 * i + 3, 2 * i + 1]])
///     .collect();
/// let mut uvs = lscm(&p, &t).expect("a disk").uvs;
/// let r = arap_refine(&p, &t, &mut uvs, 20).expect("fits in memory");
/// assert_eq!(r.flips_after, 0);
/// assert!(r.energy_after <= r.energy_before);
/// ```
///
/// # Accuracy
/// Exact on flips: `flips_after ≤ flips_before`, both counted by exact `orient2d`, and the energy
/// never rises (`lscm_arap.rs::arap_never_increases_flips`, from LSCM and from scrambled starts).
/// On a developable surface (a bent strip) started from a mean-value embedding on a circle, the
/// energy drops below 1% of the start and every edge keeps its length within 2%
/// (`lscm_arap.rs::arap_recovers_the_isometry_of_a_developable_strip`).
///
/// # Errors
/// [`UnwrapError::OutOfMemory`] when the matrix does not fit; [`UnwrapError::IndexOutOfRange`]
/// for a triangle naming a vertex past `positions` or `uvs`.
pub fn arap_refine(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
    uvs: &mut [DVec2],
    max_iterations: u32,
) -> Result<ArapReport, UnwrapError> {
    let n = positions.len().min(uvs.len());
    for (t, tri) in triangles.iter().enumerate() {
        if let Some(&index) = tri.iter().find(|&&v| v as usize >= n) {
            return Err(UnwrapError::IndexOutOfRange {
                triangle: t as u32,
                index,
                vertices: n as u32,
            });
        }
    }
    let elements: Vec<(usize, Element)> = triangles
        .iter()
        .enumerate()
        .filter_map(|(t, tri)| element(tri.map(|v| positions[v as usize])).map(|e| (t, e)))
        .collect();
    let flips_start = count_flips(uvs, triangles);
    rescale_to_surface_area(&elements, triangles, uvs, flips_start);
    let mut report = ArapReport {
        flips_before: count_flips(uvs, triangles),
        energy_before: energy(&elements, triangles, uvs),
        ..ArapReport::default()
    };
    report.flips_after = report.flips_before;
    report.energy_after = report.energy_before;
    // Unknowns: every used vertex but the pinned one.
    let mut used = vec![false; n];
    for (t, _) in &elements {
        for &v in &triangles[*t] {
            used[v as usize] = true;
        }
    }
    let Some(pin) = used.iter().position(|&u| u) else {
        return Ok(report);
    };
    let mut index = vec![NONE; n];
    let mut unknowns = 0usize;
    for v in 0..n {
        if used[v] && v != pin {
            index[v] = unknowns as u32;
            unknowns += 1;
        }
    }
    if unknowns == 0 || max_iterations == 0 {
        return Ok(report);
    }
    let mut t = Triplets::new(unknowns, 9 * elements.len())?;
    // Stiffness entries coupling a free vertex to the pin, moved to the right-hand side.
    let mut pin_coupling = vec![0.0; unknowns];
    for (ti, e) in &elements {
        let tri = &triangles[*ti];
        for a in 0..3 {
            let ia = index[tri[a] as usize];
            if ia == NONE {
                continue;
            }
            for b in 0..3 {
                let k = e.area * e.grad[a].dot(e.grad[b]);
                let ib = index[tri[b] as usize];
                if ib == NONE {
                    pin_coupling[ia as usize] += k;
                } else {
                    t.add(ia as usize, ib as usize, k);
                }
            }
        }
    }
    let stiffness = CsrMatrix::from_triplets(t)?;
    // The stiffness matrix never changes: factor it once for every global step.
    let mut coords = vec![DVec3::ZERO; unknowns];
    for v in 0..n {
        if index[v] != NONE {
            coords[index[v] as usize] = positions[v];
        }
    }
    let factor = try_factor(&stiffness, &coords);
    // Each global step only has to lower the energy (the acceptance test checks it exactly), so
    // it is solved to 1e-8 from a warm start, not to the embeddings' 1e-12.
    let control = SolveControl::for_size(unknowns, ARAP_TOLERANCE);
    let mut x = [vec![0.0; unknowns], vec![0.0; unknowns]];
    let mut candidate = uvs.to_vec();
    for _ in 0..max_iterations {
        // Local step: the rotations; global step: the Poisson solve towards them.
        let mut rhs = [vec![0.0; unknowns], vec![0.0; unknowns]];
        for (ti, e) in &elements {
            let tri = &triangles[*ti];
            let (gu, gv) = gradients(e, tri, uvs);
            let (ru, rv) = closest_rotation(gu, gv);
            for k in 0..3 {
                let i = index[tri[k] as usize];
                if i != NONE {
                    rhs[0][i as usize] += e.area * e.grad[k].dot(ru);
                    rhs[1][i as usize] += e.area * e.grad[k].dot(rv);
                }
            }
        }
        let pinned = uvs[pin];
        for axis in 0..2 {
            for (i, r) in rhs[axis].iter_mut().enumerate() {
                *r -= pin_coupling[i] * pinned[axis];
            }
            for v in 0..n {
                if index[v] != NONE {
                    x[axis][index[v] as usize] = uvs[v][axis];
                }
            }
            let _ = solve_spd(
                &stiffness,
                factor.as_ref(),
                &rhs[axis],
                &mut x[axis],
                control,
            );
        }
        // Accept the step, or a shorter one, only without new flips and with lower energy.
        let mut step = 1.0;
        let mut accepted = None;
        for _ in 0..=BACKTRACKS {
            for v in 0..n {
                let i = index[v];
                candidate[v] = if i == NONE {
                    uvs[v]
                } else {
                    let target = DVec2::new(x[0][i as usize], x[1][i as usize]);
                    uvs[v] + step * (target - uvs[v])
                };
            }
            let flips = count_flips(&candidate, triangles);
            let e = energy(&elements, triangles, &candidate);
            if flips <= report.flips_after && e < report.energy_after {
                accepted = Some((flips, e));
                break;
            }
            step *= 0.5;
        }
        let Some((flips, e)) = accepted else { break };
        uvs.copy_from_slice(&candidate[..uvs.len()]);
        let decrease = (report.energy_after - e) / report.energy_after.max(f64::MIN_POSITIVE);
        report.iterations += 1;
        report.flips_after = flips;
        report.energy_after = e;
        if decrease < STALL {
            break;
        }
    }
    Ok(report)
}

/// Scales `uvs` about the origin so the uv area equals the surface area, unless that would add
/// a flip (rounding can, on a nearly degenerate triangle).
fn rescale_to_surface_area(
    elements: &[(usize, Element)],
    triangles: &[[u32; 3]],
    uvs: &mut [DVec2],
    flips: usize,
) {
    let surface: f64 = elements.iter().map(|(_, e)| e.area).sum();
    let uv_area: f64 = triangles
        .iter()
        .map(|t| 0.5 * doubled_area_2d(t.map(|v| uvs[v as usize])))
        .sum();
    let s = (surface / uv_area).sqrt();
    if !(s.is_finite() && s > 0.0) {
        return;
    }
    let scaled: Vec<DVec2> = uvs.iter().map(|&u| u * s).collect();
    if count_flips(&scaled, triangles) <= flips && scaled.iter().all(|u| u.is_finite()) {
        uvs.copy_from_slice(&scaled);
    }
}
