//! The 2D convex hull: `convex_hull_2d` under both collinear policies against geo 0.33 (its
//! default `ConvexHull`, QuickHull, and `graham_hull` with and without collinear points), on
//! points uniform in a square, on a circle, and on the hard-case table; each vertex set compared
//! with the exact one.

use std::collections::BTreeSet;
use std::hint::black_box;
use std::time::Instant;

use barytex_interp::hard_cases::hulls_2d;
use barytex_interp::{CollinearPoints, convex_hull_2d};
use barytex_testkit::exact;
use barytex_testkit::seeded::{XorShift, points_in_square, points_on_circle};
use geo::algorithm::convex_hull::graham_hull;
use geo::{ConvexHull, Coord, MultiPoint, Point};
use glam::Vec2;

use super::table::per_case_matrix;
use super::{Row, Section, Settings, Table};
use crate::timing::median;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Method {
    Drop,
    Keep,
    GeoConvexHull,
    GeoGraham,
    GeoGrahamOnHull,
}

const METHODS: [Method; 5] = [
    Method::Drop,
    Method::Keep,
    Method::GeoConvexHull,
    Method::GeoGraham,
    Method::GeoGrahamOnHull,
];

impl Method {
    fn name(self) -> &'static str {
        match self {
            Self::Drop => "convex_hull_2d(…, CollinearPoints::Drop)",
            Self::Keep => "convex_hull_2d(…, CollinearPoints::Keep)",
            Self::GeoConvexHull => "geo `MultiPoint::convex_hull` (peer, QuickHull, f32 → f64)",
            Self::GeoGraham => "geo `graham_hull(…, false)` (peer)",
            Self::GeoGrahamOnHull => "geo `graham_hull(…, true)` (peer, keeps collinear)",
        }
    }

    fn short(self) -> &'static str {
        match self {
            Self::Drop => "Drop",
            Self::Keep => "Keep",
            Self::GeoConvexHull => "geo ConvexHull",
            Self::GeoGraham => "geo graham",
            Self::GeoGrahamOnHull => "geo graham (on hull)",
        }
    }

    /// Which exact set the method's answer is compared with.
    fn keeps_collinear(self) -> bool {
        matches!(self, Self::Keep | Self::GeoGrahamOnHull)
    }

    /// The hull's vertex positions, as `(x, y)` bit patterns with `-0.0` read as `0.0`.
    fn vertex_set(self, points: &[Vec2], geo_points: &GeoInput) -> BTreeSet<(u32, u32)> {
        match self {
            Self::Drop | Self::Keep => {
                let policy = if self == Self::Drop {
                    CollinearPoints::Drop
                } else {
                    CollinearPoints::Keep
                };
                convex_hull_2d(points, policy)
                    .map(|h| h.positions(points).map(bits).collect())
                    .unwrap_or_default()
            }
            Self::GeoConvexHull => coord_set(geo_points.multi.convex_hull().exterior().0.iter()),
            Self::GeoGraham | Self::GeoGrahamOnHull => {
                let mut coords = geo_points.coords.clone();
                coord_set(
                    graham_hull(&mut coords, self == Self::GeoGrahamOnHull)
                        .0
                        .iter(),
                )
            }
        }
    }

    /// One timed call (the geo peers' coordinate copy for `graham_hull` is made outside).
    fn time_once(self, points: &[Vec2], geo_points: &GeoInput) -> f64 {
        let mut coords = geo_points.coords.clone();
        let start = Instant::now();
        match self {
            Self::Drop => {
                black_box(convex_hull_2d(black_box(points), CollinearPoints::Drop)).ok();
            }
            Self::Keep => {
                black_box(convex_hull_2d(black_box(points), CollinearPoints::Keep)).ok();
            }
            Self::GeoConvexHull => {
                black_box(black_box(&geo_points.multi).convex_hull());
            }
            Self::GeoGraham => {
                black_box(graham_hull(black_box(&mut coords), false));
            }
            Self::GeoGrahamOnHull => {
                black_box(graham_hull(black_box(&mut coords), true));
            }
        }
        start.elapsed().as_secs_f64() * 1e9
    }
}

/// The same points for geo, converted exactly to f64.
struct GeoInput {
    coords: Vec<Coord<f64>>,
    multi: MultiPoint<f64>,
}

impl GeoInput {
    fn new(points: &[Vec2]) -> Self {
        let coords: Vec<Coord<f64>> = points
            .iter()
            .map(|p| Coord {
                x: f64::from(p.x),
                y: f64::from(p.y),
            })
            .collect();
        let multi = coords.iter().map(|&c| Point::from(c)).collect();
        Self { coords, multi }
    }
}

