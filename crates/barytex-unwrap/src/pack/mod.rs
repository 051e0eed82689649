//! Packing charts into the unit square: one texel density for every chart, each chart turned to
//! its minimum-area bounding box, then packed with a padding in texels between charts and to the
//! border — as boxes, as raster masks, or as outlines on a horizon, whichever reaches the
//! largest scale.
//!
//! The packer scales all charts by one factor (so every chart gets the same texels per unit of
//! surface, as a lightmap or a painted texture wants) and searches the largest factor at which
//! every chart still fits the square:
//!
//! 1. Boxes: the charts' padded minimum-area boxes (Freeman and Shapira 1975) on a skyline
//!    (Jylänki 2010, SKYLINE-BL), the scale found by bisection. Boxes are whole texels, so the
//!    padding holds exactly. This always runs and gives the floor for the others.
//! 2. Raster masks (up to 256 charts): each chart, in its four quarter turns,
//!    rasterized conservatively, dilated by the padding and placed in an atlas bitmap where the
//!    filled square stays smallest — xatlas's packer (Jonathan Young's texture atlas library),
//!    with the scale found by secant steps. Charts fill each other's holes and overhangs.
//! 3. A horizon (up to 256 charts): chart column outlines lowered onto the packed area's upper
//!    outline (Lévy et al., "Least squares conformal maps for automatic texture atlas
//!    generation", SIGGRAPH 2002, §6, "Tetris" packing), tried from the raster's scale up.
//!
//! Two charts are at least `padding` texels apart (plus a margin of 1/64 texel that keeps them
//! apart after rounding uvs to f32), and every chart is at least `padding` texels from the
//! border.
//!
//! # Efficiency
//! [`PackStats::efficiency`] is the charts' total uv area (the triangles' areas after packing)
//! over the unit square's area 1: the fraction of the texture that texels of the surface cover.
//!
//! ```
//! use barytex_unwrap::Chart;
//! use barytex_unwrap::pack::{PackOptions, pack};
//! use glam::DVec2;
//!
//! // Two unit squares, each two triangles.
//! let square = Chart {
//!     faces: vec![0, 1],
//!     vertices: vec![0, 1, 2, 3],
//!     triangles: vec![[0, 1, 2], [0, 2, 3]],
//!     uvs: vec![DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y],
//! };
//! let mut charts = vec![square.clone(), square];
//! let stats = pack(&mut charts, &PackOptions { size: 256, padding: 2, rotate: true })?;
//! assert!(stats.efficiency > 0.45 && stats.efficiency <= 0.5);
//! for uv in charts.iter().flat_map(|c| &c.uvs) {
//!     assert!(uv.cmpge(DVec2::splat(2.0 / 256.0)).all() && uv.cmple(DVec2::splat(254.0 / 256.0)).all());
//! }
//! # Ok::<(), barytex_unwrap::pack::PackError>(())
//! ```

mod bitmap;
mod error;
mod horizon;
mod min_area_rect;
mod options;
mod raster;
mod skyline;

use glam::DVec2;

use crate::Chart;
pub use error::PackError;
pub use options::{MAX_ATLAS_SIZE, PackOptions};
use skyline::{Skyline, Spot};

/// The bisection steps on the scale: the result is within `2^-20` of the largest scale the
/// skyline packer accepts.
const BISECTION_STEPS: u32 = 20;

/// Extra space in texels around each chart inside its box, so that rounding uvs to f32 never
/// brings two charts closer than the padding (f32's spacing near 1 is `2^-24`, which is 1/512
/// texel in a 32768-texel atlas).
const MARGIN_TEXELS: f64 = 1.0 / 64.0;

/// The most charts packed on a horizon too (its search costs `charts × size × chart width`
/// per attempt).
const HORIZON_MAX_CHARTS: usize = 256;

