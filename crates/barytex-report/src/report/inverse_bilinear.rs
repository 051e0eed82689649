//! Inverse bilinear interpolation: the default against the Quilez / pbrt-v4 routine (ported in
//! `barytex_testkit::reference`), against Newton's method in f64 from the known preimage.

use barytex_interp::hard_cases::quads;
use barytex_interp::{InverseBilinear, inverse_bilinear_2d};
use barytex_testkit::invariants::inverse_bilinear_error;
use barytex_testkit::reference::{
    bilinear_f64, inverse_bilinear_newton, quilez_inverse_bilinear_f32,
};
use barytex_testkit::strategies::is_strictly_convex_ccw;
use barytex_testkit::ulp::ulp_f32;
use glam::{DVec2, Vec2};

use super::table::{fmt_err, fmt_ulps, per_case_matrix};
use super::{ErrorStats, Row, Section, Settings, Table};
use crate::timing::ns_per_call;
use barytex_testkit::seeded::{self, XorShift};
use barytex_testkit::strategies::step_ulps;

/// The project's accuracy bar for inverse bilinear at unit scale (`docs/ACCURACY.md`).
const BAR: f64 = 3e-7;

/// A point, its quad, and the f64 Newton reference preimage.
#[derive(Clone, Copy, Debug)]
struct Case {
    p: Vec2,
    quad: [Vec2; 4],
    reference: DVec2,
}

impl Case {
    /// Map `ab` forward in f64, round the point to f32, and refine the preimage of the rounded
    /// point by Newton's method from `ab`; `None` when Newton fails.
    fn new(quad: [Vec2; 4], ab: Vec2) -> Option<Self> {
        let quad64 = quad.map(Vec2::as_dvec2);
        let p = bilinear_f64(quad64, ab.as_dvec2()).as_vec2();
        let reference = inverse_bilinear_newton(p.as_dvec2(), quad64, ab.as_dvec2())?;
        reference.is_finite().then_some(Self { p, quad, reference })
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Method {
    Default,
    Quilez,
}

const METHODS: [Method; 2] = [Method::Default, Method::Quilez];

impl Method {
    fn name(self) -> &'static str {
        match self {
            Self::Default => "inverse_bilinear_2d",
            Self::Quilez => "reference::quilez_inverse_bilinear_f32 (Quilez / pbrt-v4 port)",
        }
    }

    fn short(self) -> &'static str {
        match self {
            Self::Default => "default",
            Self::Quilez => "Quilez / pbrt",
        }
    }

    /// The preimage the method reports and whether it says the point is inside the quad.
    fn evaluate(self, case: &Case) -> (Vec2, bool) {
        match self {
            Self::Default => match inverse_bilinear_2d(case.p, case.quad) {
                Ok(InverseBilinear::Inside(ab)) => (ab, true),
                Ok(InverseBilinear::Folded(first, second)) => {
                    let closer = if inverse_bilinear_error(first, case.reference)
                        <= inverse_bilinear_error(second, case.reference)
                    {
                        first
                    } else {
                        second
                    };
                    (closer, true)
                }
                Ok(InverseBilinear::Outside(Some(ab))) => (ab, false),
                Ok(InverseBilinear::Outside(None)) | Err(_) => (Vec2::NAN, false),
            },
            Self::Quilez => {
                let ab = quilez_inverse_bilinear_f32(case.p, case.quad);
                let inside = (0.0..=1.0).contains(&ab.x) && (0.0..=1.0).contains(&ab.y);
                (ab, inside)
            }
        }
    }

    fn time(self, inputs: &[(Vec2, [Vec2; 4])], settings: Settings) -> f64 {
        let config = settings.timing;
        match self {
            Self::Default => ns_per_call(inputs, config, |(p, q)| inverse_bilinear_2d(p, q)),
            Self::Quilez => ns_per_call(inputs, config, |(p, q)| quilez_inverse_bilinear_f32(p, q)),
        }
    }
}

