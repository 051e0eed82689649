//! 3D barycentric coordinates: Cramer's dot form, the cross-product form, the precomputed form of
//! Buss, *3D Computer Graphics* (2003), §IV.1 (`β = u_β·f`, `γ = u_γ·f`) and the default, against
//! exact rational weights.

use barytex_interp::barycentric_3d;
use barytex_interp::hard_cases::triangles_3d;
use barytex_interp::methods::{
    PrecomputedTriangle3, barycentric_3d_cramer_f32, barycentric_3d_cross_f32,
};
use barytex_testkit::exact;
use barytex_testkit::ulp::ulp_f32;
use glam::Vec3;

use super::barycentric_2d::sign_f32;
use super::table::superscript;
use super::table::{fmt_err, fmt_ulps, per_case_matrix};
use super::{ErrorStats, Row, Section, Settings, Table};
use crate::timing::ns_per_call;
use barytex_testkit::seeded::{self, XorShift};

type Input = (Vec3, [Vec3; 3]);

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Method {
    Cramer,
    Cross,
    PrecomputedQuery,
    PrecomputedWithSetup,
    Default,
}

const METHODS: [Method; 5] = [
    Method::Cramer,
    Method::Cross,
    Method::PrecomputedQuery,
    Method::PrecomputedWithSetup,
    Method::Default,
];

impl Method {
    fn name(self) -> &'static str {
        match self {
            Self::Cramer => "methods::barycentric_3d_cramer_f32",
            Self::Cross => "methods::barycentric_3d_cross_f32",
            Self::PrecomputedQuery => "PrecomputedTriangle3::weights (setup not timed)",
            Self::PrecomputedWithSetup => "PrecomputedTriangle3::new + weights",
            Self::Default => "barycentric_3d",
        }
    }

    fn short(self) -> &'static str {
        match self {
            Self::Cramer => "Cramer f32",
            Self::Cross => "cross f32",
            Self::PrecomputedQuery | Self::PrecomputedWithSetup => "precomputed",
            Self::Default => "default",
        }
    }

    fn evaluate(self, (p, tri): Input) -> [f32; 3] {
        match self {
            Self::Cramer => barycentric_3d_cramer_f32(p, tri),
            Self::Cross => barycentric_3d_cross_f32(p, tri),
            Self::PrecomputedQuery | Self::PrecomputedWithSetup => {
                PrecomputedTriangle3::new(tri).map_or([f32::NAN; 3], |pre| pre.weights(p))
            }
            Self::Default => barycentric_3d(p, tri).map_or([f32::NAN; 3], |b| b.weights),
        }
    }

    fn time(self, inputs: &[Input], settings: Settings) -> f64 {
        let config = settings.timing;
        match self {
            Self::Cramer => ns_per_call(inputs, config, |(p, t)| barycentric_3d_cramer_f32(p, t)),
            Self::Cross => ns_per_call(inputs, config, |(p, t)| barycentric_3d_cross_f32(p, t)),
            Self::PrecomputedQuery => {
                let pre: Vec<(Vec3, PrecomputedTriangle3)> = inputs
                    .iter()
                    .filter_map(|&(p, t)| PrecomputedTriangle3::new(t).ok().map(|pre| (p, pre)))
                    .collect();
                ns_per_call(&pre, config, |(p, pre)| pre.weights(p))
            }
            Self::PrecomputedWithSetup => ns_per_call(inputs, config, |(p, t)| {
                PrecomputedTriangle3::new(t).map(|pre| pre.weights(p))
            }),
            Self::Default => ns_per_call(inputs, config, |(p, t)| barycentric_3d(p, t)),
        }
    }
}

/// Exact weights (rounded to f64) of the projected point and the condition number
/// `κ = max(|p|, |a|, |b|, |c|) · longest edge / |2·area|`.
fn reference((p, tri): Input) -> Option<([f64; 3], f64)> {
    let weights = exact::barycentric_3d(p, tri)?.map(|w| exact::to_f64(&w));
    let [a, b, c] = tri.map(|v| v.as_dvec3());
    let magnitude = [p.as_dvec3(), a, b, c]
        .iter()
        .map(|v| v.length())
        .fold(0.0, f64::max);
    let edge = (b - a).length().max((c - b).length()).max((a - c).length());
    let area2 = (b - a).cross(c - a).length();
    Some((weights, magnitude * edge / area2))
}

fn random_inputs(n: usize) -> Vec<Input> {
    seeded::triangles_3d(&mut XorShift::new(0xba3d_2024), n)
}