/// The most charts packed as raster masks too: each placement searches the atlas bitmap row by
/// row, so the cost grows with the charts times the atlas side; many small charts of nearly
/// equal size (pairs, single triangles) fill their boxes anyway and gain little (480 sphere
/// pairs: 0.3 s for the boxes' efficiency). 256 covers a parameterization's charts at the
/// default cone on the sample meshes (Suzanne 120, 136 at a 40° cone: 60.3% as masks, 54.1%
/// on the horizon at 128 allowed).
const RASTER_MAX_CHARTS: usize = 256;

/// The share of the square the charts' area is guessed to cover when the raster search starts.
const RASTER_START_EFFICIENCY: f64 = 0.55;

/// Bisection steps of the horizon packer's scale, between the boxes' scale and the area bound.
const HORIZON_BISECTION_STEPS: u32 = 10;

/// What packing did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PackStats {
    /// Texels per unit of the charts' input uvs (surface units for an isometric chart).
    pub texels_per_unit: f64,
    /// The charts' total uv area after packing over the unit square's (see the module docs).
    pub efficiency: f64,
    /// How many times the skyline packer ran during the bisection.
    pub attempts: u32,
}

/// Scales, turns and places `charts` (their uvs in any common unit, e.g. surface units) inside
/// the unit square, in place, as [`PackOptions`] says. Every chart is moved by a similarity (a
/// uniform scale, a rotation and a translation; never a mirror), so a triangle's orientation and
/// shape are kept and distortion does not change.
///
/// Charts with no uvs are left alone (they take no space).
///
/// # Errors
/// [`PackError::Options`] for options out of range, [`PackError::NonFinite`] for a chart with a
/// NaN or infinite uv, [`PackError::TooManyCharts`] when the charts do not fit even at one
/// texel each.
pub fn pack(charts: &mut [Chart], options: &PackOptions) -> Result<PackStats, PackError> {
    options.validate()?;
    if let Some(chart) = charts
        .iter()
        .position(|c| !c.uvs.iter().all(|p| p.is_finite()))
    {
        return Err(PackError::NonFinite { chart });
    }
    // Each chart turned, moved to the origin, with its extent.
    let extents: Vec<DVec2> = charts
        .iter_mut()
        .map(|chart| normalize(&mut chart.uvs, options.rotate))
        .collect();
    let placed: Vec<usize> = (0..charts.len())
        .filter(|&i| !charts[i].uvs.is_empty())
        .collect();
    let mut order = placed.clone();
    order.sort_by(|&a, &b| {
        let (ea, eb) = (extents[a], extents[b]);
        eb.y.total_cmp(&ea.y).then(eb.x.total_cmp(&ea.x))
    });
    let bin = options.size - options.padding;
    let attempt = |scale: f64| try_pack(&order, &extents, scale, bin, options);
    let mut attempts = 1;
    let Some(mut best) = attempt(0.0) else {
        return Err(PackError::TooManyCharts {
            charts: placed.len(),
            size: options.size,
            padding: options.padding,
        });
    };
    let mut scale = 0.0;
    let area: f64 = placed.iter().map(|&i| extents[i].x * extents[i].y).sum();
    let longest = placed
        .iter()
        .map(|&i| extents[i].max_element())
        .fold(0.0, f64::max);
    let bin_f = f64::from(bin);
    let upper = if area > 0.0 {
        (bin_f / area.sqrt()).min(bin_f / longest)
    } else if longest > 0.0 {
        bin_f / longest
    } else {
        0.0
    };
    let mut high = upper;
    if high.is_finite() && high > 0.0 {
        attempts += 1;
        if let Some(spots) = attempt(high) {
            (best, scale) = (spots, high);
        } else {
            let mut low = 0.0;
            for _ in 0..BISECTION_STEPS {
                let mid = 0.5 * (low + high);
                attempts += 1;
                match attempt(mid) {
                    Some(spots) => (best, scale, low) = (spots, mid, mid),
                    None => high = mid,
                }
            }
        }
    }
    // The charts' own area bounds the scale (their boxes' area does not: outlines nest).
    let surface: f64 = placed.iter().map(|&i| chart_uv_area(&charts[i])).sum();
    let bound = if surface > 0.0 {
        (bin_f / surface.sqrt()).min(bin_f / longest)
    } else {
        upper
    };
    // The best outline packing so far: its scale, chart order and spots.
    let mut outlined: Option<(f64, Vec<usize>, Vec<horizon::Placed>)> = None;
    // Rasterized chart masks (xatlas's packer), searched from the boxes' scale up.
    if placed.len() <= RASTER_MAX_CHARTS && scale > 0.0 {
        let areas: Vec<f64> = charts.iter().map(chart_uv_area).collect();
        // Start where the charts would cover a typical share of the square (the search's
        // secant steps correct a poor guess), never below the boxes' scale.
        let start = if surface > 0.0 {
            (f64::from(options.size) * (RASTER_START_EFFICIENCY / surface).sqrt())
                .min(bound)
                .max(scale)
        } else {
            scale
        };
        let mut order = placed.clone();
        order.sort_by(|&a, &b| areas[b].total_cmp(&areas[a]).then(a.cmp(&b)));
        if let Some((reached, spots)) = raster::search(
            &order,
            charts,
            &extents,
            options,
            start,
            bound,
            &mut attempts,
        ) && reached > scale
        {
            outlined = Some((reached, order, spots));
        }
    }
    // Chart outlines on a horizon (Lévy et al. 2002) when there are few enough charts for its
    // column-by-column search (a parameterization's charts; flat pairs and triangles fill their
    // boxes anyway); kept when it reaches a larger scale than the boxes and masks did.
    if placed.len() <= HORIZON_MAX_CHARTS && scale > 0.0 {
        let outlines: Vec<[horizon::Outline; 4]> = (0..charts.len())
            .map(|i| {
                [0, 1, 2, 3].map(|k| {
                    horizon::Outline::new(&charts[i].uvs, &charts[i].triangles, extents[i], k)
                })
            })
            .collect();
        // Three orders (largest area, tallest, widest first); the one reaching the largest
        // scale is kept.
        let keys: [fn(DVec2) -> f64; 3] = [|e| e.x * e.y, |e| e.y.min(e.x), |e| e.x.max(e.y)];
        for key in keys {
            let mut order = placed.clone();
            order.sort_by(|&a, &b| key(extents[b]).total_cmp(&key(extents[a])).then(a.cmp(&b)));
            let attempt = |scale: f64| {
                horizon::try_pack(
                    &order,
                    &outlines,
                    scale,
                    options.size,
                    options.padding,
                    options.rotate,
                )
            };
            let floor = outlined.as_ref().map_or(scale, |b| b.0);
            attempts += 1;
            let Some(mut found) = attempt(floor) else {
                continue;
            };
            let (mut low, mut high) = (floor, bound.max(floor));
            let mut reached = floor;
            for _ in 0..HORIZON_BISECTION_STEPS {
                let mid = 0.5 * (low + high);
                attempts += 1;
                match attempt(mid) {
                    Some(spots) => (found, reached, low) = (spots, mid, mid),
                    None => high = mid,
                }
            }
            if outlined.as_ref().is_none_or(|b| reached > b.0) {
                outlined = Some((reached, order, found));
            }
        }
    }
    if let Some((best_scale, order, found)) = outlined {
        let efficiency = place(charts, &order, &extents, best_scale, &found, options.size);
        return Ok(PackStats {
            texels_per_unit: best_scale,
            efficiency,
            attempts,
        });
    }
    let size = f64::from(options.size);
    let padding = f64::from(options.padding);
    let mut chart_area = 0.0;
    for (&i, spot) in order.iter().zip(&best) {
        let e = extents[i] * scale;
        let (w, h) = footprint(extents[i], scale, options.padding);
        let placed_extent = if spot.turned { DVec2::new(e.y, e.x) } else { e };
        let (bw, bh) = if spot.turned { (h, w) } else { (w, h) };
        let inset = DVec2::new(
            (f64::from(bw) - padding - placed_extent.x) / 2.0,
            (f64::from(bh) - padding - placed_extent.y) / 2.0,
        );
        let origin = DVec2::new(f64::from(spot.x), f64::from(spot.y)) + padding + inset;
        for uv in &mut charts[i].uvs {
            let q = *uv * scale;
            let q = if spot.turned {
                DVec2::new(e.y - q.y, q.x)
            } else {
                q
            };
            *uv = (origin + q) / size;
        }
        chart_area += chart_uv_area(&charts[i]);
    }
    Ok(PackStats {
        texels_per_unit: scale,
        efficiency: chart_area,
        attempts,
    })
}

