//! `barytex examples`: the worked examples of S. R. Buss, *3D Computer Graphics: A
//! Mathematical Introduction with OpenGL* (2003), ch. IV, numbered as in A. Denisjuk's lecture
//! *Interpolacja i teksturowanie* (University of Warmia and Mazury), run through
//! `barytex-interp`, each checked against exact rational arithmetic ([`crate::exact`]); the
//! scanline triangle of S. Schaefer's *Shading/Texturing* lecture slides (Texas A&M University)
//! filled by `barytex_raster::scanline` in exact arithmetic; and a summary of Kettner's
//! orientation grid. Every number is computed at run time.

use std::io::Write;

use barytex_interp::hard_cases::kettner_grid;
use barytex_interp::methods::{orient2d_dop_f32, orient2d_naive_f32};
use barytex_interp::{InverseBilinear, barycentric_2d, bilinear, inverse_bilinear_2d, orient2d};
use barytex_raster::scanline::{SampleRule, ScanVertex, scanline_fill};
use glam::{DVec2, Vec2};

use crate::exact::{self, Q};

type Result = std::result::Result<(), Box<dyn std::error::Error>>;

/// A rational `n/d` from small integers.
fn rat(n: i32, d: i32) -> Q {
    Q::new(n.into(), d.into())
}

/// The exact value of an f32 the examples computed (small and finite).
fn qf(x: f32) -> std::result::Result<Q, String> {
    Q::from_f32(x).ok_or_else(|| format!("{x:e} has no exact fraction here"))
}

/// The f32 nearest a rational (through f64; the examples' values have no double-rounding ties).
fn to_f32(x: Q) -> f32 {
    x.to_f64() as f32
}

/// The spacing of f32 values at `x`'s magnitude: `ulp(x)`, with `ulp(0)` the smallest
/// subnormal (IEEE 754 binary32: 2^(⌊log₂|x|⌋ − 23) for normal magnitudes).
fn ulp_f32(x: f64) -> f64 {
    let x = x.abs();
    if !x.is_finite() {
        return f64::INFINITY;
    }
    if x < f64::from(f32::MIN_POSITIVE) {
        return f64::from(f32::from_bits(1));
    }
    let exponent = ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    2f64.powi(exponent - 23)
}

/// The bilinear map of `quad` at `ab`, in f64.
fn bilinear_f64([x, y, z, w]: [DVec2; 4], ab: DVec2) -> DVec2 {
    let (a, b) = (ab.x, ab.y);
    x * ((1.0 - a) * (1.0 - b)) + y * (a * (1.0 - b)) + z * (a * b) + w * ((1.0 - a) * b)
}

/// The reference preimage of `p` under the bilinear map of `quad`: Newton's method in f64 from
/// `start` (the examples start from the given parameters, near the answer, where it converges
/// quadratically). `None` when the Jacobian is singular, or when after 50 steps the residual is
/// above 1e-14 of the quad's size.
fn inverse_bilinear_newton(p: DVec2, quad: [DVec2; 4], start: DVec2) -> Option<DVec2> {
    let [x, y, z, w] = quad;
    let mut ab = start;
    for _ in 0..50 {
        let r = bilinear_f64(quad, ab) - p;
        let d_alpha = (y - x) * (1.0 - ab.y) + (z - w) * ab.y;
        let d_beta = (w - x) * (1.0 - ab.x) + (z - y) * ab.x;
        let det = d_alpha.perp_dot(d_beta);
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        // Solve [d_alpha d_beta] · step = r by Cramer's rule (2×2).
        let step = DVec2::new(r.perp_dot(d_beta) / det, d_alpha.perp_dot(r) / det);
        ab -= step;
        if step.abs().max_element() <= 1e-17 * ab.abs().max_element().max(1.0) {
            return Some(ab);
        }
    }
    let size = quad
        .iter()
        .map(|c| (*c - quad[0]).length())
        .fold(0.0, f64::max);
    ((bilinear_f64(quad, ab) - p).length() <= 1e-14 * size).then_some(ab)
}

fn show_q2(p: &[Q; 2]) -> String {
    format!("({}, {})", p[0], p[1])
}

fn show_q3(w: &[Q; 3]) -> String {
    format!("({}, {}, {})", w[0], w[1], w[2])
}

fn show_f32s(values: &[f32]) -> String {
    let parts: Vec<String> = values.iter().map(|v| format!("{v}")).collect();
    format!("({})", parts.join(", "))
}

fn show_err(e: f64) -> String {
    if e == 0.0 {
        "0".to_owned()
    } else {
        format!("{e:.1e}")
    }
}

