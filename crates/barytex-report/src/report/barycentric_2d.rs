//! 2D barycentric coordinates: naive f32, difference of products f32, f64, and the exact-sign
//! default, against exact rational weights.

use barytex_interp::hard_cases::{kettner_grid, triangles_2d};
use barytex_interp::methods::{
    barycentric_2d_dop_f32, barycentric_2d_f64, barycentric_2d_naive_f32,
};
use barytex_interp::{Location, barycentric_2d};
use barytex_testkit::exact;
use barytex_testkit::invariants::{barycentric_bar, barycentric_condition};
use barytex_testkit::ulp::ulp_f32;
use glam::Vec2;

use super::table::{fmt_err, fmt_ulps, per_case_matrix};
use super::{ErrorStats, Row, Section, Settings, Table};
use crate::timing::ns_per_call;
use barytex_testkit::seeded::{self, XorShift};

type Input = (Vec2, [Vec2; 3]);

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Method {
    Naive,
    Dop,
    F64,
    Default,
}

const METHODS: [Method; 4] = [Method::Naive, Method::Dop, Method::F64, Method::Default];

impl Method {
    fn name(self) -> &'static str {
        match self {
            Self::Naive => "methods::barycentric_2d_naive_f32",
            Self::Dop => "methods::barycentric_2d_dop_f32",
            Self::F64 => "methods::barycentric_2d_f64",
            Self::Default => "barycentric_2d",
        }
    }

    fn short(self) -> &'static str {
        match self {
            Self::Naive => "naive f32",
            Self::Dop => "dop f32",
            Self::F64 => "f64",
            Self::Default => "default",
        }
    }

    /// Weights and the location the method reports (derived from the weights' signs for the
    /// methods without a classification).
    fn evaluate(self, (p, tri): Input) -> ([f32; 3], Option<Location>) {
        let weights = match self {
            Self::Naive => barycentric_2d_naive_f32(p, tri),
            Self::Dop => barycentric_2d_dop_f32(p, tri),
            Self::F64 => barycentric_2d_f64(p, tri),
            Self::Default => {
                return match barycentric_2d(p, tri) {
                    Ok(b) => (b.weights, Some(b.location)),
                    Err(_) => ([f32::NAN; 3], Some(Location::Degenerate)),
                };
            }
        };
        (weights, location_of_signs(weights.map(sign_f32)))
    }

    /// The documented accuracy bound `1 ulp + c·κ` as its text and `c`, where one is documented.
    fn documented_bound(self) -> Option<(&'static str, f64)> {
        match self {
            Self::Default => Some(("1 ulp", 0.0)),
            Self::F64 => Some(("1 ulp + 2⁻⁴⁹·κ", 2f64.powi(-49))),
            Self::Naive | Self::Dop => None,
        }
    }

    fn time(self, inputs: &[Input], settings: Settings) -> f64 {
        let config = settings.timing;
        match self {
            Self::Naive => ns_per_call(inputs, config, |(p, t)| barycentric_2d_naive_f32(p, t)),
            Self::Dop => ns_per_call(inputs, config, |(p, t)| barycentric_2d_dop_f32(p, t)),
            Self::F64 => ns_per_call(inputs, config, |(p, t)| barycentric_2d_f64(p, t)),
            Self::Default => ns_per_call(inputs, config, |(p, t)| barycentric_2d(p, t)),
        }
    }
}

/// The sign of an f32 (`None` for NaN).
pub(super) fn sign_f32(x: f32) -> Option<i8> {
    if x > 0.0 {
        Some(1)
    } else if x < 0.0 {
        Some(-1)
    } else if x == 0.0 {
        Some(0)
    } else {
        None
    }
}

fn sign_f64(x: f64) -> i8 {
    if x > 0.0 {
        1
    } else if x < 0.0 {
        -1
    } else {
        0
    }
}

/// The location that weights with these signs describe; `None` when a sign is missing (NaN) or
/// all three are zero.
fn location_of_signs(signs: [Option<i8>; 3]) -> Option<Location> {
    let signs: [i8; 3] = [signs[0]?, signs[1]?, signs[2]?];
    if signs.contains(&-1) {
        return Some(Location::Outside);
    }
    match signs.iter().filter(|&&s| s == 0).count() {
        0 => Some(Location::Inside),
        1 => signs.iter().position(|&s| s == 0).map(Location::OnEdge),
        2 => signs.iter().position(|&s| s != 0).map(Location::OnVertex),
        _ => None,
    }
}