/// Moves the charts `order` (normalized, box extents `extents`) to their `spots` at `scale` in
/// a `size`-texel square, and returns their total uv area.
fn place(
    charts: &mut [Chart],
    order: &[usize],
    extents: &[DVec2],
    scale: f64,
    spots: &[horizon::Placed],
    size: u32,
) -> f64 {
    let size = f64::from(size);
    let mut chart_area = 0.0;
    for (&i, spot) in order.iter().zip(spots) {
        let e = extents[i];
        for uv in &mut charts[i].uvs {
            let q = horizon::turn(*uv, e, spot.turns) * scale;
            *uv = (spot.origin + q) / size;
        }
        chart_area += chart_uv_area(&charts[i]);
    }
    chart_area
}

/// The total unsigned area of a chart's triangles in uv.
fn chart_uv_area(chart: &Chart) -> f64 {
    chart
        .triangles
        .iter()
        .filter_map(|t| {
            let [a, b, c] = t.map(|i| chart.uvs.get(i as usize).copied());
            Some((b? - a?).perp_dot(c? - a?).abs() / 2.0)
        })
        .sum()
}

/// Turns `uvs` to their minimum-area box (when `rotate`; lying, wider than tall), moves them so
/// the box starts at the origin, and returns the box's extent.
fn normalize(uvs: &mut [DVec2], rotate: bool) -> DVec2 {
    if uvs.is_empty() {
        return DVec2::ZERO;
    }
    if rotate {
        let d = min_area_rect::min_area_direction(uvs);
        for p in uvs.iter_mut() {
            *p = DVec2::new(p.dot(d), d.perp_dot(*p));
        }
    }
    let (mut lo, mut hi) = bounds(uvs);
    if rotate && hi.y - lo.y > hi.x - lo.x {
        // A quarter turn (x, y) -> (y, -x): a rotation, so orientation is kept.
        for p in uvs.iter_mut() {
            *p = DVec2::new(p.y, -p.x);
        }
        (lo, hi) = bounds(uvs);
    }
    for p in uvs.iter_mut() {
        *p -= lo;
    }
    hi - lo
}

