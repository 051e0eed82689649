//! The SLERP family: exact slerp and its approximations against glam and nalgebra, error as the
//! 4D angle to an f64 SLERP of the same inputs (the rotation angle error is twice it), and the
//! uneven spacing of renormalized normals.

use std::fmt::Write as _;

use barytex_interp::hard_cases::vector_pairs;
use barytex_interp::{
    NormalInterpolation, QuatInterpolation, interpolate_normal, renormalize_spacing_error, slerp,
};
use barytex_testkit::seeded::XorShift;
use barytex_testkit::sphere;
use glam::{Quat, Vec3};
use nalgebra::{Quaternion, Unit, UnitQuaternion, Vector3};

use super::{ErrorStats, Row, Section, Settings, Table};
use crate::timing::ns_per_call;

type QuatInput = (Quat, Quat, f32);
type VecInput = (Vec3, Vec3, f32);
type QuatMethod = fn(Quat, Quat, f32) -> Quat;
type VecMethod = fn(Vec3, Vec3, f32) -> Vec3;

fn f64s<const N: usize>(v: [f32; N]) -> Vec<f64> {
    v.iter().map(|&x| f64::from(x)).collect()
}

/// 4D angle and |length − 1| of `r` against the short-path SLERP of `(a, b, t)`.
fn quat_errors((a, b, t): QuatInput, r: Quat) -> (f64, f64) {
    let b = if a.dot(b) < 0.0 { -b } else { b };
    let reference = sphere::slerp(
        &f64s(a.to_array()),
        &f64s(b.to_array()),
        f64::from(t),
        &[1.0, 0.0, 0.0, 0.0],
    )
    .unwrap_or_default();
    sphere::errors(&f64s(r.to_array()), &reference)
}

fn vec_errors((a, b, t): VecInput, r: Vec3) -> (f64, f64) {
    let reference = sphere::slerp(
        &f64s(a.to_array()),
        &f64s(b.to_array()),
        f64::from(t),
        &f64s(a.any_orthonormal_vector().to_array()),
    )
    .unwrap_or_default();
    sphere::errors(&f64s(r.to_array()), &reference)
}

fn to_nalgebra(q: Quat) -> UnitQuaternion<f32> {
    UnitQuaternion::new_unchecked(Quaternion::new(q.w, q.x, q.y, q.z))
}

fn nalgebra_quat(q: UnitQuaternion<f32>) -> Quat {
    Quat::from_xyzw(q.i, q.j, q.k, q.w)
}

fn unit3(v: Vec3) -> Unit<Vector3<f32>> {
    Unit::new_unchecked(Vector3::new(v.x, v.y, v.z))
}

/// A row from a method's results, its time and its angle bound; the max length error goes to
/// `extra`.
fn row(
    name: String,
    is_default: bool,
    ns: f64,
    errors: &[(f64, f64)],
    bar: Option<f64>,
    extra: &mut Vec<String>,
) -> Row {
    let non_finite = errors.iter().filter(|e| !e.0.is_finite()).count();
    let finite: Vec<f64> = errors
        .iter()
        .map(|e| e.0)
        .filter(|e| e.is_finite())
        .collect();
    let length = errors
        .iter()
        .map(|e| e.1)
        .filter(|e| e.is_finite())
        .fold(0.0f64, f64::max);
    extra.push(format!("`{name}`: max |length − 1| = {length:.2e}"));
    let max = finite.iter().copied().fold(0.0f64, f64::max);
    // `Row::bar` is the ratio of the worst error to the bound (≤ 1 meets it).
    let bar = bar.map(|bound| max / bound);
    Row {
        method: name,
        is_default,
        ns,
        abs: ErrorStats::of(finite),
        bar,
        non_finite: Some(non_finite),
        ..Row::default()
    }
}

fn quaternion_table(settings: Settings) -> Table {
    let mut rng = XorShift::new(0x51e2_2026);
    let inputs = sphere::quat_pairs(&mut rng, settings.random, std::f32::consts::FRAC_PI_2);
    let mut table = Table {
        title: "quaternion interpolation, short path".to_owned(),
        description: "Unit quaternion pairs with 4D angles spread over [0, π/2] (rotations up to \
                      180°), `t` uniform in [0, 1]; error: 4D angle to an f64 SLERP of the same \
                      f32 inputs (radians). Bar: the method's enforced `angle_bound`."
            .to_owned(),
        inputs: inputs.len(),
        error_label: "max angle error (rad)".to_owned(),
        ..Table::default()
    };
    let mut extra = Vec::new();
    for method in QuatInterpolation::ALL {
        let errors: Vec<_> = inputs
            .iter()
            .map(|&x| quat_errors(x, method.interpolate(x.0, x.1, x.2)))
            .collect();
        let ns = ns_per_call(&inputs, settings.timing, |(a, b, t)| {
            method.interpolate(a, b, t)
        });
        table.rows.push(row(
            method.name(),
            method == QuatInterpolation::Slerp,
            ns,
            &errors,
            Some(f64::from(method.angle_bound())),
            &mut extra,
        ));
    }
    let peers: [(&str, QuatMethod); 4] = [
        ("glam Quat::slerp (peer)", |a, b, t| a.slerp(b, t)),
        ("glam Quat::lerp (peer, nlerp)", |a, b, t| a.lerp(b, t)),
        ("nalgebra try_slerp (peer)", |a, b, t| {
            to_nalgebra(a)
                .try_slerp(&to_nalgebra(b), t, 1e-7)
                .map_or(Quat::NAN, nalgebra_quat)
        }),
        ("nalgebra nlerp (peer)", |a, b, t| {
            nalgebra_quat(to_nalgebra(a).nlerp(&to_nalgebra(b), t))
        }),
    ];
    for (name, f) in peers {
        let errors: Vec<_> = inputs
            .iter()
            .map(|&x| quat_errors(x, f(x.0, x.1, x.2)))
            .collect();
        // nalgebra's own type is timed, not the conversions around it.
        let ns = if name.starts_with("nalgebra") {
            let native: Vec<_> = inputs
                .iter()
                .map(|&(a, b, t)| (to_nalgebra(a), to_nalgebra(b), t))
                .collect();
            if name.contains("nlerp") {
                ns_per_call(&native, settings.timing, |(a, b, t)| a.nlerp(&b, t))
            } else {
                ns_per_call(&native, settings.timing, |(a, b, t)| {
                    a.try_slerp(&b, t, 1e-7)
                })
            }
        } else {
            ns_per_call(&inputs, settings.timing, |(a, b, t)| f(a, b, t))
        };
        table
            .rows
            .push(row(name.to_owned(), false, ns, &errors, None, &mut extra));
    }
    table.extra = extra;
    table.mark_pareto();
    table
}