/// The exact answer for one input.
struct Reference {
    /// Exact weights rounded to f64 (`None` for a zero-area triangle).
    weights: Option<[f64; 3]>,
    location: Location,
    kappa: f64,
}

impl Reference {
    fn of((p, tri): Input) -> Self {
        let weights = exact::barycentric_2d(p, tri).map(|w| w.map(|wi| exact::to_f64(&wi)));
        let location = match weights {
            // f64 rounding keeps the sign of every weight: the smallest non-zero weight of f32
            // inputs is above 2⁻⁶⁰⁰, far inside f64's range.
            Some(w) => {
                location_of_signs(w.map(|wi| Some(sign_f64(wi)))).unwrap_or(Location::Degenerate)
            }
            None => Location::Degenerate,
        };
        Self {
            weights,
            location,
            kappa: barycentric_condition(p, tri),
        }
    }
}

/// Per-input measurements of one method.
struct Measured {
    abs: Vec<f64>,
    ulps: Vec<f64>,
    bar: Vec<f64>,
    documented: Vec<f64>,
    wrong_signs: Vec<usize>,
    wrong_class: Vec<bool>,
    non_finite: usize,
}

fn measure(method: Method, inputs: &[Input], references: &[Reference]) -> Measured {
    let mut m = Measured {
        abs: Vec::with_capacity(inputs.len()),
        ulps: Vec::with_capacity(inputs.len()),
        bar: Vec::with_capacity(inputs.len()),
        documented: Vec::with_capacity(inputs.len()),
        wrong_signs: Vec::with_capacity(inputs.len()),
        wrong_class: Vec::with_capacity(inputs.len()),
        non_finite: 0,
    };
    for (&input, reference) in inputs.iter().zip(references) {
        let (weights, location) = method.evaluate(input);
        m.wrong_class.push(location != Some(reference.location));
        let Some(exact_w) = reference.weights else {
            m.wrong_signs.push(0);
            continue;
        };
        if !weights.iter().all(|w| w.is_finite()) {
            m.non_finite += 1;
        }
        let (mut abs, mut ulps, mut bar, mut documented, mut wrong) =
            (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0);
        for (&w, &x) in weights.iter().zip(&exact_w) {
            let e = if w.is_finite() {
                (f64::from(w) - x).abs()
            } else {
                f64::INFINITY
            };
            abs = abs.max(e);
            ulps = ulps.max(e / ulp_f32(x));
            bar = bar.max(e / barycentric_bar(x, reference.kappa));
            if let Some((_, c)) = method.documented_bound() {
                let bound = ulp_f32(x) + reference.kappa * c;
                documented = documented.max(e / bound);
            }
            if sign_f32(w) != Some(sign_f64(x)) {
                wrong += 1;
            }
        }
        m.abs.push(abs);
        m.ulps.push(ulps);
        m.bar.push(bar);
        m.documented.push(documented);
        m.wrong_signs.push(wrong);
    }
    m
}

fn random_inputs(n: usize) -> Vec<Input> {
    seeded::triangles_2d(&mut XorShift::new(0xba2d_2024), n)
}

struct InputSet {
    title: String,
    description: String,
    inputs: Vec<Input>,
    /// Case names for a per-case breakdown (hard-case table only).
    cases: Option<Vec<String>>,
}