/// Run the family.
pub(super) fn run(settings: Settings, progress: &mut dyn FnMut(&str)) -> Section {
    let hard: Vec<_> = triangles_3d().collect();
    let sets = [
        (
            "random well-shaped".to_owned(),
            format!(
                "Triangles with vertices uniform in [−100, 100]³ and |2·area| ≥ 0.05·longest \
                 edge²; points with affine weights uniform in [−0.25, 1.25], computed in f32 \
                 (so in the plane only up to rounding: the reference is the exact projection). \
                 Seeded xorshift, {} inputs.",
                settings.random
            ),
            random_inputs(settings.random),
            None,
        ),
        (
            "hard cases".to_owned(),
            "`barytex_interp::hard_cases::triangles_3d()`: tilted slivers of aspect 1e-3 … 1e-7 \
             and offsets 1e4 … 1e7."
                .to_owned(),
            hard.iter().map(|c| (c.point, c.triangle)).collect(),
            Some(
                hard.iter()
                    .map(|c| format!("{} {:e}", c.name, c.parameter))
                    .collect::<Vec<String>>(),
            ),
        ),
    ];
    let mut section = Section {
        heading: "3D barycentric".to_owned(),
        intro: "Weights of the orthogonal projection of a point onto the triangle's plane. \
                Errors per input are the largest of the three weights' errors against the exact \
                rational weights of the projection; the bar column applies the 2D bar \
                `4 ulp + 2⁻²⁴·κ` (same κ, with the 3D area) for scale. Wrong signs count weights \
                whose sign differs from the exact one. The two precomputed rows compute the \
                same numbers; one times the query alone (the triangle prepared outside the \
                timed loop), the other includes the per-triangle setup."
            .to_owned(),
        ..Section::default()
    };
    for (title, description, inputs, cases) in sets {
        progress(&format!(
            "{title} ({} inputs): exact references",
            inputs.len()
        ));
        let references: Vec<Option<([f64; 3], f64)>> =
            inputs.iter().map(|&i| reference(i)).collect();
        progress(&format!("{title}: errors and timing"));
        let mut table = Table {
            title: title.clone(),
            description,
            inputs: inputs.len(),
            sign_total: format!("of {} weights", 3 * inputs.len()),
            error_label: "max abs error of the weights".to_owned(),
            ..Table::default()
        };
        let mut matrix: Vec<Vec<String>> = vec![Vec::new(); inputs.len()];
        for method in METHODS {
            let (mut abs, mut ulps, mut bar) = (Vec::new(), Vec::new(), Vec::new());
            let (mut wrong_signs, mut non_finite, mut documented) = (0, 0, 0.0f64);
            for (i, (&input, reference)) in inputs.iter().zip(&references).enumerate() {
                let Some((exact_w, kappa)) = *reference else {
                    continue;
                };
                let weights = method.evaluate(input);
                if !weights.iter().all(|w| w.is_finite()) {
                    non_finite += 1;
                }
                let (mut a, mut u, mut b) = (0.0f64, 0.0f64, 0.0f64);
                for (&w, &x) in weights.iter().zip(&exact_w) {
                    let e = if w.is_finite() {
                        (f64::from(w) - x).abs()
                    } else {
                        f64::INFINITY
                    };
                    a = a.max(e);
                    u = u.max(e / ulp_f32(x));
                    b = b.max(e / (4.0 * ulp_f32(x) + kappa * 2f64.powi(-24)));
                    documented = documented.max(e / (ulp_f32(x) + kappa * 2f64.powi(-46)));
                    let exact_sign = if x > 0.0 {
                        1
                    } else if x < 0.0 {
                        -1
                    } else {
                        0
                    };
                    if sign_f32(w) != Some(exact_sign) {
                        wrong_signs += 1;
                    }
                }
                matrix[i].push(fmt_err(a));
                abs.push(a);
                ulps.push(u);
                bar.push(b);
            }
            if method == Method::Default {
                section.notes.push(format!(
                    "{title}: `barycentric_3d` max error / its documented bound \
                     (1 ulp + 2⁻{}·κ) = {}{}",
                    superscript(46),
                    fmt_ulps(documented),
                    if documented > 1.0 {
                        " — **exceeds the documented bound**"
                    } else {
                        ""
                    }
                ));
            }
            table.rows.push(Row {
                method: method.name().to_owned(),
                is_default: method == Method::Default,
                ns: method.time(&inputs, settings),
                abs: ErrorStats::of(abs),
                ulps: ErrorStats::of(ulps),
                bar: ErrorStats::of(bar).map(|s| s.max),
                wrong_signs: Some(wrong_signs),
                wrong_class: None,
                non_finite: Some(non_finite),
                pareto: false,
            });
        }
        if let Some(cases) = cases {
            // The two precomputed rows share their errors: show one column.
            let keep: Vec<usize> = (0..METHODS.len())
                .filter(|&i| METHODS[i] != Method::PrecomputedWithSetup)
                .collect();
            let methods: Vec<String> = keep
                .iter()
                .map(|&i| METHODS[i].short().to_owned())
                .collect();
            let values: Vec<Vec<String>> = matrix
                .iter()
                .map(|row| keep.iter().filter_map(|&i| row.get(i).cloned()).collect())
                .collect();
            table.extra.push(per_case_matrix(
                "Per case: max abs error of the three weights.",
                &cases,
                &methods,
                &values,
            ));
        }
        section.tables.push(table);
    }
    section
}