/// The quad's condition number as `inverse_bilinear_2d` documents it: diameter over the
/// smallest distance from a corner to the opposite diagonal's line.
fn condition(quad: [Vec2; 4]) -> f64 {
    let q = quad.map(Vec2::as_dvec2);
    let mut diameter = 0.0f64;
    for i in 0..4 {
        for j in i + 1..4 {
            diameter = diameter.max((q[i] - q[j]).length());
        }
    }
    let distance = |corner: DVec2, a: DVec2, b: DVec2| {
        let d = b - a;
        (corner - a).perp_dot(d).abs() / d.length()
    };
    let nearest = distance(q[0], q[1], q[3])
        .min(distance(q[2], q[1], q[3]))
        .min(distance(q[1], q[0], q[2]))
        .min(distance(q[3], q[0], q[2]));
    diameter / nearest
}

fn random_cases(n: usize, seed: u64, scale: f32) -> Vec<Case> {
    let mut rng = XorShift::new(seed);
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let quad = seeded::convex_quad(&mut rng).map(|c| c * scale);
        let ab = Vec2::new(rng.f32_in(0.01, 0.99), rng.f32_in(0.01, 0.99));
        out.extend(Case::new(quad, ab));
    }
    out
}

/// Parallelograms with corner `z` moved by −4 … 4 ulps in x: where thresholded solvers switch
/// branches.
fn near_parallelogram_cases(n: usize) -> Vec<Case> {
    let mut rng = XorShift::new(0x9a2a_2024);
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let x = rng.vec2_in(-10.0, 10.0);
        let e = rng.vec2_in(0.5, 5.0);
        let f = Vec2::new(rng.f32_in(-2.0, 2.0), rng.f32_in(0.5, 2.5));
        let z = x + e + f;
        let quad = [
            x,
            x + e,
            Vec2::new(step_ulps(z.x, rng.i32_in(-4, 4)), z.y),
            x + f,
        ];
        if !is_strictly_convex_ccw(quad) {
            continue;
        }
        let ab = Vec2::new(rng.f32_in(0.01, 0.99), rng.f32_in(0.01, 0.99));
        out.extend(Case::new(quad, ab));
    }
    out
}