/// Run the family.
pub(super) fn run(settings: Settings, progress: &mut dyn FnMut(&str)) -> Section {
    let hard: Vec<_> = triangles_2d().collect();
    let n = settings.kettner;
    let sets = [
        InputSet {
            title: "random well-shaped".to_owned(),
            description: format!(
                "Triangles with vertices uniform in [−100, 100]² and shape quality \
                 (2·area / longest edge²) ≥ 0.05, either orientation; points with affine weights \
                 uniform in [−0.25, 1.25] (inside and outside). Seeded xorshift, {} inputs.",
                settings.random
            ),
            inputs: random_inputs(settings.random),
            cases: None,
        },
        InputSet {
            title: "hard cases".to_owned(),
            description: "`barytex_interp::hard_cases::triangles_2d()`: slivers of aspect \
                          1e-3 … 1e-7, offsets 1e4 … 1e7, tiny scales to 1e-30, subnormal and \
                          huge coordinates, points exactly on edges and vertices and one ulp off \
                          an edge."
                .to_owned(),
            inputs: hard.iter().map(|c| (c.point, c.triangle)).collect(),
            cases: Some(
                hard.iter()
                    .map(|c| {
                        if c.parameter == 0.0 {
                            c.name.to_owned()
                        } else {
                            format!("{} {:e}", c.name, c.parameter)
                        }
                    })
                    .collect(),
            ),
        },
        InputSet {
            title: "Kettner grid near an edge".to_owned(),
            description: format!(
                "Kettner's grid (`hard_cases::kettner_grid({n})`): the {} points \
                 (0.5 + i·ulp, 0.5 + j·ulp) in the triangle (12, 12), (24, 24), (0, 24), whose \
                 edge line passes through the grid: γ is zero or tiny, and the point is outside \
                 (β < 0).",
                n * n
            ),
            inputs: kettner_grid(n)
                .map(|(p, a, b)| (p, [a, b, Vec2::new(0.0, 24.0)]))
                .collect(),
            cases: None,
        },
    ];
    let mut section = Section {
        heading: "2D barycentric".to_owned(),
        intro: "Weights `[α, β, γ]` of a point in a triangle. Errors are per input the largest of \
                the three weights' errors against the exact rational weights; ulps are f32 ulps \
                of the exact weight (a weight that should be exactly 0 and is not has an \
                enormous ulp error); the bar is the project's (`docs/ACCURACY.md`) \
                `4 ulp + 2⁻²⁴·κ` with `κ = max(|p|, |a|, |b|, |c|) · longest edge / |2·area|`. \
                Wrong signs count weights whose sign (−, 0, +) differs from the exact one; wrong \
                class counts points whose location (inside / on edge i / on vertex i / outside) \
                differs — for the methods without a classification it is read from the signs of \
                their weights."
            .to_owned(),
        ..Section::default()
    };
    for set in sets {
        progress(&format!(
            "{} ({} inputs): exact references",
            set.title,
            set.inputs.len()
        ));
        let references: Vec<Reference> = set.inputs.iter().map(|&i| Reference::of(i)).collect();
        progress(&format!("{}: errors and timing", set.title));
        let mut table = Table {
            title: set.title.clone(),
            description: set.description,
            inputs: set.inputs.len(),
            sign_total: format!("of {} weights", 3 * set.inputs.len()),
            error_label: "max abs error of the weights".to_owned(),
            ..Table::default()
        };
        let mut matrix: Vec<Vec<String>> = vec![Vec::new(); set.inputs.len()];
        for method in METHODS {
            let measured = measure(method, &set.inputs, &references);
            let ns = method.time(&set.inputs, settings);
            if let Some((text, _)) = method.documented_bound() {
                let worst = measured.documented.iter().copied().fold(0.0, f64::max);
                section.notes.push(format!(
                    "{}: `{}` max error / its documented bound ({text}) = {}{}",
                    set.title,
                    method.name(),
                    fmt_ulps(worst),
                    if worst > 1.0 {
                        " — **exceeds the documented bound**"
                    } else {
                        ""
                    }
                ));
            }
            for (i, cell) in matrix.iter_mut().enumerate() {
                let mut text = measured
                    .abs
                    .get(i)
                    .map_or_else(|| "–".to_owned(), |&e| fmt_err(e));
                if measured.wrong_class.get(i) == Some(&true) {
                    text.push_str(" ✗");
                }
                cell.push(text);
            }
            table.rows.push(Row {
                method: method.name().to_owned(),
                is_default: method == Method::Default,
                ns,
                abs: ErrorStats::of(measured.abs),
                ulps: ErrorStats::of(measured.ulps),
                bar: ErrorStats::of(measured.bar).map(|s| s.max),
                wrong_signs: Some(measured.wrong_signs.iter().sum()),
                wrong_class: Some(measured.wrong_class.iter().filter(|&&w| w).count()),
                non_finite: Some(measured.non_finite),
                pareto: false,
            });
        }
        if let Some(cases) = set.cases {
            let methods: Vec<String> = METHODS.iter().map(|m| m.short().to_owned()).collect();
            table.extra.push(per_case_matrix(
                "Per case: max abs error of the three weights (✗ = wrong location).",
                &cases,
                &methods,
                &matrix,
            ));
        }
        section.tables.push(table);
    }
    section
}