fn bits(p: Vec2) -> (u32, u32) {
    ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())
}

/// geo's coordinates back in f32 (exact for its vertices, which are input points); the closing
/// repeat of the first vertex collapses in the set.
fn coord_set<'a>(coords: impl Iterator<Item = &'a Coord<f64>>) -> BTreeSet<(u32, u32)> {
    coords
        .map(|c| bits(Vec2::new(c.x as f32, c.y as f32)))
        .collect()
}

/// The exact vertex sets (Drop, Keep): ours after an exact validation, or the brute-force
/// rational hull for small inputs, where the two are also checked against each other.
fn exact_sets(points: &[Vec2]) -> Option<[BTreeSet<(u32, u32)>; 2]> {
    let mut sets = [BTreeSet::new(), BTreeSet::new()];
    for (set, policy) in sets
        .iter_mut()
        .zip([CollinearPoints::Drop, CollinearPoints::Keep])
    {
        let hull = convex_hull_2d(points, policy).ok()?;
        hull.validate(points).ok()?;
        *set = hull.positions(points).map(bits).collect();
        if points.len() <= 64 {
            let brute: BTreeSet<(u32, u32)> =
                exact::convex_hull_2d_vertex_set(points, policy == CollinearPoints::Keep)
                    .into_iter()
                    .map(|i| bits(points[i]))
                    .collect();
            if brute != *set {
                return None;
            }
        }
    }
    Some(sets)
}

/// Vertices reported that the exact hull lacks, and exact vertices missed.
fn differences(got: &BTreeSet<(u32, u32)>, want: &BTreeSet<(u32, u32)>) -> (usize, usize) {
    (got.difference(want).count(), want.difference(got).count())
}

fn median_ns(method: Method, points: &[Vec2], geo: &GeoInput, runs: usize) -> f64 {
    black_box(method.time_once(points, geo));
    let mut samples: Vec<f64> = (0..runs).map(|_| method.time_once(points, geo)).collect();
    median(&mut samples)
}

/// Run the family.
pub(super) fn run(settings: Settings, progress: &mut dyn FnMut(&str)) -> Section {
    let n = if settings.random >= 4096 {
        1_000_000
    } else {
        settings.random * 64
    };
    let runs = settings.timing.batches.clamp(3, 7);
    let sets = [
        (
            "uniform square".to_owned(),
            format!(
                "{n} points uniform in [−1, 1)² (`seeded::points_in_square`, seeded xorshift)."
            ),
            points_in_square(&mut XorShift::new(0x5a_2024), n),
        ),
        (
            "circle".to_owned(),
            format!(
                "{n} points on the unit circle rounded to f32, scrambled order \
                 (`hard_cases::hull_circle_2d`): rounding decides which are corners."
            ),
            points_on_circle(n),
        ),
    ];
    let mut section = Section {
        heading: "2D convex hull".to_owned(),
        intro: format!(
            "The hull's vertex set against the exact one (our hull after \
             `ConvexHull2d::validate`, an exact check; below 64 points also the brute-force \
             rational hull). `Drop` rows and geo's QuickHull and `graham_hull(…, false)` are \
             compared with the exact strict corners, `Keep` and `graham_hull(…, true)` with the \
             exact boundary points. **ns/call is per input point**: the median time of one hull \
             over {runs} runs divided by the number of points; total milliseconds in the matrix \
             under each table. geo gets the same points converted exactly to f64."
        ),
        ..Section::default()
    };
    for (title, description, points) in sets {
        progress(&format!("{title} ({} points): exact sets", points.len()));
        let geo = GeoInput::new(&points);
        let Some(exact) = exact_sets(&points) else {
            section
                .notes
                .push(format!("{title}: the exact check failed; table skipped."));
            continue;
        };
        let mut table = Table {
            title: title.clone(),
            description: format!(
                "{description} Exact hull: {} strict corners, {} boundary points.",
                exact[0].len(),
                exact[1].len()
            ),
            inputs: points.len(),
            sign_total: format!(
                "vertex-set differences vs exact, of {} points",
                points.len()
            ),
            time_unit: "input point".to_owned(),
            error_label: "vertex-set differences (count)".to_owned(),
            ..Table::default()
        };
        let mut matrix = Vec::new();
        for method in METHODS {
            progress(&format!("{title}: {}", method.short()));
            let got = method.vertex_set(&points, &geo);
            let want = &exact[usize::from(method.keeps_collinear())];
            let (extra, missed) = differences(&got, want);
            let ns = median_ns(method, &points, &geo, runs);
            table.rows.push(Row {
                method: method.name().to_owned(),
                is_default: method == Method::Drop,
                ns: ns / points.len() as f64,
                wrong_signs: Some(extra + missed),
                ..Row::default()
            });
            matrix.push(vec![
                format!("{:.1}", ns / 1e6),
                got.len().to_string(),
                want.len().to_string(),
                if extra + missed == 0 {
                    "yes".to_owned()
                } else {
                    format!("no: {extra} extra, {missed} missed")
                },
            ]);
        }
        let names: Vec<String> = METHODS.iter().map(|m| m.short().to_owned()).collect();
        table.extra.push(transpose_matrix(&names, &matrix));
        let ratio = |m: Method| {
            let find = |m: Method| {
                table
                    .rows
                    .iter()
                    .find(|r| r.method == m.name())
                    .map_or(f64::NAN, |r| r.ns)
            };
            find(m) / find(Method::GeoConvexHull)
        };
        section.notes.push(format!(
            "{title}: `Drop` takes {:.2}× and `Keep` {:.2}× the time of geo's `ConvexHull` \
             (issue 3's bar: ≤ {} on 10⁶ points).",
            ratio(Method::Drop),
            ratio(Method::Keep),
            if title == "uniform square" {
                "0.5×"
            } else {
                "1×"
            }
        ));
        section.tables.push(table);
    }
    progress("hard cases");
    section.tables.push(hard_case_table(runs));
    section
}