/// Print the demo to stdout.
///
/// # Errors
/// When stdout cannot be written.
pub(crate) fn run() -> Result {
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    writeln!(
        out,
        "barytex {} — interpolation math, exact where a sign decides topology.",
        env!("CARGO_PKG_VERSION")
    )?;
    writeln!(
        out,
        "This runs the worked examples of S. R. Buss, 3D \
         Computer Graphics (2003), ch. IV,\nnumbered as in A. Denisjuk's lecture notes \
         \"Interpolacja i teksturowanie\", through barytex-interp, and S. Schaefer's scanline\n\
         triangle through barytex-raster, and checks every result against exact rational \
         arithmetic, computed now.\n"
    )?;
    barycentric_examples(&mut out)?;
    bilinear_examples(&mut out)?;
    scanline_example(&mut out)?;
    kettner_summary(&mut out)?;
    writeln!(
        out,
        "Full speed-vs-error report: docs/report/README.md and docs/report/interp.md.\n\
         Produce it with the workspace tool barytex-report (from the repository root: \
         `cargo run --release -p barytex-report`; add `-- --quick` for a fast, rough run)."
    )?;
    Ok(())
}

fn barycentric_examples(out: &mut impl Write) -> Result {
    let tri_q = [
        [rat(0, 1), rat(0, 1)],
        [rat(2, 1), rat(3, 1)],
        [rat(3, 1), rat(1, 1)],
    ];
    let tri = tri_q.map(|[x, y]| Vec2::new(to_f32(x), to_f32(y)));
    let points = [(2, 1, 3, 1), (11, 3, 2, 1), (3, 2, 3, 2), (1, 1, 0, 1)];
    writeln!(
        out,
        "Examples 7 and 9 (Buss, Exercise IV.5): barycentric coordinates (α, β, γ) in the \
         triangle x = (0, 0), y = (2, 3), z = (3, 1)"
    )?;
    writeln!(
        out,
        "with barytex_interp::barycentric_2d. The point is rounded to f32 first (11/3 is not an \
         f32), so the error is measured\nagainst the exact weights of the f32 point, and, \
         separately, against the exact answer for the ideal point."
    )?;
    let h = [
        "point",
        "ideal answer",
        "barycentric_2d (f32)",
        "location",
        "error",
        "ulps",
        "vs ideal",
    ];
    writeln!(
        out,
        "  {:<11} {:<18} {:<38} {:<14} {:<9} {:<9} {}",
        h[0], h[1], h[2], h[3], h[4], h[5], h[6]
    )?;
    for (xn, xd, yn, yd) in points {
        let ideal = [rat(xn, xd), rat(yn, yd)];
        let ideal_weights =
            exact::barycentric(ideal, tri_q).ok_or("degenerate example triangle")?;
        let p = Vec2::new(to_f32(ideal[0]), to_f32(ideal[1]));
        let b = barycentric_2d(p, tri)?;
        let exact_w = exact::barycentric_2d(p, tri).ok_or("degenerate example triangle")?;
        let (mut err, mut ulps, mut vs_ideal) = (0.0f64, 0.0f64, 0.0f64);
        for ((&w, &e), &s) in b.weights.iter().zip(&exact_w).zip(&ideal_weights) {
            let d = exact::abs_diff(qf(w)?, e);
            err = err.max(d);
            ulps = ulps.max(d / ulp_f32(e.to_f64()));
            vs_ideal = vs_ideal.max(exact::abs_diff(qf(w)?, s));
        }
        let exact_location = exact::location_2d(p, tri);
        let location = if exact_location == b.location {
            format!("{:?}", b.location)
        } else {
            format!("{:?} ✗ exact: {exact_location:?}", b.location)
        };
        writeln!(
            out,
            "  {:<11} {:<18} {:<38} {:<14} {:<9} {:<9} {}",
            show_q2(&ideal),
            show_q3(&ideal_weights),
            show_f32s(&b.weights),
            location,
            show_err(err),
            format!("{ulps:.2}"),
            show_err(vs_ideal)
        )?;
    }
    writeln!(out)?;
    Ok(())
}