/// Run the family.
pub(super) fn run(settings: Settings, progress: &mut dyn FnMut(&str)) -> Section {
    let n = settings.random;
    let hard: Vec<_> = quads().collect();
    let hard_cases: Vec<(String, Option<Case>)> = hard
        .iter()
        .map(|c| {
            let name = if c.parameter == 0.0 {
                c.name.to_owned()
            } else {
                format!("{} {:e}", c.name, c.parameter)
            };
            (name, Case::new(c.quad, c.alpha_beta))
        })
        .collect();
    let unreferenced: Vec<&str> = hard_cases
        .iter()
        .filter(|(_, c)| c.is_none())
        .map(|(name, _)| name.as_str())
        .collect();
    let (names, cases): (Vec<String>, Vec<Case>) = hard_cases
        .iter()
        .filter_map(|(name, c)| c.map(|c| (name.clone(), c)))
        .unzip();
    let sets = [
        (
            "random convex, unit scale".to_owned(),
            format!(
                "Strictly convex quads with corners on a perturbed unit circle (radius 0.7 … \
                 1.3, angles 90° ± 23° apart); (α, β) uniform in [0.01, 0.99]²; {n} inputs."
            ),
            random_cases(n, 0x1b11_2024, 1.0),
            None,
        ),
        (
            "random convex, scale 0.01".to_owned(),
            format!(
                "The same kind of quads scaled by 0.01 (k₂ then falls below the port's absolute \
                 1e-3 threshold, so it takes its parallelogram branch); {n} inputs."
            ),
            random_cases(n, 0x1b11_2025, 0.01),
            None,
        ),
        (
            "near-parallelogram".to_owned(),
            format!(
                "Parallelograms in [−10, 10]² with corner z moved by −4 … 4 ulps in x; {n} inputs."
            ),
            near_parallelogram_cases(n),
            None,
        ),
        (
            "hard cases".to_owned(),
            format!(
                "`barytex_interp::hard_cases::quads()`: Example 10 (the quad of Exercise IV.7 in \
                 Buss, *3D Computer Graphics*, 2003), an exact parallelogram, a \
                 near-parallelogram, a trapezoid, a sliver, corners of mixed magnitude, tiny \
                 scales to 1e-30, subnormal size, two exact edge points next to a double root \
                 (parameter: the quad's κ) and offsets 1e4 … 1e7.{}",
                if unreferenced.is_empty() {
                    String::new()
                } else {
                    format!(
                        " Left out (Newton found no reference): {}.",
                        unreferenced.join(", ")
                    )
                }
            ),
            cases,
            Some(names),
        ),
    ];
    let mut section = Section {
        heading: "Inverse bilinear".to_owned(),
        intro: "Point → (α, β) in a quad. Each input maps a known (α, β) forward in f64 \
                (`reference::bilinear_f64`) and rounds the point to f32; the reference is \
                Newton's method in f64 on that rounded point, started from the known (α, β). \
                The error is the max-norm distance in parameter space; ulps are f32 ulps of the \
                reference parameter (max of α and β); the bar column divides by the project's \
                unit-scale bar 3e-7 (`docs/ACCURACY.md`). Every reference preimage is inside \
                [0, 1]², so \"wrong class\" counts answers that say the point is outside the \
                quad (for the port: a result outside [0, 1]²). For a folded quad the default's \
                preimage nearer the reference is scored."
            .to_owned(),
        ..Section::default()
    };
    for (title, description, cases, names) in sets {
        progress(&format!(
            "{title} ({} inputs): errors and timing",
            cases.len()
        ));
        let mut table = Table {
            title: title.clone(),
            description,
            inputs: cases.len(),
            error_label: "max error in (α, β)".to_owned(),
            ..Table::default()
        };
        let timing_inputs: Vec<(Vec2, [Vec2; 4])> = cases.iter().map(|c| (c.p, c.quad)).collect();
        let mut matrix: Vec<Vec<String>> = vec![Vec::new(); cases.len()];
        for method in METHODS {
            let (mut abs, mut ulps) = (Vec::new(), Vec::new());
            let (mut outside, mut non_finite, mut documented) = (0, 0, 0.0f64);
            for (i, case) in cases.iter().enumerate() {
                let (ab, inside) = method.evaluate(case);
                let error = if ab.is_finite() {
                    inverse_bilinear_error(ab, case.reference)
                } else {
                    non_finite += 1;
                    f64::INFINITY
                };
                let d = (ab.as_dvec2() - case.reference).abs();
                let ulp_error =
                    (d.x / ulp_f32(case.reference.x)).max(d.y / ulp_f32(case.reference.y));
                abs.push(error);
                ulps.push(if ab.is_finite() {
                    ulp_error
                } else {
                    f64::INFINITY
                });
                if !inside {
                    outside += 1;
                }
                documented = documented.max(error / (BAR * (1.0 + condition(case.quad))));
                matrix[i].push(format!(
                    "{}{}",
                    fmt_err(error),
                    if inside { "" } else { " ✗" }
                ));
            }
            if method == Method::Default {
                section.notes.push(format!(
                    "{title}: `inverse_bilinear_2d` max error / its documented bound \
                     (3e-7·(1 + κ), κ = diameter / nearest corner-to-opposite-diagonal \
                     distance) = {}{}",
                    fmt_ulps(documented),
                    if documented > 1.0 {
                        " — **exceeds the documented bound**"
                    } else {
                        ""
                    }
                ));
            }
            let abs_stats = ErrorStats::of(abs);
            table.rows.push(Row {
                method: method.name().to_owned(),
                is_default: method == Method::Default,
                ns: method.time(&timing_inputs, settings),
                abs: abs_stats,
                ulps: ErrorStats::of(ulps),
                bar: abs_stats.map(|s| s.max / BAR),
                wrong_signs: None,
                wrong_class: Some(outside),
                non_finite: Some(non_finite),
                pareto: false,
            });
        }
        if let Some(names) = names {
            let methods: Vec<String> = METHODS.iter().map(|m| m.short().to_owned()).collect();
            table.extra.push(per_case_matrix(
                "Per case: parameter-space error (✗ = reported outside the quad).",
                &names,
                &methods,
                &matrix,
            ));
        }
        section.tables.push(table);
    }
    section
}