/// Rows: what each method's vertex set looks like on the input (one row per method).
fn transpose_matrix(methods: &[String], values: &[Vec<String>]) -> String {
    per_case_matrix(
        "Per method: total time of one hull (ms, median), vertices reported, exact vertices, \
         and whether the sets are equal.",
        methods,
        &[
            "ms".to_owned(),
            "vertices".to_owned(),
            "exact".to_owned(),
            "equals exact set".to_owned(),
        ],
        values,
    )
}

/// The hard-case table: per case, each method's vertex-set differences from the exact hull; the
/// time is the sum over the cases of each one's median, per input point.
fn hard_case_table(runs: usize) -> Table {
    let mut table = Table {
        title: "hard cases".to_owned(),
        description: "`hard_cases::hulls_2d()`: circle, grids with collinear runs (also \
                      subnormal), equal points, signed zeros, 3000 collinear points, Kettner's \
                      last-ulp grid, a segment rounded to f32, coordinates near 1e30, 1e38 and \
                      1e-30. ns/call is the sum over the cases of the median time of one hull, per \
                      input point; the error is the total number of vertex-set differences over \
                      all cases."
            .to_owned(),
        sign_total: "vertex-set differences vs exact, all cases".to_owned(),
        time_unit: "input point".to_owned(),
        error_label: "vertex-set differences (count)".to_owned(),
        ..Table::default()
    };
    let cases = hulls_2d();
    table.inputs = cases.len();
    let mut names = Vec::new();
    let mut matrix = Vec::new();
    let mut totals = [0usize; METHODS.len()];
    let mut times = [0.0f64; METHODS.len()];
    for case in &cases {
        names.push(format!("{} ({} points)", case.name, case.points.len()));
        let geo = GeoInput::new(&case.points);
        let Some(exact) = exact_sets(&case.points) else {
            matrix.push(vec!["exact check failed".to_owned(); METHODS.len()]);
            continue;
        };
        let mut row = Vec::new();
        for ((total, time), method) in totals.iter_mut().zip(&mut times).zip(METHODS) {
            *time += median_ns(method, &case.points, &geo, runs);
            let got = method.vertex_set(&case.points, &geo);
            let (extra, missed) = differences(&got, &exact[usize::from(method.keeps_collinear())]);
            *total += extra + missed;
            row.push(if extra + missed == 0 {
                format!("✓ {}", got.len())
            } else {
                format!("✗ {} (+{extra} −{missed})", got.len())
            });
        }
        matrix.push(row);
    }
    let points: usize = cases.iter().map(|c| c.points.len()).sum();
    for ((method, total), time) in METHODS.into_iter().zip(totals).zip(times) {
        table.rows.push(Row {
            method: method.name().to_owned(),
            is_default: method == Method::Drop,
            ns: time / points as f64,
            wrong_signs: Some(total),
            ..Row::default()
        });
    }
    let methods: Vec<String> = METHODS.iter().map(|m| m.short().to_owned()).collect();
    table.extra.push(per_case_matrix(
        "Per case: vertices reported (✓ = the exact set; ✗ with +extra −missed vertices).",
        &names,
        &methods,
        &matrix,
    ));
    table
}