fn bilinear_examples(out: &mut impl Write) -> Result {
    let corners = [(0, 0), (4, 0), (5, 3), (0, 2)];
    let quad_q = corners.map(|(x, y)| [rat(x, 1), rat(y, 1)]);
    let quad = corners.map(|(x, y)| Vec2::new(x as f32, y as f32));
    let params = [(1, 1, 0, 1), (1, 3, 1, 1), (1, 2, 1, 4), (2, 3, 1, 3)];
    writeln!(
        out,
        "Example 10 (Buss, Exercise IV.7): the quad x = (0, 0), y = (4, 0), z = (5, 3), \
         w = (0, 2); (α, β) mapped forward with\nbarytex_interp::bilinear (error against the \
         exact map of the f32 parameters) and back with inverse_bilinear_2d\n(error against the \
         given (α, β) and against Newton's method in f64 on the f32 point)."
    )?;
    let h = [
        "(α, β)",
        "bilinear (f32)",
        "exact point",
        "error",
        "inverse_bilinear_2d",
        "vs (α, β)",
        "vs Newton",
    ];
    writeln!(
        out,
        "  {:<10} {:<22} {:<13} {:<9} {:<34} {:<9} {}",
        h[0], h[1], h[2], h[3], h[4], h[5], h[6]
    )?;
    for (an, ad, bn, bd) in params {
        let (alpha, beta) = (rat(an, ad), rat(bn, bd));
        let exact_point = exact::bilinear(quad_q, alpha, beta);
        let (a32, b32) = (to_f32(alpha), to_f32(beta));
        let p = bilinear(quad, a32, b32);
        // The exact map of the f32 parameters (what `bilinear` was given).
        let exact_p = exact::bilinear(quad_q, qf(a32)?, qf(b32)?);
        let forward_err =
            exact::abs_diff(qf(p.x)?, exact_p[0]).max(exact::abs_diff(qf(p.y)?, exact_p[1]));
        let (kind, ab) = match inverse_bilinear_2d(p, quad)? {
            InverseBilinear::Inside(ab) => ("Inside", Some(ab)),
            InverseBilinear::Folded(ab, _) => ("Folded", Some(ab)),
            InverseBilinear::Outside(ab) => ("Outside", ab),
        };
        let newton = inverse_bilinear_newton(
            p.as_dvec2(),
            quad.map(Vec2::as_dvec2),
            DVec2::new(f64::from(a32), f64::from(b32)),
        );
        let (inverse, vs_given, vs_newton) = match ab {
            Some(ab) => (
                format!("{kind} {}", show_f32s(&[ab.x, ab.y])),
                show_err(exact::abs_diff(qf(ab.x)?, alpha).max(exact::abs_diff(qf(ab.y)?, beta))),
                newton.map_or_else(
                    || "–".to_owned(),
                    |r| show_err((ab.as_dvec2() - r).abs().max_element()),
                ),
            ),
            None => (kind.to_owned(), "–".to_owned(), "–".to_owned()),
        };
        writeln!(
            out,
            "  {:<10} {:<22} {:<13} {:<9} {:<34} {:<9} {}",
            format!("({alpha}, {beta})"),
            show_f32s(&[p.x, p.y]),
            show_q2(&exact_point),
            show_err(forward_err),
            inverse,
            vs_given,
            vs_newton
        )?;
    }
    writeln!(out)?;
    Ok(())
}

/// Schaefer's worked example: the triangle A = (0, 0), B = (1, 5), C = (4, 2) filled by the
/// scanline backend (Edge Table, Active Edge List) at integer points, carrying F = the
/// barycentric weights of A, B and C (1 at its vertex, 0 at the others) along the edges and the
/// spans, in exact rationals; each point's F is checked against its exact barycentric
/// coordinates.
fn scanline_example(out: &mut impl Write) -> Result {
    let corners = [(0, 0), (1, 5), (4, 2)];
    let tri_q = corners.map(|(x, y)| [Q::int(x), Q::int(y)]);
    let unit = |k: usize| core::array::from_fn(|i| Q::int(i64::from(i == k)));
    let polygon: Vec<ScanVertex<Q, 3>> = corners
        .iter()
        .enumerate()
        .map(|(k, &(x, y))| ScanVertex {
            x: Q::int(x),
            y: Q::int(y),
            f: unit(k),
        })
        .collect();
    let mut covered: Vec<(i64, i64, [Q; 3])> = Vec::new();
    scanline_fill(
        &polygon,
        SampleRule::IntegerPoints,
        (-1, 7),
        (-1, 6),
        |x, y, f| covered.push((x, y, f)),
    );
    writeln!(
        out,
        "Schaefer's scanline example (Shading/Texturing slides): the triangle A = (0, 0), \
         B = (1, 5), C = (4, 2) filled by\nbarytex_raster::scanline::scanline_fill (Edge Table, \
         Active Edge List) at the integer points (x, y), y down; a point on a\nleft or top edge \
         is in, on a right or bottom edge out. F = (α, β, γ), the weights of A, B, C, is \
         interpolated\nalong the edges and across each span in exact rationals, and checked \
         against each point's exact barycentric\ncoordinates."
    )?;
    let mut rows: Vec<(i64, i64, i64)> = Vec::new();
    for &(x, y, _) in &covered {
        match rows.last_mut() {
            Some((row, _, last)) if *row == y && *last + 1 == x => *last = x,
            _ => rows.push((y, x, x)),
        }
    }
    for (y, first, last) in rows {
        if first == last {
            writeln!(out, "  span y = {y}: x = {first}")?;
        } else {
            writeln!(out, "  span y = {y}: x = {first} to {last}")?;
        }
    }
    writeln!(out, "  {:<8} {:<20} exact", "(x, y)", "F = (α, β, γ)")?;
    for (x, y, f) in &covered {
        let exact = exact::barycentric([Q::int(*x), Q::int(*y)], tri_q)
            .ok_or("degenerate example triangle")?;
        let check = if exact == *f {
            "✓".to_owned()
        } else {
            format!("✗ {}", show_q3(&exact))
        };
        writeln!(
            out,
            "  {:<8} {:<20} {check}",
            format!("({x}, {y})"),
            show_q3(f)
        )?;
    }
    writeln!(out)?;
    Ok(())
}