fn vector_table(settings: Settings) -> Table {
    let mut rng = XorShift::new(0x7ec3_2026);
    let mut inputs = sphere::vec3_pairs(&mut rng, settings.random, std::f32::consts::PI);
    // The near-antiparallel hard cases, at several t, so the peers' length loss shows.
    for case in vector_pairs() {
        for t in [0.25f32, 0.5, 0.75] {
            inputs.push((case.a, case.b, t));
        }
    }
    let mut table = Table {
        title: "unit-vector slerp (normals), every angle".to_owned(),
        description: "Unit `Vec3` pairs with angles spread over [0, π] plus the near-antiparallel \
                      hard cases (1e-3 … 1e-7 rad from opposite, exactly opposite) at t = ¼, ½, ¾; \
                      error: angle to an f64 SLERP of the same inputs (radians)."
            .to_owned(),
        inputs: inputs.len(),
        error_label: "max angle error (rad)".to_owned(),
        ..Table::default()
    };
    let mut extra = Vec::new();
    let methods: [(&str, bool, VecMethod); 4] = [
        ("slerp (Vec3)", true, slerp),
        ("interpolate_normal(Renormalize)", false, |a, b, t| {
            interpolate_normal(a, b, t, NormalInterpolation::Renormalize)
        }),
        ("glam Vec3::slerp (peer)", false, |a, b, t| a.slerp(b, t)),
        ("nalgebra try_slerp (peer)", false, |a, b, t| {
            unit3(a)
                .try_slerp(&unit3(b), t, 1e-7)
                .map_or(Vec3::NAN, |v| Vec3::new(v.x, v.y, v.z))
        }),
    ];
    for (name, is_default, f) in methods {
        let errors: Vec<_> = inputs
            .iter()
            .map(|&x| vec_errors(x, f(x.0, x.1, x.2)))
            .collect();
        let ns = ns_per_call(&inputs, settings.timing, |(a, b, t)| f(a, b, t));
        let bar = is_default.then_some(f64::from(barytex_interp::SLERP_F32_ANGLE_BOUND));
        table.rows.push(row(
            name.to_owned(),
            is_default,
            ns,
            &errors,
            bar,
            &mut extra,
        ));
    }
    table.extra = extra;
    table.mark_pareto();
    table
}

/// Run the family.
pub(super) fn run(settings: Settings, progress: &mut dyn FnMut(&str)) -> Section {
    progress("quaternions");
    let quaternions = quaternion_table(settings);
    progress("vectors");
    let vectors = vector_table(settings);
    let mut spacing = String::from(
        "Renormalized lerp of normals θ apart stays on the arc but is unevenly spaced (as S. \
         Schaefer's *Shading/Texturing* lecture slides note); its largest angular error against \
         even spacing (`renormalize_spacing_error`):",
    );
    for degrees in [10.0f64, 30.0, 60.0, 90.0, 120.0, 170.0] {
        let _ = write!(
            spacing,
            " {degrees}° → {:.3}°;",
            renormalize_spacing_error(degrees.to_radians()).to_degrees()
        );
    }
    Section {
        heading: "SLERP family".to_owned(),
        intro: "Exact slerp (f64 inside, angle by atan2, arc in its orthonormal frame), nlerp, \
                Kapoulkine's corrected nlerp, Eberly's polynomial slerp with 4–16 terms, and the \
                peers glam 0.34 and nalgebra 0.35, on the same inputs."
            .to_owned(),
        tables: vec![quaternions, vectors],
        notes: vec![
            spacing,
            "`slerp` on arcs up to 90° with t in [0, 1] (all rows of the quaternion table) runs \
             Eberly's series with 16 balanced factors in f64, evaluated by blocked prefix \
             products; the `eberly-N` rows are the textbook f32 Horner evaluation, whose serial \
             chain is why eberly-16 is slower than the default."
                .to_owned(),
        ],
    }
}