fn bounds(uvs: &[DVec2]) -> (DVec2, DVec2) {
    uvs.iter().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(lo, hi), &p| (lo.min(p), hi.max(p)),
    )
}

/// A chart's box in whole texels at `scale`: its extent, the margin, and the padding (the gap
/// to the next box), or `u32::MAX` when that does not fit a `u32`.
fn footprint(extent: DVec2, scale: f64, padding: u32) -> (u32, u32) {
    let side = |e: f64| {
        let t = (e * scale + MARGIN_TEXELS).ceil() + f64::from(padding);
        if t.is_finite() && t < f64::from(u32::MAX) {
            t as u32
        } else {
            u32::MAX
        }
    };
    (side(extent.x), side(extent.y))
}

/// Packs the padded boxes of the charts `order` at `scale` into a `bin × bin` skyline (which
/// starts `padding` texels from the square's low corner), or `None` when one does not fit.
fn try_pack(
    order: &[usize],
    extents: &[DVec2],
    scale: f64,
    bin: u32,
    options: &PackOptions,
) -> Option<Vec<Spot>> {
    let mut skyline = Skyline::new(bin, bin);
    order
        .iter()
        .map(|&i| {
            let (w, h) = footprint(extents[i], scale, options.padding);
            if w > bin || h > bin {
                return None;
            }
            skyline.insert(w, h, options.rotate)
        })
        .collect()
}