fn kettner_summary(out: &mut impl Write) -> Result {
    let n = 256;
    let (mut naive, mut dop, mut ours, mut collinear) = (0, 0, 0, 0);
    let (mut naive_b, mut dop_b) = (0, 0);
    for (p, a, b) in kettner_grid(n) {
        let want = exact::orient2d_sign(p, a, b);
        collinear += usize::from(want == 0);
        naive += usize::from(orient2d_naive_f32(p, a, b).sign() != want);
        dop += usize::from(orient2d_dop_f32(p, a, b).sign() != want);
        ours += usize::from(orient2d(p, a, b).map(barytex_interp::Orientation::sign) != Ok(want));
        // The same sign with the differences taken from b (cyclic rotation).
        naive_b += usize::from(orient2d_naive_f32(b, p, a).sign() != want);
        dop_b += usize::from(orient2d_dop_f32(b, p, a).sign() != want);
    }
    let total = n * n;
    writeln!(
        out,
        "Kettner's grid: the {total} points (0.5 + i·ulp, 0.5 + j·ulp), i, j < {n}, against the \
         line (12, 12)–(24, 24)\n({collinear} exactly collinear); orientation signs that differ \
         from the exact rational sign:"
    )?;
    for (name, wrong) in [
        ("naive f32 determinant (methods::orient2d_naive_f32)", naive),
        ("difference of products (methods::orient2d_dop_f32)", dop),
        ("barytex_interp::orient2d", ours),
    ] {
        writeln!(
            out,
            "  {name:<54} {wrong:>6} wrong ({:.2} %)",
            100.0 * wrong as f64 / f64::from(total)
        )?;
    }
    writeln!(
        out,
        "  (evaluated as orient(p, a, b), differences from p; taken from b = (24, 24) instead, \
         naive gets {naive_b} and dop {dop_b} wrong)\n"
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use barytex_testkit::seeded::{XorShift, convex_quad};

    /// The local f64 references agree with barytex-testkit's, which the test suites use.
    #[test]
    fn references_match_the_testkit() {
        let mut rng = XorShift::new(5);
        for _ in 0..10_000 {
            let x = f64::from(f32::from_bits(rng.next_u64() as u32));
            let ours = ulp_f32(x);
            let theirs = barytex_testkit::ulp::ulp_f32(x);
            assert!(
                ours == theirs || (ours.is_nan() && theirs.is_nan()),
                "{x:e}"
            );
        }
        for _ in 0..2_000 {
            let quad = convex_quad(&mut rng).map(Vec2::as_dvec2);
            let ab = DVec2::new(rng.f32_in(-0.5, 1.5).into(), rng.f32_in(-0.5, 1.5).into());
            let p = bilinear_f64(quad, ab);
            let start = ab + DVec2::splat(1e-3);
            assert_eq!(
                inverse_bilinear_newton(p, quad, start),
                barytex_testkit::reference::inverse_bilinear_newton(p, quad, start)
            );
        }
    }

    /// The printed examples, as Buss states them: Example 9's point (1, 0) has the exact weights
    /// (5/7, −1/7, 3/7), outside; (3/2, 3/2) has (5/14, 3/7, 3/14).
    #[test]
    fn exact_weights_of_the_worked_examples() {
        let tri = [
            [rat(0, 1), rat(0, 1)],
            [rat(2, 1), rat(3, 1)],
            [rat(3, 1), rat(1, 1)],
        ];
        let w = exact::barycentric([rat(1, 1), rat(0, 1)], tri).unwrap();
        assert_eq!(show_q3(&w), "(5/7, -1/7, 3/7)");
        let w = exact::barycentric([rat(3, 2), rat(3, 2)], tri).unwrap();
        assert_eq!(show_q3(&w), "(5/14, 3/7, 3/14)");
        let quad = [(0, 0), (4, 0), (5, 3), (0, 2)].map(|(x, y)| [rat(x, 1), rat(y, 1)]);
        assert_eq!(
            show_q2(&exact::bilinear(quad, rat(2, 3), rat(1, 3))),
            "(26/9, 8/9)"
        );
    }
}
